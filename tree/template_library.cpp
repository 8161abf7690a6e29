#include "tree/template_library.h"

#include <algorithm>
#include <filesystem>

#include "core/data_paths.h"
#include "core/errors.h"
#include "core/input_file.h"
#include "tree/template_file.h"

namespace sylva {

// Generated from templates/*.toml (tree/CMakeLists.txt).
const std::vector<std::pair<std::string_view, std::string_view>>& builtin_template_texts();

namespace {

constexpr std::string_view kDefaultName = "oak";

std::vector<TreeTemplate> parse_builtins() {
    std::vector<TreeTemplate> all;
    for (const auto& [file, text] : builtin_template_texts()) {
        all.push_back(parse_template_file(text, "templates/" + std::string(file)));
        // Not a file the user has: errors count the grammar's own lines.
        all.back().source.clear();
        all.back().grammar_line = 1;
    }
    // The default first, the rest in file-name order.
    std::stable_partition(all.begin(), all.end(),
                          [](const TreeTemplate& t) { return t.name == kDefaultName; });
    return all;
}

}  // namespace

const std::vector<const TreeTemplate*>& builtin_templates() {
    static const std::vector<TreeTemplate> parsed = parse_builtins();
    static const std::vector<const TreeTemplate*> all = [] {
        std::vector<const TreeTemplate*> out;
        for (const TreeTemplate& t : parsed) out.push_back(&t);
        return out;
    }();
    return all;
}

std::string_view builtin_template_text(std::string_view name) {
    const auto& texts = builtin_template_texts();
    for (const auto& [file, text] : texts) {
        // The file's stem is the template's name for every built-in one; fall back to parsing.
        if (std::filesystem::path(file).stem().string() == name) return text;
    }
    for (std::size_t i = 0; i < texts.size(); ++i)
        if (parse_template_file(texts[i].second, std::string(texts[i].first)).name == name)
            return texts[i].second;
    return {};
}

const TreeTemplate& default_template() {
    return *builtin_templates().front();
}

namespace {

const TreeTemplate* builtin_named(const std::string& name) {
    if (name == "default") return &default_template();
    for (const TreeTemplate* t : builtin_templates())
        if (t->name == name) return t;
    return nullptr;
}

std::string builtin_names() {
    std::string names;
    for (const TreeTemplate* t : builtin_templates())
        names += (names.empty() ? "" : ", ") + t->name;
    return names;
}

TreeTemplate parse_template_text(const std::string& text, const std::filesystem::path& path) {
    if (path.extension() == ".toml") return parse_template_file(text, path.string());
    // A bare grammar file: parameters take their defaults.
    TreeTemplate t;
    t.name = path.stem().string();
    t.description = "grammar file " + path.string();
    t.grammar = text;
    t.source = path.string();
    return t;
}

}  // namespace

TreeTemplate load_template(const std::string& name_or_path) {
    if (const TreeTemplate* t = builtin_named(name_or_path)) return *t;
    std::error_code ec;
    if (!std::filesystem::exists(name_or_path, ec))
        throw InputError("'" + name_or_path + "' is neither a built-in template (" +
                         builtin_names() + ") nor an existing file");
    return parse_template_text(read_input_file(name_or_path, "template"), name_or_path);
}

TreeTemplate load_template_reference(const std::string& name, const std::filesystem::path& folder,
                                     const std::string& where) {
    if (const TreeTemplate* t = builtin_named(name)) return *t;
    const std::filesystem::path path = resolve_data_reference(name, folder, where);
    std::error_code ec;
    if (!std::filesystem::exists(path, ec))
        throw InputError(where + ": '" + name + "' is neither a built-in template (" +
                         builtin_names() + ") nor a file beside it");
    return parse_template_text(read_input_file(path, "template"), path);
}

}  // namespace sylva
