// A forest's species list as a file, for more than `--species oak:2,birch` says: each
// species a template (built-in name or file) with a weight and parameter overrides.
//
//   {"species": [
//     {"template": "oak", "weight": 2, "set": {"leaf_density": 40}},
//     {"template": "my_birch.toml"}
//   ]}
#pragma once

#include <filesystem>
#include <string>
#include <vector>

#include "forest/forest.h"

namespace sylva::forest {

// "weight" defaults to 1, "set" to none. A "template" is a built-in name or a file inside
// `folder` (the species file's own; empty: built-in names only), never outside it
// (load_template_reference(), tree/template_library.h). Throws InputError naming `source`
// and the JSON line and column of a syntax error, or the entry ("species[1].set.age") of a
// bad value, and what load_template_reference() / set_param() throw.
std::vector<Species> parse_species_json(const std::string& text, const std::string& source,
                                        const std::filesystem::path& folder = {});
// Reads a file (read_input_file(), core/input_file.h) and parses it, its templates looked up
// beside it.
std::vector<Species> load_species(const std::filesystem::path& path);

}  // namespace sylva::forest
