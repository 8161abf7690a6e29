#include "ui/layout_panel.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <glm/common.hpp>

#include "core/errors.h"
#include "forest/forest.h"
#include "layout/cost.h"
#include "layout/derive.h"
#include "layout/examples.h"
#include "layout/geometry.h"
#include "layout/positions.h"
#include "tree/cost.h"
#include "ui/state/forest_preview_plan.h"

namespace sylva::studio {

namespace {

using Clock = std::chrono::steady_clock;

ImU32 to_imgui(std::uint32_t rgb, int alpha = 255) {
    return IM_COL32((rgb >> 16) & 0xff, (rgb >> 8) & 0xff, rgb & 0xff, alpha);
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

// Something to draw in a cell, in the example's units: filled faces, edges and the stubs of
// half-edges (a rule side's open ends).
struct Picture {
    std::vector<std::pair<std::vector<glm::dvec2>, std::uint32_t>> faces;
    std::vector<std::pair<glm::dvec2, glm::dvec2>> edges, stubs;
};

Picture picture_of(const layout::PolygonMesh& mesh) {
    Picture p;
    for (const layout::Polygon& poly : mesh.polygons) {
        std::vector<glm::dvec2> pts;
        for (int i : poly.vertices) pts.push_back(mesh.vertices[i]);
        for (std::size_t k = 0; k < pts.size(); ++k)
            p.edges.emplace_back(pts[k], pts[(k + 1) % pts.size()]);
        p.faces.emplace_back(std::move(pts), poly.color);
    }
    return p;
}

// A partial graph placed by walking its edges at the example's mean lengths (thumbnails of
// rule sides: faces close where the example's plots are alike, near enough otherwise).
Picture picture_of(const layout::Piece& piece, const layout::Directions& dirs) {
    Picture p;
    auto unit = [&](int dir) {
        const double r = dirs.degrees[dir] * M_PI / 180.0;
        return glm::dvec2(std::cos(r), std::sin(r));
    };
    if (piece.floating) {
        const double len = dirs.length_of(piece.edge);
        p.edges.emplace_back(glm::dvec2(0), unit(piece.edge.dir) * len);
        p.stubs.emplace_back(-unit(piece.edge.dir) * (0.3 * len), glm::dvec2(0));
        p.stubs.emplace_back(unit(piece.edge.dir) * len, unit(piece.edge.dir) * (1.3 * len));
        return p;
    }
    const layout::AngleGraph& g = piece.graph;
    const int n = static_cast<int>(g.vertices.size());
    std::vector<glm::dvec2> pos(n);
    std::vector<char> placed(n, 0);
    std::vector<int> stack{0};
    placed[0] = 1;
    while (!stack.empty()) {
        const int v = stack.back();
        stack.pop_back();
        for (int i = 0; i < static_cast<int>(g.vertices[v].size()); ++i) {
            const layout::Dart& d = g.vertices[v][i];
            if (d.to < 0 || placed[d.to]) continue;
            placed[d.to] = 1;
            pos[d.to] = pos[v] + unit(d.dir) * dirs.length_of(layout::dart_label(g, v, i));
            stack.push_back(d.to);
        }
    }
    for (int v = 0; v < n; ++v)
        for (int i = 0; i < static_cast<int>(g.vertices[v].size()); ++i) {
            const layout::Dart& d = g.vertices[v][i];
            const double len = dirs.length_of(layout::dart_label(g, v, i));
            if (d.to < 0)
                p.stubs.emplace_back(pos[v], pos[v] + unit(d.dir) * (0.35 * len));
            else if (d.to > v)
                p.edges.emplace_back(pos[v], pos[d.to]);
        }
    const layout::Analysis a = layout::analyze(g, dirs);
    for (const layout::Walk& w : a.walks) {
        if (!w.items.empty() || w.turning > 0 || w.color <= 0) continue;
        std::vector<glm::dvec2> pts;
        for (auto it = w.darts.rbegin(); it != w.darts.rend(); ++it)
            pts.push_back(pos[g.vertices[it->first][it->second].to]);
        p.faces.emplace_back(std::move(pts), dirs.palette[w.color]);
    }
    return p;
}

// Draws `p` fitted into a w x h cell at the cursor, and advances the cursor.
void draw_picture(const Picture& p, float w, float h, bool selected = false) {
    ImDrawList* list = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();
    ImGui::Dummy(ImVec2(w, h));
    list->AddRectFilled(origin, ImVec2(origin.x + w, origin.y + h), IM_COL32(250, 250, 245, 255));
    if (selected)
        list->AddRect(origin, ImVec2(origin.x + w, origin.y + h), IM_COL32(230, 120, 20, 255), 0.0f,
                      0, 3.0f);
    glm::dvec2 lo(1e300), hi(-1e300);
    auto grow = [&](glm::dvec2 q) { lo = glm::min(lo, q), hi = glm::max(hi, q); };
    for (const auto& [pts, c] : p.faces)
        for (const glm::dvec2& q : pts) grow(q);
    for (const auto& [a, b] : p.edges) grow(a), grow(b);
    for (const auto& [a, b] : p.stubs) grow(a), grow(b);
    if (lo.x > hi.x) return;
    const double extent = std::max({hi.x - lo.x, hi.y - lo.y, 1e-9});
    const double scale = std::min((w - 10.0) / std::max(hi.x - lo.x, 1e-9 * extent),
                                  (h - 10.0) / std::max(hi.y - lo.y, 1e-9 * extent));
    const glm::dvec2 mid = 0.5 * (lo + hi);
    auto to_screen = [&](glm::dvec2 q) {
        return ImVec2(origin.x + 0.5f * w + static_cast<float>((q.x - mid.x) * scale),
                      origin.y + 0.5f * h - static_cast<float>((q.y - mid.y) * scale));
    };
    for (const auto& [pts, color] : p.faces) {
        std::vector<ImVec2> screen;
        for (const glm::dvec2& q : pts) screen.push_back(to_screen(q));
        fill_polygon(list, screen, pts, to_imgui(color));
    }
    for (const auto& [a, b] : p.edges)
        list->AddLine(to_screen(a), to_screen(b), IM_COL32(40, 40, 40, 255), 1.0f);
    for (const auto& [a, b] : p.stubs)
        list->AddLine(to_screen(a), to_screen(b), IM_COL32(200, 60, 40, 255), 2.0f);
}

// Derives (unless `table` is given) and generates: what the worker runs.
std::shared_ptr<const LayoutResult> run_job(std::string source, int seed, int count, int size,
                                            std::shared_ptr<const layout::GrowthTable> table,
                                            std::optional<layout::Example> input,
                                            std::shared_ptr<std::atomic<bool>> cancel) {
    auto r = std::make_shared<LayoutResult>();
    r->source = std::move(source);
    r->seed = seed, r->count = count, r->size = size;
    try {
        const auto t0 = Clock::now();
        // Refused above the command line's default limits, as `sylva layout` refuses it.
        const CostLimits limits;
        auto affordable = [&](const layout::LayoutCost& c, const std::string& what) {
            if (c.seconds > limits.max_seconds || c.bytes > limits.max_bytes) {
                char text[160];
                std::snprintf(text, sizeof text, " is estimated at about %.2g GB and %.3g s",
                              c.bytes / 1e9, c.seconds);
                throw InputError(what + " (" + c.what + ")" + text + ", too much for the studio");
            }
        };
        if (!table) {
            input = layout::make_example(layout::load_example(r->source));
            layout::DeriveSettings d;
            d.cancel = cancel.get();
            affordable(layout::derive_cost(*input, d), "deriving this example");
            table = std::make_shared<const layout::GrowthTable>(layout::derive_grammar(*input, d));
        }
        r->input = std::move(input);
        r->table = table;
        const layout::Grammar& g = table->grammar();
        for (std::size_t i = 0; i < g.starters.size() && i < 8; ++i)
            if (g.starters[i].vertices.size() <= 4096)
                if (auto m = layout::realize(g.starters[i], g.dirs, i + 1, {}, 12, 3))
                    r->starters.push_back(std::move(*m));
        const auto t1 = Clock::now();
        layout::VariationSettings v;
        v.size = size;
        v.cancel = cancel.get();
        v.threads = 1;  // the UI thread and the tree's own jobs keep the other cores
        affordable(layout::generate_cost(*table, count, v), "these variations");
        r->variations = layout::generate_layouts(*table, count, static_cast<std::uint64_t>(seed), v,
                                                 &r->report);
        r->derive_ms = std::chrono::duration<double, std::milli>(t1 - t0).count();
        r->generate_ms = std::chrono::duration<double, std::milli>(Clock::now() - t1).count();
    } catch (const Cancelled&) {
        r->error = "cancelled";
    } catch (const std::exception& e) {
        r->error = e.what();
    }
    return r;
}

bool finished(const std::future<std::shared_ptr<const LayoutResult>>& job) {
    return job.valid() && job.wait_for(std::chrono::seconds(0)) == std::future_status::ready;
}

// Starts a job for the panel's settings unless the shown result or the running job has them.
void refresh(LayoutPanelState& s) {
    std::erase_if(s.stale, [](const auto& j) { return finished(j); });
    if (finished(s.job)) {
        std::shared_ptr<const LayoutResult> r = s.job.get();
        if (r->error.empty() || !s.shown) s.shown = r;
        if (!r->error.empty() && r->error != "cancelled") {
            s.message = r->error;
            s.message_failed = true;
        }
    }
    auto same = [&](const LayoutResult& r) {
        return r.source == s.source && r.seed == s.seed && r.count == s.count && r.size == s.size;
    };
    if (s.shown && same(*s.shown) && !s.job.valid()) return;
    if (s.job.valid()) {
        if (same(s.job_settings)) return;
        s.cancel->store(true);
        s.stale.push_back(std::move(s.job));
    }
    s.cancel = std::make_shared<std::atomic<bool>>(false);
    s.job_settings.source = s.source;
    s.job_settings.seed = s.seed, s.job_settings.count = s.count, s.job_settings.size = s.size;
    // The same example: its grammar is kept, only the variations are made again.
    std::shared_ptr<const layout::GrowthTable> table;
    std::optional<layout::Example> input;
    if (s.shown && s.shown->source == s.source && s.shown->table) {
        table = s.shown->table;
        input = s.shown->input;
    }
    s.message.clear();
    s.job = std::async(std::launch::async, run_job, s.source, s.seed, s.count, s.size, table,
                       std::move(input), s.cancel);
}

forest::Ground ground_of(const layout::PolygonMesh& mesh) {
    forest::Ground g;
    for (const layout::PlantingPolygon& p : layout::planting_polygons(mesh))
        g.polygons.push_back({p.points, p.planting_class});
    return g;
}

void start_forest_export(LayoutPanelState& s, const StudioState& studio, const std::string& path) {
    const LayoutResult& r = *s.shown;
    ForestPreviewPlan plan;
    plan.ground = std::make_shared<const forest::Ground>(ground_of(r.variations[s.selected]));
    forest::ForestSettings settings =
        forest_preview_settings(studio.shown_template, studio.view.forest_options, plan);
    settings.finish.budget.total =
        static_cast<std::size_t>(std::max(0, studio.shown_template.params.triangle_budget));
    s.export_cancel = std::make_shared<std::atomic<bool>>(false);
    settings.cancel = s.export_cancel.get();
    s.export_job = std::async(std::launch::async, [settings, path] {
        try {
            const forest::ForestResult result = forest::plant_forest(settings, path);
            return "wrote " + path + ": " + std::to_string(result.plan.placements.size()) +
                   " trees";
        } catch (const std::exception& e) {
            return std::string("forest not written: ") + e.what();
        }
    });
}

}  // namespace

bool select_layout_example(LayoutPanelState& state, const std::string& name_or_path) {
    bool known = false;
    for (const auto& [example, text] : layout::builtin_examples())
        known = known || example == name_or_path;
    std::error_code ec;
    if (!known && !std::filesystem::is_regular_file(name_or_path, ec)) return false;
    state.source = name_or_path;
    state.open = true;
    state.selected = 0;
    return true;
}

bool plant_layout(LayoutPanelState& s, StudioState& studio) {
    const LayoutResult* r = s.shown.get();
    if (!r || r->variations.empty() || r->source != s.source) return false;
    s.selected = std::clamp(s.selected, 0, static_cast<int>(r->variations.size()) - 1);
    ForestPreviewPlan& plan = studio.view.forest_plan;
    plan.ground = std::make_shared<const forest::Ground>(ground_of(r->variations[s.selected]));
    plan.id = ++s.planted;
    studio.view.forest = true;
    s.message = "planting variation " + std::to_string(s.selected) + " with " +
                studio.shown_template.name + " (the forest view)";
    s.message_failed = false;
    return true;
}

void open_layout_file(LayoutPanelState& state, const std::string& path) {
    state.source = path;
    state.open = true;
    state.selected = 0;
}

void draw_layout_panel(LayoutPanelState& s, StudioState& studio, const PanelLayout& layout) {
    if (!s.open) return;
    refresh(s);
    if (s.plant_when_ready && plant_layout(s, studio)) s.plant_when_ready = false;
    // Over the lower half of the 3D view, reaching a little over the side panels.
    const float x0 = 0.5f * layout.left, x1 = layout.width - 0.5f * layout.right;
    ImGui::SetNextWindowPos(ImVec2(x0, 0.42f * layout.height), ImGuiCond_FirstUseEver);
    ImGui::SetNextWindowSize(ImVec2(x1 - x0, 0.55f * layout.height - layout.bottom),
                             ImGuiCond_FirstUseEver);
    if (!ImGui::Begin("2D layouts from one example", &s.open)) {
        ImGui::End();
        return;
    }
    // The example: shipped ones by name, or a file.
    ImGui::SetNextItemWidth(170);
    const std::string shown_name = std::filesystem::path(s.source).filename().string();
    if (ImGui::BeginCombo("##example", shown_name.c_str())) {
        for (const auto& [name, text] : layout::builtin_examples())
            if (ImGui::Selectable(name.c_str(), name == s.source)) select_layout_example(s, name);
        ImGui::EndCombo();
    }
    ImGui::SameLine();
    if (ImGui::Button("Open example...")) {
        s.open_dialog.saving = false;
        s.open_dialog.extensions = {".mesh", ".json"};
        s.open_dialog.what = "layout example";
        s.open_dialog.open_requested = true;
    }
    if (auto path = file_dialog(s.open_dialog, {})) open_layout_file(s, *path);
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90);
    if (ImGui::InputInt("seed", &s.seed)) s.seed = std::max(s.seed, 0);  // core/seed.h's range
    ImGui::SameLine();
    ImGui::SetNextItemWidth(80);
    ImGui::SliderInt("count", &s.count, 1, 48);
    const LayoutResult* r = s.shown.get();
    const int base = r && r->table ? r->table->example_size() : 1;
    const char* unit = r && r->table ? layout::measure_name(r->table->measure()) : "polygons";
    ImGui::SameLine();
    ImGui::SetNextItemWidth(200);
    char size_text[64];
    if (s.size <= 0)
        std::snprintf(size_text, sizeof size_text, "sizes %d to %d %s", base + 1, 12 * base, unit);
    else
        std::snprintf(size_text, sizeof size_text, "%d %s", s.size, unit);
    ImGui::SliderInt("target size", &s.size, 0, std::max(24, 20 * base), size_text);
    if (s.job.valid()) {
        ImGui::SameLine();
        ImGui::TextDisabled(r && r->source == s.source ? "growing..." : "deriving...");
    }
    if (!s.message.empty())
        ImGui::TextColored(
            s.message_failed ? ImVec4(1, 0.4f, 0.3f, 1) : ImVec4(0.6f, 0.9f, 0.6f, 1), "%s",
            s.message.c_str());
    if (!r || !r->table || !r->input) {
        ImGui::End();
        return;
    }
    const layout::Grammar& g = r->table->grammar();
    const layout::HierarchyReport& h = g.hierarchy;
    ImGui::Text(
        "%s: %zu primitives, %zu starter rules, %zu rules (%.0f ms); hierarchy %d graphs, %s",
        std::filesystem::path(r->source).filename().string().c_str(), g.primitives.size(),
        g.starters.size(), g.rules.size(), r->derive_ms, h.graphs,
        h.stopped_by == "closed" ? "closed" : ("ended by its " + h.stopped_by + " limit").c_str());
    // The example, the primitives and the starter rules; then the rules, scrolling.
    const float cell = 90.0f, small = 48.0f;
    ImGui::BeginGroup();
    ImGui::TextUnformatted("example");
    draw_picture(picture_of(r->input->mesh), cell, cell);
    ImGui::EndGroup();
    ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::TextUnformatted("primitives");
    for (std::size_t i = 0; i < g.primitives.size(); ++i) {
        if (i % 6 != 0) ImGui::SameLine();
        draw_picture(picture_of(layout::Piece{g.primitives[i], false, {}}, g.dirs), small * 0.85f,
                     small * 0.85f);
    }
    ImGui::EndGroup();
    ImGui::SameLine();
    ImGui::BeginGroup();
    ImGui::TextUnformatted("starter rules");
    for (std::size_t i = 0; i < r->starters.size(); ++i) {
        if (i > 0) ImGui::SameLine();
        draw_picture(picture_of(r->starters[i]), small, small);
    }
    ImGui::EndGroup();
    ImGui::TextUnformatted("rules  L <-> R1 v R2 ... (red: open ends, the interface)");
    ImGui::BeginChild("rules", ImVec2(0, 1.7f * (small + 8.0f)), true);
    ImGuiListClipper clipper;
    clipper.Begin(static_cast<int>(g.rules.size()), small + 8.0f);
    while (clipper.Step())
        for (int i = clipper.DisplayStart; i < clipper.DisplayEnd; ++i) {
            const layout::Rule& rule = g.rules[i];
            ImGui::Text("%4d", i + 1);
            ImGui::SameLine();
            draw_picture(picture_of(layout::Piece{rule.left, false, {}}, g.dirs), small, small);
            ImGui::SameLine();
            ImGui::TextUnformatted("<->");
            for (const layout::Piece& p : rule.right) {
                ImGui::SameLine();
                draw_picture(picture_of(p, g.dirs), small, small);
            }
            ImGui::SameLine();
            ImGui::TextDisabled("%s", rule.boundary.c_str());
        }
    ImGui::EndChild();
    // The variations: a strip to pick one from.
    int lo = 1 << 30, hi = 0;
    for (const layout::VariationReport& v : r->report.items)
        lo = std::min(lo, v.size), hi = std::max(hi, v.size);
    ImGui::Text("%zu variations, %d to %d %s (%.0f ms)", r->variations.size(), lo, hi, unit,
                r->generate_ms);
    const std::string bound = r->report.limits();
    if (!bound.empty()) {
        ImGui::SameLine();
        ImGui::TextDisabled("(%s)", bound.c_str());
    }
    s.selected = std::clamp(s.selected, 0, std::max(0, static_cast<int>(r->variations.size()) - 1));
    const float strip = std::clamp(
        ImGui::GetContentRegionAvail().y - 2.0f * ImGui::GetFrameHeightWithSpacing() - 8.0f, 120.0f,
        260.0f);
    ImGui::BeginChild("variations", ImVec2(0, strip), true, ImGuiWindowFlags_HorizontalScrollbar);
    const float thumb = strip - 2.0f * ImGui::GetTextLineHeightWithSpacing() -
                        ImGui::GetStyle().ScrollbarSize - 8.0f;
    for (std::size_t i = 0; i < r->variations.size(); ++i) {
        if (i > 0) ImGui::SameLine();
        ImGui::BeginGroup();
        ImGui::PushID(static_cast<int>(i));
        const ImVec2 at = ImGui::GetCursorScreenPos();
        draw_picture(picture_of(r->variations[i]), thumb, thumb, static_cast<int>(i) == s.selected);
        ImGui::SetCursorScreenPos(at);
        if (ImGui::InvisibleButton("pick", ImVec2(thumb, thumb))) s.selected = static_cast<int>(i);
        ImGui::Text("%d %s", r->report.items[i].size, unit);
        ImGui::PopID();
        ImGui::EndGroup();
    }
    ImGui::EndChild();
    // Plant the chosen plan into the forest preview; export the planted forest.
    const bool any = !r->variations.empty();
    ImGui::BeginDisabled(!any);
    if (ImGui::Button("Plant this plan")) plant_layout(s, studio);
    ImGui::SameLine();
    ImGui::BeginDisabled(s.export_job.valid());
    if (ImGui::Button("Export planted forest...")) {
        s.export_dialog.saving = true;
        s.export_dialog.extensions = {".glb"};
        s.export_dialog.what = "forest";
        if (s.export_dialog.name.empty()) s.export_dialog.name = "forest.glb";
        s.export_dialog.open_requested = true;
    }
    ImGui::EndDisabled();
    ImGui::EndDisabled();
    if (auto path = file_dialog(s.export_dialog, {})) start_forest_export(s, studio, *path);
    ImGui::SameLine();
    if (studio.view.forest_plan.ground && ImGui::Button("Back to the square"))
        studio.view.forest_plan = {};
    if (s.export_job.valid()) {
        if (s.export_job.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
            s.message = s.export_job.get();
            s.message_failed = s.message.rfind("wrote", 0) != 0;
        } else {
            ImGui::SameLine();
            ImGui::TextDisabled("planting and writing the forest...");
        }
    }
    ImGui::End();
}

void release_layout_panel(LayoutPanelState& s) {
    if (s.cancel) s.cancel->store(true);
    if (s.export_cancel) s.export_cancel->store(true);
    if (s.job.valid()) s.job.wait();
    for (auto& j : s.stale)
        if (j.valid()) j.wait();
    if (s.export_job.valid()) s.export_job.wait();
}

}  // namespace sylva::studio
