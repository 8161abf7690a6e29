#include "app/template_library.h"

#include "app/errors.h"

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace sylva {

TreeTemplate load_template(const std::string& name_or_path) {
    for (const TreeTemplate* t : builtin_templates())
        if (t->name == name_or_path) return *t;
    std::error_code ec;
    if (!std::filesystem::exists(name_or_path, ec)) {
        std::string names;
        for (const TreeTemplate* t : builtin_templates()) names += (names.empty() ? "" : ", ") + t->name;
        throw InputError("'" + name_or_path + "' is neither a built-in template (" + names +
                         ") nor an existing file");
    }
    if (std::filesystem::is_directory(name_or_path, ec))
        throw IoError("cannot read '" + name_or_path + "': it is a directory");
    std::ifstream in(name_or_path, std::ios::binary);
    if (!in) throw IoError("cannot read '" + name_or_path + "': " + std::strerror(errno));
    std::ostringstream text;
    text << in.rdbuf();
    TreeTemplate t;
    t.name = std::filesystem::path(name_or_path).stem().string();
    t.description = "grammar file " + name_or_path;
    t.grammar = text.str();
    return t;
}

}  // namespace sylva
