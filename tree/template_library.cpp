#include "tree/template_library.h"

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "core/errors.h"
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

TreeTemplate load_template(const std::string& name_or_path) {
    if (name_or_path == "default") return default_template();
    for (const TreeTemplate* t : builtin_templates())
        if (t->name == name_or_path) return *t;
    std::error_code ec;
    if (!std::filesystem::exists(name_or_path, ec)) {
        std::string names;
        for (const TreeTemplate* t : builtin_templates())
            names += (names.empty() ? "" : ", ") + t->name;
        throw InputError("'" + name_or_path + "' is neither a built-in template (" + names +
                         ") nor an existing file");
    }
    if (std::filesystem::is_directory(name_or_path, ec))
        throw IoError("cannot read '" + name_or_path + "': it is a directory", name_or_path);
    std::ifstream in(name_or_path, std::ios::binary);
    if (!in)
        throw IoError("cannot read '" + name_or_path + "': " + std::strerror(errno), name_or_path);
    std::ostringstream text;
    text << in.rdbuf();
    if (std::filesystem::path(name_or_path).extension() == ".toml")
        return parse_template_file(text.str(), name_or_path);
    // A bare grammar file: parameters take their defaults.
    TreeTemplate t;
    t.name = std::filesystem::path(name_or_path).stem().string();
    t.description = "grammar file " + name_or_path;
    t.grammar = text.str();
    t.source = name_or_path;
    return t;
}

}  // namespace sylva
