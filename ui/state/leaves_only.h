// A leaf edit without growing or meshing again. Leaf density, size and shape change only
// the leaves: the skeleton, trunk and crown an edit of them makes are the tree's own, so the
// studio scatters the new leaves over the shown tree's crown field and keeps the rest (and,
// with trunk and crown unchanged, the reduction too: studio_state.h's reuse_reduction()).
// tests/ui checks that the leaves are the bytes generate_tree() makes for the edit.
#pragma once

#include <optional>

#include "core/cancel.h"
#include "core/tree_template.h"
#include "tree/pipeline.h"

namespace sylva::studio {

// True when `a` and `b` differ at most in leaf_density, leaf_size and leaf_shape (colours,
// name and description aside): the same skeleton, trunk and crown.
bool leaves_only_edit(const TreeTemplate& a, const TreeTemplate& b);

// `tree`, generated from a template that differs from `edit` only in its leaves
// (leaves_only_edit()), with the leaves generate_tree(edit) makes. Nothing for a younger tree
// (age below 1: its crown is sized from the mature tree, which `tree` does not keep). Throws
// Cancelled once `cancel` is set.
std::optional<Tree> with_new_leaves(const Tree& tree, const TreeTemplate& edit,
                                    CancelFlag cancel = nullptr);

}  // namespace sylva::studio
