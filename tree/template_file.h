// Template files (TOML): a human-editable, commented description of one tree: name,
// description, grammar, turtle mode, width model, every parameter and the part colours.
//
//   name = "oak"
//   description = "..."
//   growth = "lsystem"       # the growth method (tree/growth.h); lsystem is the default
//   turtle = "abop"          # abop | lptg (Heuer's 2022 elevation/azimuth turtle)
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
//   palette = [[0.3, 0.2, 0.1], [0.9, 0.9, 1.0]]   # colour index i (' and ;) -> entry i
//   (or, the palette alone: colors = [[...], [...]])
#pragma once

#include <filesystem>
#include <map>
#include <string>
#include <string_view>

#include "core/tree_template.h"

namespace sylva {

// Throws InputError naming `source` (a file name), the line and the key at fault.
TreeTemplate parse_template_file(std::string_view text, const std::string& source);

// The comments of a template file, to write them again: the header above the first key,
// the comment lines above a key or table ("params.leaf_size", "[colors]") and the comment
// at the end of a key's line (with its '#').
struct TemplateComments {
    std::string header;
    std::map<std::string, std::string> above;
    std::map<std::string, std::string> after;
};
TemplateComments template_comments(std::string_view text);

// The TOML text of a template; parse_template_file reads it back to an equal template.
// Numbers are written as the shortest text that reads back to them (0.8, not
// 0.80000000000000004). The comments of `original` (the text the template was read from,
// when there is one) are kept at the keys they stood at. Throws InputError for a seed outside
// core/seed.h's range (no reader would take the file back).
std::string template_file_text(const TreeTemplate& tree, std::string_view original = {});

// Throws IoError naming the path (InputError as template_file_text); never leaves a partial
// file.
void save_template_file(const std::filesystem::path& path, const TreeTemplate& tree,
                        std::string_view original = {});

}  // namespace sylva
