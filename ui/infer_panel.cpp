#include "ui/infer_panel.h"

#include <imgui.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <glm/common.hpp>

#include "core/cancel.h"
#include "core/errors.h"
#include "infer/example_tree.h"
#include "ui/state/orbit_camera.h"

namespace sylva::studio {
namespace {

// Magenta: apart from the bark, the foliage, the yellow skeleton and the blue envelope.
constexpr glm::vec3 kExampleColor{0.95f, 0.4f, 0.85f};
const ImVec4 kExampleText(0.95f, 0.4f, 0.85f, 1.0f);
const ImVec4 kWarningColor(1.0f, 0.75f, 0.25f, 1.0f);
const ImVec4 kErrorColor(1.0f, 0.45f, 0.4f, 1.0f);
constexpr float kPanelWidth = 390.0f;

// How close a regrown tree should come, per figure (docs/infer.md): past it a difference
// shows amber.
constexpr double kCountTarget = 0.10, kLengthTarget = 0.10, kHeightTarget = 0.05,
                 kWidthTarget = 0.05, kDepthTarget = 0.10;

double elapsed_ms(std::chrono::steady_clock::time_point since) {
    return std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - since)
        .count();
}

// The job: infer, then regrow and compare (infer/fit_report.h). Runs on a worker.
InferOutcome derive(ExampleTree example, std::string source, std::string name, int max_rules,
                    std::chrono::steady_clock::time_point started, CancelFlag cancel) {
    InferSettings settings;
    settings.max_rules = max_rules;
    settings.name = std::move(name);
    settings.cancel = cancel;
    InferOutcome out;
    out.source = std::move(source);
    out.inferred = infer_template(example, settings);
    out.infer_ms = elapsed_ms(started);
    GrowthContext context;
    context.cancel = cancel;
    out.report = fit_report(example, out.inferred, nullptr, context);
    out.report.max_rules = max_rules;
    out.example = example_skeleton_with_depths(example);
    return out;
}

void stop_job(InferPanel& panel) {
    if (!panel.job.valid()) return;
    panel.cancel->store(true);
    panel.job.wait();  // inference and regrowth poll the flag: this is short
    panel.job = {};
}

void begin_job(InferPanel& panel) {
    stop_job(panel);
    panel.cancel = std::make_shared<std::atomic<bool>>(false);
    panel.error.clear();
    panel.from_tree_pending = false;
}

std::vector<glm::vec3> example_lines(const InferPanel& panel) {
    std::vector<glm::vec3> lines;
    if (!panel.result) return lines;
    lines.reserve(2 * panel.result->example.segments.size());
    for (const Segment& s : panel.result->example.segments)
        lines.insert(lines.end(), {s.a + panel.offset, s.b + panel.offset});
    return lines;
}

// The example beside the regrown tree: to its left (the person stands on the right), a
// sixth of the height apart, so neither covers the other.
void place_example(InferPanel& panel) {
    const Skeleton& example = panel.result->example;
    glm::vec3 low = example.segments.front().a, high = low;
    for (const Segment& s : example.segments) {
        low = glm::min(low, glm::min(s.a, s.b));
        high = glm::max(high, glm::max(s.a, s.b));
    }
    panel.low = low;
    panel.high = high;
    const float gap = std::max(0.16f * (high.y - low.y), 0.2f);
    panel.offset = panel.overlay == InferOverlay::Beside
                       ? glm::vec3(low.x - high.x - gap, 0.0f, 0.0f)
                       : glm::vec3(0.0f);
}

void difference_cell(double example, double regrown, double target) {
    const double d = relative_difference(example, regrown);
    char text[32];
    std::snprintf(text, sizeof text, "%+.1f %%",
                  example == 0.0 ? 0.0 : 100.0 * (regrown - example) / example);
    if (d > target)
        ImGui::TextColored(kWarningColor, "%s", text);
    else
        ImGui::TextUnformatted(text);
}

void figure_row(const char* name, double example, double regrown, const char* format,
                double target) {
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted(name);
    ImGui::TableNextColumn();
    ImGui::Text(format, example);
    ImGui::TableNextColumn();
    ImGui::Text(format, regrown);
    ImGui::TableNextColumn();
    difference_cell(example, regrown, target);
}

void fit_table(const FitReport& r) {
    if (!ImGui::BeginTable("fit", 4, ImGuiTableFlags_SizingStretchProp | ImGuiTableFlags_RowBg))
        return;
    ImGui::TableSetupColumn("");
    ImGui::TableSetupColumn("example");
    ImGui::TableSetupColumn("regrown");
    ImGui::TableSetupColumn("difference");
    ImGui::TableHeadersRow();
    figure_row("segments", double(r.example.segments), double(r.regrown.segments), "%.0f",
               kCountTarget);
    figure_row("total length", r.example.total_length, r.regrown.total_length, "%.2f m",
               kLengthTarget);
    figure_row("height", r.example.height, r.regrown.height, "%.2f m", kHeightTarget);
    figure_row("crown width", r.example.crown_width, r.regrown.crown_width, "%.2f m", kWidthTarget);
    // Per depth: the worst depth in the row, every depth in the tooltip.
    const std::size_t depths = std::max(r.example.per_depth.size(), r.regrown.per_depth.size());
    double worst = 0.0;
    std::size_t worst_depth = 0;
    std::string every = "segments per branch depth, example / regrown:";
    for (std::size_t d = 0; d < depths; ++d) {
        const double a = d < r.example.per_depth.size() ? double(r.example.per_depth[d]) : 0.0;
        const double b = d < r.regrown.per_depth.size() ? double(r.regrown.per_depth[d]) : 0.0;
        if (relative_difference(a, b) > worst) worst = relative_difference(a, b), worst_depth = d;
        char line[64];
        std::snprintf(line, sizeof line, "\n  depth %zu: %.0f / %.0f", d, a, b);
        every += line;
    }
    ImGui::TableNextRow();
    ImGui::TableNextColumn();
    ImGui::TextUnformatted("per depth");
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", every.c_str());
    // The depths each tree has, and the difference at the depth that differs most.
    const double a =
        worst_depth < r.example.per_depth.size() ? double(r.example.per_depth[worst_depth]) : 0.0;
    const double b =
        worst_depth < r.regrown.per_depth.size() ? double(r.regrown.per_depth[worst_depth]) : 0.0;
    ImGui::TableNextColumn();
    ImGui::Text("%zu depths", r.example.per_depth.size());
    ImGui::TableNextColumn();
    ImGui::Text("%zu depths", r.regrown.per_depth.size());
    ImGui::TableNextColumn();
    difference_cell(a, b, kDepthTarget);
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", every.c_str());
    ImGui::EndTable();
    ImGui::Text("Hausdorff distance %.3f m, %.1f %% of the height", r.hausdorff,
                r.example.height > 0.0 ? 100.0 * r.hausdorff / r.example.height : 0.0);
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip(
            "the farthest any point of one skeleton is from the other (both sampled every "
            "1/200 of the height)");
}

void sentences(const char* title, const std::vector<std::string>& lines) {
    if (lines.empty()) return;
    const std::string label = std::string(title) + " (" + std::to_string(lines.size()) + ")";
    if (!ImGui::TreeNode(label.c_str())) return;
    ImGui::PushTextWrapPos(0.0f);
    for (const std::string& line : lines) ImGui::BulletText("%s", line.c_str());
    ImGui::PopTextWrapPos();
    ImGui::TreePop();
}

// Names over both trees in the 3D view (behind the panels, over the tree).
void labels(const InferPanel& panel, const StudioState& state, const PanelLayout& layout) {
    if (!panel.result || panel.overlay == InferOverlay::Off) return;
    const float x0 = layout.left, width = layout.width - layout.left - layout.right;
    const float height = layout.height - layout.bottom;
    if (width <= 1.0f || height <= 1.0f) return;
    const glm::mat4 to_clip =
        projection_matrix(state.camera, width / height) * view_matrix(state.camera);
    ImDrawList* draw = ImGui::GetBackgroundDrawList();
    auto label = [&](glm::vec3 at, const char* text, ImU32 color) {
        const glm::vec4 clip = to_clip * glm::vec4(at, 1.0f);
        if (clip.w <= 0.0f) return;
        const float sx = x0 + (clip.x / clip.w + 1.0f) * 0.5f * width;
        const float sy = (1.0f - clip.y / clip.w) * 0.5f * height;
        const ImVec2 size = ImGui::CalcTextSize(text);
        draw->AddText(ImVec2(sx - 0.5f * size.x, sy + 6.0f), color, text);
    };
    // Under the roots: the window covers the top of the view.
    const glm::vec3 base(0.5f * (panel.low.x + panel.high.x), panel.low.y,
                         0.5f * (panel.low.z + panel.high.z));
    const ImU32 magenta = ImGui::GetColorU32(kExampleText);
    if (panel.overlay == InferOverlay::Beside) {
        label(base + panel.offset, "example", magenta);
        label(base, "regrown", IM_COL32(235, 235, 235, 255));
    } else {
        label(base, "example (lines) over the regrown tree", magenta);
    }
}

}  // namespace

void start_infer_from_tree(InferPanel& panel, const StudioState& state) {
    if (!state.tree) {
        panel.from_tree_pending = true;
        return;
    }
    begin_job(panel);
    ExampleTree example;
    example.skeleton = state.tree->tree.skeleton;
    example.params = state.shown_template.params;
    const std::string name = state.shown_template.name;
    example.format = "the " + name + " on screen";
    if (!example.skeleton.polygons.empty())
        example.notes.push_back(std::to_string(example.skeleton.polygons.size()) +
                                " leaf polygons are not regrown (infer regrows branches)");
    const auto started = std::chrono::steady_clock::now();
    panel.job = std::async(std::launch::async, [example = std::move(example), name,
                                                rules = panel.max_rules, started,
                                                cancel = panel.cancel]() mutable {
        finish_example_tree(example, name);
        const std::string source = example.format;
        return derive(std::move(example), source, name + "-inferred", rules, started, cancel.get());
    });
}

void start_infer_from_file(InferPanel& panel, const std::string& path) {
    begin_job(panel);
    std::optional<UpAxis> up;
    if (panel.up == 1) up = UpAxis::Y;
    if (panel.up == 2) up = UpAxis::Z;
    const auto started = std::chrono::steady_clock::now();
    panel.job = std::async(
        std::launch::async, [path, up, rules = panel.max_rules, started, cancel = panel.cancel] {
            ExampleTree example = read_example_tree(path, up);
            const std::string name = std::filesystem::path(path).stem().string() + "-inferred";
            return derive(std::move(example), path, name, rules, started, cancel.get());
        });
}

bool infer_running(const InferPanel& panel) {
    return panel.job.valid() || panel.from_tree_pending;
}

bool is_skeleton_file(const std::string& path) {
    std::string ext = std::filesystem::path(path).extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return ext == ".json" || ext == ".csv" || ext == ".obj";
}

void update_infer_panel(InferPanel& panel, StudioState& state) {
    if (panel.from_tree_pending && state.tree && !generation_running(state))
        start_infer_from_tree(panel, state);
    if (panel.job.valid() &&
        panel.job.wait_for(std::chrono::seconds(0)) == std::future_status::ready) {
        try {
            panel.result = panel.job.get();
            place_example(panel);
            panel.upload_pending = true;
            // Into the editor: an undoable edit, framed when its tree arrives.
            load_template_into(state, panel.result->inferred.tree, panel.result->inferred.text);
        } catch (const Cancelled&) {
        } catch (const std::exception& e) {
            panel.error = e.what();
        }
        panel.job = {};
    }
    if (!panel.upload_pending) return;
    if (!panel.lines) panel.lines = std::make_unique<LineRenderer>();
    panel.lines->upload(example_lines(panel));
    panel.upload_pending = false;
}

void draw_infer_panel(InferPanel& panel, StudioState& state, const PanelLayout& layout) {
    labels(panel, state, layout);
    // Closed, nothing of it shows over the 3D view: the View menu opens it. Open, it sits at
    // the view's top left corner, under the menu bar.
    panel.covered = 0.0f;
    if (!panel.open) return;
    ImGui::SetNextWindowPos(ImVec2(layout.left + 6.0f, layout.top + 6.0f), ImGuiCond_Always);
    ImGui::SetNextWindowSizeConstraints(ImVec2(kPanelWidth, 0.0f),
                                        ImVec2(kPanelWidth, layout.height * 0.8f));
    const bool shown =
        ImGui::Begin("Rules from a tree", &panel.open,
                     ImGuiWindowFlags_NoMove | ImGuiWindowFlags_AlwaysAutoResize |
                         ImGuiWindowFlags_NoSavedSettings | ImGuiWindowFlags_NoCollapse);
    const float view_height = layout.height - layout.bottom;
    panel.covered = std::clamp(
        (ImGui::GetWindowPos().y + ImGui::GetWindowHeight()) / std::max(view_height, 1.0f), 0.0f,
        0.6f);
    if (!shown || !panel.open) {
        ImGui::End();
        return;
    }
    const bool running = infer_running(panel);
    ImGui::BeginDisabled(running);
    if (ImGui::Button("Derive rules from this tree")) start_infer_from_tree(panel, state);
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(
            "infer a parametric L-system that regrows the skeleton on screen, and load it "
            "into the editor (undo brings this template back)");
    ImGui::SameLine();
    if (ImGui::Button("Open a skeleton...")) {
        panel.dialog.saving = false;
        panel.dialog.what = "skeleton";
        panel.dialog.extensions = {".json", ".csv", ".txt", ".obj"};
        panel.dialog.open_requested = true;
    }
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled))
        ImGui::SetTooltip(
            "a skeleton.json (sylva skeleton), a cylinder table as laser-scan tools write it "
            "(TreeQSM's columns or named ones) or an OBJ of line segments; or drop one on "
            "the window");
    ImGui::EndDisabled();
    ImGui::SetNextItemWidth(120.0f);
    ImGui::Combo("up", &panel.up, "as the file\0y\0z\0");
    if (ImGui::IsItemHovered())
        ImGui::SetTooltip("which axis of a cylinder table or OBJ points up (tables: z, OBJ: y)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(90.0f);
    ImGui::SliderInt("max rules", &panel.max_rules, 1, 30);
    if (running) {
        ImGui::TextDisabled("deriving rules...");
        ImGui::SameLine();
        if (ImGui::SmallButton("cancel")) {
            stop_job(panel);
            panel.from_tree_pending = false;
        }
    }
    if (!panel.error.empty()) {
        ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(panel.error.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
    }
    if (panel.result) {
        const InferOutcome& r = *panel.result;
        ImGui::Separator();
        ImGui::PushTextWrapPos(0.0f);
        ImGui::Text("From %s: %zu segments, inferred in %.0f ms.", r.source.c_str(),
                    r.example.segments.size(), r.infer_ms);
        ImGui::PopTextWrapPos();
        if (r.report.within_rule_limit)
            ImGui::Text("%d rules in %d modules (at most %d)", r.report.rules, r.report.modules,
                        r.report.max_rules);
        else
            ImGui::TextColored(kWarningColor, "%d rules in %d modules: more than %d",
                               r.report.rules, r.report.modules, r.report.max_rules);
        fit_table(r.report);
        sentences("generalised", r.report.generalised);
        sentences("dropped", r.report.dropped);
        int overlay = static_cast<int>(panel.overlay);
        ImGui::TextColored(kExampleText, "example:");
        ImGui::SameLine();
        bool changed = ImGui::RadioButton("beside", &overlay, 0);
        ImGui::SameLine();
        changed |= ImGui::RadioButton("over the tree", &overlay, 1);
        ImGui::SameLine();
        changed |= ImGui::RadioButton("hidden", &overlay, 2);
        ImGui::SameLine();
        if (changed) {
            panel.overlay = static_cast<InferOverlay>(overlay);
            place_example(panel);
            panel.upload_pending = true;
            state.frame_requested = true;
        }
        ImGui::TextDisabled("(?)");
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip(
                "The rules are in the editor: their #define sliders (This tree), Variants and "
                "Export work on them as on any template; undo goes back to the tree before.");
    }
    ImGui::End();
}

void draw_infer_dialog(InferPanel& panel) {
    if (auto path = file_dialog(panel.dialog, {})) start_infer_from_file(panel, *path);
}

void draw_infer_overlay(const InferPanel& panel, const glm::mat4& view,
                        const glm::mat4& projection) {
    if (!panel.lines || !panel.result || panel.overlay == InferOverlay::Off) return;
    panel.lines->draw(view, projection, kExampleColor);
}

std::vector<glm::vec3> infer_overlay_points(const InferPanel& panel) {
    if (!panel.result || panel.overlay == InferOverlay::Off) return {};
    const float tall = panel.high.y - panel.low.y;
    const float above = tall * panel.covered / (1.0f - panel.covered);
    return {panel.low + panel.offset, panel.high + panel.offset,
            glm::vec3(panel.low.x, panel.high.y + above, panel.low.z)};
}

void release_infer_panel(InferPanel& panel) {
    stop_job(panel);
    panel.lines.reset();
}

}  // namespace sylva::studio
