#include "ui/layout_panel.h"

#include <imgui.h>

#include <algorithm>
#include <cmath>

#include "core/errors.h"
#include "layout/geometry.h"
#include "layout/layout_cli.h"
#include "layout/positions.h"

namespace sylva::studio {

namespace {

ImU32 to_imgui(std::uint32_t rgb) {
    return IM_COL32((rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff, 255);
}

// Ear clipping (polygons are small and counter-clockwise): ImGui fills convex shapes only.
void fill_polygon(ImDrawList* list, const std::vector<ImVec2>& screen,
                  const std::vector<glm::dvec2>& pts, ImU32 color) {
    // Collinear corners (a path's side passing plots) would make zero-area ears, which the
    // anti-aliased fill draws as spikes: leave them out, and fill without the AA fringe.
    std::vector<int> idx;
    const std::size_t n = pts.size();
    for (std::size_t i = 0; i < n; ++i) {
        const glm::dvec2 a = pts[(i + n - 1) % n], b = pts[i], c = pts[(i + 1) % n];
        if (std::abs(layout::cross(b - a, c - b)) > 1e-12 * glm::dot(c - a, c - a))
            idx.push_back(static_cast<int>(i));
    }
    const ImDrawListFlags flags = list->Flags;
    list->Flags &= ~ImDrawListFlags_AntiAliasedFill;
    int guard = 0;
    while (idx.size() > 3 && guard++ < 10000) {
        bool cut = false;
        for (std::size_t i = 0; i < idx.size() && !cut; ++i) {
            const int a = idx[(i + idx.size() - 1) % idx.size()], b = idx[i],
                      c = idx[(i + 1) % idx.size()];
            if (layout::cross(pts[b] - pts[a], pts[c] - pts[b]) <= 0) continue;  // reflex or flat
            bool empty = true;
            for (int k : idx) {
                if (k == a || k == b || k == c) continue;
                if (layout::point_in_polygon(pts[k], {pts[a], pts[b], pts[c]}, 0.0) >= 0)
                    empty = false;
            }
            if (!empty) continue;
            list->AddTriangleFilled(screen[a], screen[b], screen[c], color);
            idx.erase(idx.begin() + static_cast<long>(i));
            cut = true;
        }
        if (!cut) break;
    }
    if (idx.size() == 3)
        list->AddTriangleFilled(screen[idx[0]], screen[idx[1]], screen[idx[2]], color);
    list->Flags = flags;
}

// Draws `mesh` fitted into a size x size cell at the cursor, and advances the cursor.
void draw_mesh(const layout::PolygonMesh& mesh, float size) {
    ImDrawList* list = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(size, size));
    list->AddRectFilled(origin, ImVec2(origin.x + size, origin.y + size),
                        IM_COL32(250, 250, 245, 255));
    if (mesh.vertices.empty()) return;
    glm::dvec2 lo(1e300), hi(-1e300);
    for (const glm::dvec2& v : mesh.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, 1e-9});
    const double scale = (size - 12.0) / extent;
    auto to_screen = [&](glm::dvec2 p) {
        return ImVec2(origin.x + 6.0f + static_cast<float>((p.x - lo.x) * scale),
                      origin.y + size - 6.0f - static_cast<float>((p.y - lo.y) * scale));
    };
    for (const layout::Polygon& poly : mesh.polygons) {
        std::vector<ImVec2> screen;
        std::vector<glm::dvec2> pts;
        for (int i : poly.vertices) pts.push_back(mesh.vertices[i]);
        for (const glm::dvec2& p : mesh.vertices) screen.push_back(to_screen(p));
        std::vector<ImVec2> ring;
        for (int i : poly.vertices) ring.push_back(screen[i]);
        fill_polygon(list, ring, pts, to_imgui(poly.color));
        // Segment by segment: a closed polyline through collinear corners draws miter spikes.
        for (std::size_t k = 0; k < ring.size(); ++k)
            list->AddLine(ring[k], ring[(k + 1) % ring.size()], IM_COL32(40, 40, 40, 255), 1.0f);
    }
}

void rebuild(LayoutPanelState& state) {
    state.dirty = false;
    state.error.clear();
    state.variations.clear();
    state.starters.clear();
    try {
        const auto& examples = layout::builtin_examples();
        const auto& [name, text] = examples[static_cast<std::size_t>(state.example)];
        state.input = layout::make_example(layout::read_mesh_text(text, name + ".mesh"));
        state.grammar = layout::derive_grammar(*state.input);
        for (std::size_t i = 0; i < state.grammar->starters.size(); ++i)
            if (auto m = layout::realize(state.grammar->starters[i], state.grammar->dirs, i + 1))
                state.starters.push_back(*m);
        layout::GenerateSettings settings;
        settings.steps = state.steps;
        state.variations = layout::generate_layouts(
            *state.grammar, state.count, static_cast<std::uint64_t>(state.seed), settings);
    } catch (const std::exception& e) {
        state.error = e.what();
    }
}

}  // namespace

bool select_layout_example(LayoutPanelState& state, const std::string& name) {
    const auto& examples = layout::builtin_examples();
    for (std::size_t i = 0; i < examples.size(); ++i)
        if (examples[i].first == name) {
            state.example = static_cast<int>(i);
            state.open = true;
            state.dirty = true;
            return true;
        }
    return false;
}

void draw_layout_panel(LayoutPanelState& state, float width, float height) {
    if (!state.open) return;
    if (state.dirty) rebuild(state);
    ImGui::SetNextWindowPos(ImVec2(width * 0.22f, 20.0f), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(width * 0.56f, height * 0.85f), ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("Layout (example-based, seed 002)", &state.open)) {
        ImGui::End();
        return;
    }
    const auto& examples = layout::builtin_examples();
    const char* current = examples[static_cast<std::size_t>(state.example)].first.c_str();
    ImGui::SetNextItemWidth(160);
    if (ImGui::BeginCombo("example", current)) {
        for (std::size_t i = 0; i < examples.size(); ++i)
            if (ImGui::Selectable(examples[i].first.c_str(),
                                  static_cast<int>(i) == state.example)) {
                state.example = static_cast<int>(i);
                state.dirty = true;
            }
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    if (ImGui::InputInt("seed", &state.seed)) {
        state.seed = std::max(state.seed, 0);  // a seed of core/seed.h's range, as the CLI's
        state.dirty = true;
    }
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    if (ImGui::SliderInt("count", &state.count, 1, 48)) state.dirty = true;
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    if (ImGui::SliderInt("steps", &state.steps, 0, 64)) state.dirty = true;
    if (!state.error.empty())
        ImGui::TextColored(ImVec4(1, 0.4f, 0.3f, 1), "%s", state.error.c_str());
    if (state.input && state.grammar) {
        const layout::Grammar& g = *state.grammar;
        ImGui::Text(
            "%zu primitives, %zu starter rules, %zu rules; hierarchy %d graphs in %d generations, "
            "%d open",
            g.primitives.size(), g.starters.size(), g.rules.size(), g.hierarchy_graphs,
            g.generations, g.open_graphs);
        const float cell = 150.0f;
        ImGui::BeginGroup();
        ImGui::TextUnformatted("input");
        draw_mesh(state.input->mesh, cell);
        ImGui::EndGroup();
        for (std::size_t i = 0; i < state.starters.size() && i < 3; ++i) {
            ImGui::SameLine();
            ImGui::BeginGroup();
            ImGui::Text("starter rule %zu", i + 1);
            draw_mesh(state.starters[i], cell);
            ImGui::EndGroup();
        }
        ImGui::SameLine();
        ImGui::BeginChild("rules", ImVec2(0, cell + ImGui::GetTextLineHeightWithSpacing()), true);
        for (std::size_t i = 0; i < g.rules.size() && i < 200; ++i) {
            const layout::Rule& r = g.rules[i];
            int floating = 0;
            for (const layout::Piece& p : r.right) floating += p.floating;
            ImGui::Text("L%zu (%zu v) <-> %zu piece(s)%s  %s", i + 1, r.left.vertices.size(),
                        r.right.size(), floating ? " with edges" : "", r.boundary.c_str());
        }
        if (g.rules.size() > 200) ImGui::Text("... %zu more", g.rules.size() - 200);
        ImGui::EndChild();
        ImGui::Separator();
        ImGui::Text("%zu variations", state.variations.size());
        const int per_row =
            std::max(1, static_cast<int>(ImGui::GetContentRegionAvail().x / (cell + 8.0f)));
        for (std::size_t i = 0; i < state.variations.size(); ++i) {
            if (i % per_row != 0) ImGui::SameLine();
            draw_mesh(state.variations[i], cell);
        }
    }
    ImGui::End();
}

}  // namespace sylva::studio
