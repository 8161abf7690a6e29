#include "tree/lowpoly_tree.h"

#include "lowpoly/inner_shells.h"
#include "lowpoly/merge_meshes.h"

namespace sylva {
namespace {

void append_note(std::string& notes, const std::string& part, const std::string& note) {
    if (note.empty()) return;
    if (!notes.empty()) notes += "; ";
    notes += part.empty() ? note : part + ": " + note;
}

}  // namespace

// Trunk and crown reduced to their own budgets.
ReducedTree reduce_parts(const Mesh& trunk, const Mesh& crown, std::size_t trunk_budget,
                         std::size_t crown_budget, const DecimateSettings& settings) {
    DecimateSettings s = settings;
    s.max_triangles = trunk_budget;
    DecimateResult t = decimate(trunk, s);
    s.max_triangles = crown_budget;
    DecimateResult c = decimate(crown, s);
    ReducedTree out;
    out.trunk = std::move(t.parts[0]);
    out.crown = std::move(c.parts[0]);
    out.within_budget = t.within_budget && c.within_budget;
    out.backoffs = t.backoffs + c.backoffs;
    out.handles_cut = t.handles_cut + c.handles_cut;
    append_note(out.note, "trunk", t.note);
    append_note(out.note, "crown", c.note);
    return out;
}

ReducedTree reduce_tree(const Tree& tree, const TreeBudget& budget,
                        const DecimateSettings& settings) {
    // Hollows inside the trunk or crown are invisible and only cost triangles.
    Mesh trunk = tree.trunk, crown = tree.crown;
    remove_inner_shells(trunk);
    remove_inner_shells(crown);
    ReducedTree out;
    if (budget.trunk || budget.crown) {
        const std::size_t trunk_budget =
            budget.trunk ? *budget.trunk : budget.total - std::min(budget.total, *budget.crown);
        const std::size_t crown_budget =
            budget.crown ? *budget.crown : budget.total - std::min(budget.total, *budget.trunk);
        out = reduce_parts(trunk, crown, trunk_budget, crown_budget, settings);
    } else {
        DecimateSettings s = settings;
        s.max_triangles = budget.total;
        const Mesh* parts[] = {&trunk, &crown};
        DecimateResult r = decimate(parts, s);
        out.trunk = std::move(r.parts[0]);
        out.crown = std::move(r.parts[1]);
        out.within_budget = r.within_budget;
        out.backoffs = r.backoffs;
        out.handles_cut = r.handles_cut;
        out.note = r.note;
        // The shared budget follows the quadric error, which at small budgets can starve a
        // part down to a token (a four-triangle trunk beside a 90-triangle crown). Each part
        // that had more keeps at least a quarter of the budget.
        const std::size_t floor = budget.total / 4;
        auto starved = [floor](const Mesh& input, const Mesh& reduced) {
            return input.triangles.size() > floor && reduced.triangles.size() < floor;
        };
        const bool trunk_starved = starved(trunk, out.trunk);
        const bool crown_starved = starved(crown, out.crown);
        if (trunk_starved != crown_starved)
            out = reduce_parts(trunk, crown, trunk_starved ? floor : budget.total - floor,
                               crown_starved ? floor : budget.total - floor, settings);
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
