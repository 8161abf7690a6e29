// Template files (TOML): a human-editable, commented description of one tree: name,
// description, grammar, turtle mode, width model, every parameter and the part colours.
//
//   name = "oak"
//   description = "..."
//   growth = "lsystem"       # the growth method (tree/growth.h); lsystem is the default
//   turtle = "abop"          # abop | lptg (seed 001's elevation/azimuth turtle)
//   widths = "explicit"      # explicit | taper | pipe
//   grammar = '''
//   axiom: A
//   A -> F[+A][-A]
//   '''
//   [params]                 # any key of `sylva --help`; omitted keys keep their defaults
//   generations = 6
//   leaf_shape = "oak"
//   [colors]                 # linear RGB, 0-1
//   trunk = [0.36, 0.24, 0.15]
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

#include "core/tree_template.h"

namespace sylva {

// Throws InputError naming `source` (a file name), the line and the key at fault.
TreeTemplate parse_template_file(std::string_view text, const std::string& source);

// The TOML text of a template; parse_template_file reads it back to an equal template.
std::string template_file_text(const TreeTemplate& tree);

// Throws IoError naming the path; never leaves a partial file.
void save_template_file(const std::filesystem::path& path, const TreeTemplate& tree);

}  // namespace sylva
