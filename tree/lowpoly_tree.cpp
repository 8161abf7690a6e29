#include "tree/lowpoly_tree.h"

#include "lowpoly/merge_meshes.h"

namespace sylva {
namespace {

void append_note(std::string& notes, const std::string& part, const std::string& note) {
    if (note.empty()) return;
    if (!notes.empty()) notes += "; ";
    notes += part.empty() ? note : part + ": " + note;
}

}  // namespace

ReducedTree reduce_tree(const Tree& tree, const TreeBudget& budget,
                        const DecimateSettings& settings) {
    ReducedTree out;
    DecimateSettings s = settings;
    if (!budget.trunk && !budget.crown) {
        s.max_triangles = budget.total;
        const Mesh* parts[] = {&tree.trunk, &tree.crown};
        DecimateResult r = decimate(parts, s);
        out.trunk = std::move(r.parts[0]);
        out.crown = std::move(r.parts[1]);
        out.within_budget = r.within_budget;
        out.backoffs = r.backoffs;
        out.handles_cut = r.handles_cut;
        out.note = r.note;
    } else {
        const std::size_t trunk_budget =
            budget.trunk ? *budget.trunk : budget.total - std::min(budget.total, *budget.crown);
        const std::size_t crown_budget =
            budget.crown ? *budget.crown : budget.total - std::min(budget.total, *budget.trunk);
        s.max_triangles = trunk_budget;
        DecimateResult trunk = decimate(tree.trunk, s);
        s.max_triangles = crown_budget;
        DecimateResult crown = decimate(tree.crown, s);
        out.trunk = std::move(trunk.parts[0]);
        out.crown = std::move(crown.parts[0]);
        out.within_budget = trunk.within_budget && crown.within_budget;
        out.backoffs = trunk.backoffs + crown.backoffs;
        out.handles_cut = trunk.handles_cut + crown.handles_cut;
        append_note(out.note, "trunk", trunk.note);
        append_note(out.note, "crown", crown.note);
    }
    out.triangles = out.trunk.triangles.size() + out.crown.triangles.size();
    return out;
}

std::vector<std::size_t> lod_budgets(std::size_t finest, std::size_t levels) {
    std::vector<std::size_t> budgets;
    for (std::size_t i = 0; i < levels; ++i)
        budgets.push_back(std::max<std::size_t>(finest >> i, 4));
    return budgets;
}

std::vector<ReducedTree> make_lod_chain(const Tree& tree, std::span<const std::size_t> budgets,
                                        const DecimateSettings& settings) {
    std::vector<ReducedTree> levels;
    for (std::size_t budget : budgets) {
        TreeBudget b;
        b.total = budget;
        levels.push_back(reduce_tree(tree, b, settings));
    }
    return levels;
}

Mesh reference_surface(const TreeTemplate& tree, int resolution, const MeshOptions& options) {
    TreeTemplate fine = tree;
    fine.params.trunk_resolution = resolution;
    fine.params.crown_resolution = resolution;
    const Tree t = generate_tree(fine, options);
    const Mesh* parts[] = {&t.trunk, &t.crown};
    return merge_meshes(parts);
}

Fidelity measure_tree_fidelity(const Mesh& trunk, const Mesh& crown, const Mesh& reference,
                               const FidelitySettings& settings) {
    const Mesh* parts[] = {&trunk, &crown};
    return measure_fidelity(merge_meshes(parts), reference, settings);
}

}  // namespace sylva
