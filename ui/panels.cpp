#include "ui/panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <random>
#include <string>

#include "export/export.h"
#include "tree/growth.h"
#include "tree/template_library.h"
#include "ui/colonization_view.h"

namespace sylva::studio {
namespace {

const ImVec4 kErrorColor(1.0f, 0.45f, 0.4f, 1.0f);
const ImVec4 kWarningColor(1.0f, 0.75f, 0.25f, 1.0f);
// Panels sit at fixed places along the window's edges; their sections carry the titles.
constexpr ImGuiWindowFlags kDocked = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove |
                                     ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                     ImGuiWindowFlags_NoSavedSettings;

// Slider ends for parameters whose valid range is far wider than a useful drag; typed
// values (Ctrl+click) may still go to the full range.
double slider_max(const ParamInfo& info) {
    const std::string key(info.key);
    if (key == "trunk_resolution" || key == "crown_resolution") return 300;
    if (key == "triangle_budget") return 5000;
    if (key == "leaf_density") return 500;
    if (key == "branch_length" || key == "branch_width" || key == "sphere_diameter") return 3;
    if (key == "crown_offset") return 2;
    return info.max;
}
double slider_min(const ParamInfo& info) {
    return std::string(info.key) == "crown_offset" ? -2 : info.min;
}

void wrapped_text(const std::string& text, bool failed) {
    if (text.empty()) return;
    if (failed) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    if (failed) ImGui::PopStyleColor();
}

void tooltip(const char* text) {
    if (ImGui::IsItemHovered()) ImGui::SetTooltip("%s", text);
}

void section(const char* title) {
    ImGui::Spacing();
    ImGui::TextDisabled("%s", title);
    ImGui::Separator();
}

void actions_row(StudioState& state) {
    ImGui::BeginDisabled(state.live);
    if (ImGui::Button("Generate")) start_generation(state);
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::Checkbox("live", &state.live);
    tooltip("regenerate on every change");
    ImGui::SameLine();
    ImGui::BeginDisabled(state.undo.empty() && same_template(state.tree_template, state.committed));
    if (ImGui::Button("undo")) undo(state);
    tooltip("Ctrl+Z");
    ImGui::EndDisabled();
    ImGui::SameLine();
    ImGui::BeginDisabled(state.redo.empty());
    if (ImGui::Button("redo")) redo(state);
    tooltip("Ctrl+Y or Ctrl+Shift+Z");
    ImGui::EndDisabled();
}

// The growth method that makes the skeleton; the rest of the pipeline is shared.
void growth_combo(StudioState& state) {
    const std::string& current = state.tree_template.growth;
    if (ImGui::BeginCombo("growth", current.c_str())) {
        for (const GrowthMethod* method : growth_methods()) {
            const std::string name(method->name);
            if (ImGui::Selectable(name.c_str(), name == current)) set_growth_method(state, name);
            tooltip(std::string(method->description).c_str());
        }
        ImGui::EndCombo();
    }
    if (const GrowthMethod* method = find_growth_method(current))
        tooltip(std::string(method->description).c_str());
}

void template_section(StudioState& state) {
    section("Template");
    if (ImGui::BeginCombo("template", state.tree_template.name.c_str(),
                          ImGuiComboFlags_HeightLargest)) {
        for (const TreeTemplate* t : builtin_templates()) {
            if (ImGui::Selectable(t->name.c_str(), t->name == state.tree_template.name))
                load_template_into(state, *t);
            tooltip(t->description.c_str());
        }
        ImGui::EndCombo();
    }
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextDisabled("%s", state.tree_template.description.c_str());
    ImGui::PopTextWrapPos();
    growth_combo(state);
    const float buttons = ImGui::CalcTextSize("OpenSave as").x +
                          4.0f * ImGui::GetStyle().FramePadding.x +
                          2.0f * ImGui::GetStyle().ItemSpacing.x;
    ImGui::SetNextItemWidth(ImGui::GetContentRegionAvail().x - buttons);
    ImGui::InputText("##file", &state.template_path);
    tooltip("a template file (.toml), or a grammar file (.lsys, .txt: the rules alone)");
    ImGui::SameLine();
    if (ImGui::Button("Open")) open_template_file(state);
    tooltip("open the template or grammar file named on the left");
    ImGui::SameLine();
    if (ImGui::Button("Save as")) save_template_to_file(state);
    tooltip("the rules, parameters and colours as a template file (.toml)");
    wrapped_text(state.file_message, state.file_failed);
}

template <class Enum>
void enum_combo(const char* label, Enum& value, std::initializer_list<const char*> names,
                const char* help) {
    int index = static_cast<int>(value);
    if (ImGui::BeginCombo(label, *(names.begin() + index))) {
        int i = 0;
        for (const char* name : names) {
            if (ImGui::Selectable(name, i == index)) value = static_cast<Enum>(i);
            ++i;
        }
        ImGui::EndCombo();
    }
    tooltip(help);
}

// One parameter's widget: a list for choices, a checkbox for 0/1, else a slider.
bool parameter_widget(const ParamInfo& info, double& value) {
    const std::string key(info.key);
    if (!info.choices.empty()) {
        int index = static_cast<int>(value);
        bool changed = false;
        if (ImGui::BeginCombo(key.c_str(),
                              std::string(info.choices[static_cast<size_t>(index)]).c_str())) {
            for (size_t i = 0; i < info.choices.size(); ++i)
                if (ImGui::Selectable(std::string(info.choices[i]).c_str(),
                                      static_cast<int>(i) == index)) {
                    value = static_cast<double>(i);
                    changed = true;
                }
            ImGui::EndCombo();
        }
        return changed;
    }
    if (info.integer && info.min == 0 && info.max == 1) {
        bool on = value != 0.0;
        bool changed = ImGui::Checkbox(key.c_str(), &on);
        value = on ? 1.0 : 0.0;
        return changed;
    }
    if (info.integer) {
        int v = static_cast<int>(value);
        bool changed = ImGui::SliderInt(key.c_str(), &v, static_cast<int>(slider_min(info)),
                                        static_cast<int>(slider_max(info)));
        value = v;
        return changed;
    }
    float v = static_cast<float>(value);
    bool changed = ImGui::SliderFloat(key.c_str(), &v, static_cast<float>(slider_min(info)),
                                      static_cast<float>(slider_max(info)), "%.3f");
    value = v;
    return changed;
}

// One parameter's widget with its help and range as a tooltip.
void parameter_row(TreeParams& params, const ParamInfo& info) {
    double value = *get_param(params, info.key);
    const bool changed = parameter_widget(info, value);
    if (ImGui::IsItemHovered()) {
        if (info.choices.empty())
            ImGui::SetTooltip("%s\nrange %g to %g (Ctrl+click to type)",
                              std::string(info.help).c_str(), info.min, info.max);
        else
            ImGui::SetTooltip("%s", std::string(info.help).c_str());
    }
    if (changed) set_param(params, info.key, std::clamp(value, info.min, info.max));
}

// The age slider and the noise controls (issue 14), shown above the other parameters.
bool is_variation_key(std::string_view key) {
    for (std::string_view k : {"age", "bend", "bend_frequency", "jitter", "width_variation",
                               "tropism_variation", "color_variation"})
        if (key == k) return true;
    return false;
}

void parameter_section(StudioState& state) {
    section("Parameters");
    TreeTemplate& t = state.tree_template;
    enum_combo("turtle", t.mode, {"abop", "lptg"},
               "abop: ABOP's H, L, U turtle; lptg: seed 001's elevation / azimuth turtle");
    enum_combo("widths", t.width_model, {"explicit", "taper", "pipe"},
               "explicit: ! sets widths; taper: trunk_taper / branch_taper per segment; "
               "pipe: Murray's pipe model from tip_width");
    TreeParams& params = t.params;
    const std::uint64_t step = 1;
    ImGui::InputScalar("seed", ImGuiDataType_U64, &params.seed, &step);
    tooltip("the random choices of stochastic rules and rand(); same seed, same tree");
    ImGui::SameLine();
    if (ImGui::Button("new")) params.seed = std::random_device{}() % 1000000;
    tooltip("a new random seed");
    // Issue 14: the age slider and the noise controls first, the other parameters below.
    for (const ParamInfo& info : param_infos())
        if (is_variation_key(info.key)) parameter_row(params, info);
    ImGui::Separator();
    for (const ParamInfo& info : param_infos())
        if (!is_variation_key(info.key)) parameter_row(params, info);
}

// A generation held back by its estimated cost, and the button that runs it anyway.
void cost_notice(StudioState& state) {
    if (state.cost_warning.empty()) return;
    wrapped_text(state.cost_warning, true);
    if (ImGui::Button("run anyway")) {
        state.run_costly = true;
        start_generation(state);
    }
}

void rules_section(StudioState& state, RulesEditorState& editor, float height) {
    section("Rules");
    if (grows_by_colonization(state.tree_template)) {
        // No grammar to edit: the editor would only invite edits that change nothing.
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled(
            "Space colonization grows without rules: the envelope, the attraction points and "
            "the colonization parameters on the left shape the tree. Switch growth to "
            "\"lsystem\" to edit a grammar.");
        ImGui::PopTextWrapPos();
        wrapped_text(state.error, true);
        if (!state.error.empty())
            ImGui::TextDisabled("(the tree on screen is the last one that worked)");
        cost_notice(state);
        return;
    }
    const TextMark mark{state.error_line, state.error_column};
    rules_editor("rules", state.tree_template.grammar, mark, editor, height);
    if (state.error_line > 0) {
        ImGui::TextColored(kErrorColor, "line %d, column %d", state.error_line, state.error_column);
        ImGui::SameLine();
        if (ImGui::SmallButton("show")) reveal(editor, mark);
        tooltip("put the cursor there");
    }
    wrapped_text(state.error, true);
    if (!state.error.empty())
        ImGui::TextDisabled("(the tree on screen is the last one that worked)");
    cost_notice(state);
}

// One level's totals against its budget; over budget in the warning colour, with the
// reducer's note (why the budget was missed, what was backed off) as the tooltip. Wrapped in
// a panel, one line in the status bar.
void totals_line(const std::string& label, const GameMeshTotals& totals, bool wrap) {
    const std::string text =
        label + totals_text(totals) + (totals.over_budget ? " over budget" : "");
    if (totals.over_budget) ImGui::PushStyleColor(ImGuiCol_Text, kWarningColor);
    if (wrap) ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(text.c_str());
    if (wrap) ImGui::PopTextWrapPos();
    if (totals.over_budget) ImGui::PopStyleColor();
    if (!totals.note.empty()) tooltip(totals.note.c_str());
}

// Space colonization's overlays: the envelope, the attraction points, and growth replayed
// up to a step (`last`: the tree's final one).
void colonization_view_row(ViewToggles& v, int last) {
    ImGui::Checkbox("envelope", &v.envelope);
    tooltip("the envelope the attraction points fill, as a wire cage");
    ImGui::SameLine();
    ImGui::Checkbox("points", &v.points);
    tooltip("the attraction points the growth started from (the template's seed)");
    ImGui::SameLine();
    ImGui::Checkbox("replay", &v.replay);
    tooltip("the skeleton as growth left it after the step on the right (no meshes)");
    ImGui::SameLine();
    ImGui::BeginDisabled(!v.replay);
    // Off, the slider rests at the whole tree, so switching replay on changes nothing yet.
    v.replay_iteration = v.replay ? std::clamp(v.replay_iteration, 0, last) : last;
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::SliderInt("##replay", &v.replay_iteration, 0, last, "step %d");
    tooltip("growth step: 0 is the trunk, the last one the whole tree");
    ImGui::EndDisabled();
}

void view_section(StudioState& state) {
    section("View");
    ViewToggles& v = state.view;
    ImGui::Checkbox("skeleton", &v.skeleton);
    tooltip("the turtle's segments as lines");
    ImGui::SameLine();
    ImGui::Checkbox("trunk", &v.trunk);
    ImGui::SameLine();
    ImGui::Checkbox("crown", &v.crown);
    ImGui::SameLine();
    ImGui::Checkbox("leaves", &v.leaves);
    ImGui::SameLine();
    ImGui::Checkbox("wireframe", &v.wireframe);
    ImGui::Checkbox("low poly", &v.low_poly);
    tooltip(
        "the game mesh: trunk and crown reduced to triangle_budget, leaves thinned to their "
        "share, exactly what an export writes");
    ImGui::SameLine();
    ImGui::BeginDisabled(!v.low_poly);
    ImGui::SetNextItemWidth(90.0f);
    ImGui::SliderInt("##lod", &v.lod_level, 0, kLodLevels - 1, "LOD %d");
    tooltip(
        "the level of the LOD chain an export with \"LOD chain\" writes: budget, 1/2, 1/4, "
        "1/8 (keys 0-3)");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("frame tree (F)")) state.frame_requested = true;
    if (state.tree && grows_by_colonization(state.shown_template))
        colonization_view_row(v, last_iteration(state.tree->tree.skeleton));
    ImGui::TextDisabled("left drag orbit, right / middle drag pan, wheel zoom");
}

void export_section(StudioState& state) {
    section("Export");
    ExportSettings& e = state.export_settings;
    ImGui::InputText("path", &e.path);
    tooltip("the extension picks the format: .obj (+ .mtl), .glb or .ply");
    const ExportFormat* format = format_from_extension(e.path);
    if (ImGui::BeginCombo("format", format ? std::string(format->name).c_str() : "(extension?)")) {
        for (const ExportFormat* f : export_formats())
            if (ImGui::Selectable(std::string(f->name).c_str(), format == f))
                e.path = std::filesystem::path(e.path).replace_extension(f->extension).string();
        ImGui::EndCombo();
    }
    int& budget = state.tree_template.params.triangle_budget;
    if (ImGui::InputInt("budget", &budget, 100, 1000)) budget = std::max(budget, 0);
    tooltip(
        "trunk + crown triangles after reduction (0 keeps every triangle); the "
        "template's triangle_budget");
    ImGui::Checkbox("LOD chain", &e.lod);
    tooltip("four levels: budget, 1/2, 1/4, 1/8 (one .glb, or a file per level)");
    ImGui::SameLine();
    ImGui::BeginDisabled(state.export_job.valid() || !state.tree);
    if (ImGui::Button("Export (Ctrl+E)")) start_export(state);
    ImGui::EndDisabled();
    // What the export writes, level by level, when the view has it at this budget.
    const GeneratedTree* shown = state.tree.get();
    if (shown && shown->reduced() && static_cast<int>(shown->budget) == budget) {
        const int levels = e.lod ? static_cast<int>(shown->finished.levels.size()) : 1;
        for (int level = 0; level < levels; ++level) {
            const std::string label = e.lod ? "LOD" + std::to_string(level) + ": " : "writes ";
            totals_line(label, game_mesh_totals(*shown, level), true);
        }
    } else {
        ImGui::TextDisabled("(switch low poly on to see the game mesh's triangles)");
    }
    wrapped_text(state.export_message, state.export_failed);
}

const char* stage_name(int stage) {
    switch (stage) {
        case JobProgress::Meshing:
            return "meshing";
        case JobProgress::Reducing:
            return "reducing";
        default:
            return "growing";
    }
}

}  // namespace

PanelLayout panel_layout(float width, float height) {
    PanelLayout layout;
    layout.width = width;
    layout.height = height;
    layout.left = std::min(370.0f, 0.3f * width);
    layout.right = std::min(430.0f, 0.34f * width);
    layout.bottom = ImGui::GetFrameHeightWithSpacing() + 8.0f;
    return layout;
}

void draw_tree_panel(StudioState& state, const PanelLayout& layout) {
    ImGui::SetNextWindowPos(ImVec2(0.0f, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(layout.left, layout.height - layout.bottom));
    ImGui::Begin("Tree", nullptr, kDocked);
    ImGui::PushItemWidth(-130.0f);
    actions_row(state);
    template_section(state);
    parameter_section(state);
    ImGui::PopItemWidth();
    ImGui::End();
}

void draw_rules_panel(StudioState& state, RulesEditorState& editor, const PanelLayout& layout) {
    ImGui::SetNextWindowPos(ImVec2(layout.width - layout.right, 0.0f));
    ImGui::SetNextWindowSize(ImVec2(layout.right, layout.height - layout.bottom));
    ImGui::Begin("Rules and export", nullptr, kDocked);
    ImGui::PushItemWidth(-80.0f);
    // The editor takes what the other sections leave.
    const float below = 18.0f * ImGui::GetFrameHeightWithSpacing();
    rules_section(state, editor, std::max(ImGui::GetContentRegionAvail().y - below, 120.0f));
    view_section(state);
    export_section(state);
    ImGui::PopItemWidth();
    ImGui::End();
}

void draw_status_bar(const StudioState& state, const PanelLayout& layout, float fps) {
    ImGui::SetNextWindowPos(ImVec2(0.0f, layout.height - layout.bottom));
    ImGui::SetNextWindowSize(ImVec2(layout.width, layout.bottom));
    ImGui::Begin("status", nullptr,
                 ImGuiWindowFlags_NoDecoration | kDocked | ImGuiWindowFlags_NoFocusOnAppearing);
    if (state.job) {
        const JobProgress& p = *state.job->progress;
        const int stage = p.stage.load();
        char label[32];
        std::snprintf(label, sizeof label, "%s %.0f%%", stage_name(stage),
                      100.0f * p.fraction.load());
        ImGui::ProgressBar(stage == JobProgress::Growing ? 0.0f : p.fraction.load(),
                           ImVec2(150.0f, 0.0f), label);
        ImGui::SameLine();
    } else if (generation_running(state)) {
        ImGui::ProgressBar(0.0f, ImVec2(150.0f, 0.0f), "waiting");
        ImGui::SameLine();
    }
    if (state.tree) {
        const GeneratedTree& shown = *state.tree;
        const Tree& t = shown.tree;
        ImGui::Text("%s  ", state.shown_template.name.c_str());
        ImGui::SameLine(0.0f, 0.0f);
        if (shown.reduced()) {
            const GameMeshTotals totals = game_mesh_totals(shown, state.view.lod_level);
            const std::string label = "game mesh LOD" + std::to_string(totals.level) + ": ";
            totals_line(label, totals, false);
        } else {
            const ShownParts parts = shown_parts(shown, 0);
            ImGui::Text("trunk %zu  crown %zu  leaves %zu triangles%s",
                        parts.trunk.triangles.size(), parts.crown.triangles.size(),
                        parts.leaves.triangles.size(),
                        shown.draft ? " (draft: the game mesh follows on release)" : "");
        }
        // The time to the tree on screen; each stage's in the tooltip (the line is full).
        ImGui::SameLine(0.0f, 0.0f);
        if (shown.reduced())
            ImGui::Text("   |   reduce %.0f ms, %.0f ms in all", shown.reduce_ms,
                        state.last_wall_ms);
        else
            ImGui::Text("   |   %.0f ms in all", state.last_wall_ms);
        if (ImGui::IsItemHovered()) {
            std::string stages;
            for (const StageTime& stage : t.times) {
                char line[96];
                std::snprintf(line, sizeof line, "%s %.1f ms\n", stage.name.c_str(), stage.ms);
                stages += line;
            }
            stages +=
                "in all: from the job's start (an edit, a slider let go) to the tree on screen";
            ImGui::SetTooltip("%s", stages.c_str());
        }
    } else if (!generation_running(state)) {
        ImGui::TextUnformatted("no tree yet");
    }
    if (!state.error.empty()) {
        ImGui::SameLine();
        ImGui::TextColored(kErrorColor, "  the last edit failed (see Rules)");
    }
    if (fps >= 0.0f) {
        char rate[32];
        std::snprintf(rate, sizeof rate, "%.0f fps", fps);
        const float text_end = ImGui::GetItemRectMax().x - ImGui::GetWindowPos().x;
        ImGui::SameLine(
            std::max(text_end + 20.0f, layout.width - ImGui::CalcTextSize(rate).x - 16.0f));
        ImGui::TextDisabled("%s", rate);
    }
    ImGui::End();
}

}  // namespace sylva::studio
