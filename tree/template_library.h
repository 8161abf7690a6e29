// Where templates come from: the ones built into the binary, or a file on disk.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>
#include <vector>

#include "core/tree_template.h"

namespace sylva {

// The built-in default tree (the oak), compiled into the binary.
const TreeTemplate& default_template();

// Built-in templates (templates/*.toml compiled in), the default tree first.
const std::vector<const TreeTemplate*>& builtin_templates();

// The file text a built-in template was read from (its comments included), for saving a copy
// that keeps them; empty for an unknown name.
std::string_view builtin_template_text(std::string_view name);

// `-t` semantics (docs/cli.md): a built-in template's name ("default" is the default tree),
// else a file: a template file (.toml, template_file.h) or a bare grammar in the syntax of
// docs/grammar.md whose parameters take their defaults.
// The user names the file, so any path is taken; it must be a regular file within
// input_size_limit() (core/input_file.h).
// Throws InputError for an unknown name or bad content, IoError when the file cannot be read.
TreeTemplate load_template(const std::string& name_or_path);

// A template that a data file names (a species list, a plan): a built-in template's name, or
// a file relative to `folder`, the naming file's folder, which it may not leave
// (resolve_data_reference(), core/data_paths.h). `where` says where the name stands
// ("species.json: species[0].template"). Throws as load_template() and resolve_data_reference().
TreeTemplate load_template_reference(const std::string& name, const std::filesystem::path& folder,
                                     const std::string& where);

}  // namespace sylva
