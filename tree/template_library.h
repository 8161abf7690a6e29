// Where templates come from: the ones built into the binary, or a file on disk.
#pragma once

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

// `-t` semantics (SPEC section 8): a built-in template's name ("default" is the default
// tree), else a file: a template file (.toml, template_file.h) or a bare grammar in the
// syntax of SPEC section 1 whose parameters take their defaults.
// Throws InputError for an unknown name, IoError when the file cannot be read.
TreeTemplate load_template(const std::string& name_or_path);

}  // namespace sylva
