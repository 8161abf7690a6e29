// Which parameters a template's tree never reads, each with the reason a person can act on
// ("every F in the rules gives its own length"): the studio greys those controls out. Made of
// the growth method's answer (GrowthMethod::unread), the other methods' parameters, and the
// shared parameters that others switch off (no leaves, no crown mesh, no budget).
#pragma once

#include <functional>
#include <map>
#include <string>

#include "core/tree_template.h"

namespace sylva {

// Keys of param_infos() (tree/parameters.h) with their reasons. May grow the tree (space
// colonization's max_no_grow is judged by growing): cache the answer where it is asked often.
// An unknown growth method leaves only the shared parameters' reasons.
std::map<std::string, std::string, std::less<>> unread_params(const TreeTemplate& tree);

}  // namespace sylva
