#include "ui/panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <random>
#include <string>

#include "core/name_list.h"
#include "export/export.h"
#include "tree/cost.h"
#include "tree/growth.h"
#include "tree/parameters.h"
#include "tree/template_library.h"
#include "ui/file_dialog.h"
#include "ui/forest_preview.h"
#include "ui/impostor_view.h"
#include "ui/rules_warnings.h"
#include "ui/state/colonization_view.h"
#include "ui/state/template_controls.h"

namespace sylva::studio {
namespace {

const ImVec4 kErrorColor(1.0f, 0.45f, 0.4f, 1.0f);
const ImVec4 kWarningColor(1.0f, 0.75f, 0.25f, 1.0f);
// Panels sit at fixed places along the window's edges; their sections carry the titles.
constexpr ImGuiWindowFlags kDocked = ImGuiWindowFlags_NoTitleBar | ImGuiWindowFlags_NoMove |
                                     ImGuiWindowFlags_NoResize | ImGuiWindowFlags_NoCollapse |
                                     ImGuiWindowFlags_NoSavedSettings;

void wrapped_text(const std::string& text, bool failed) {
    if (text.empty()) return;
    if (failed) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::PushTextWrapPos(0.0f);
    ImGui::TextUnformatted(text.c_str());
    ImGui::PopTextWrapPos();
    if (failed) ImGui::PopStyleColor();
}

void tooltip(const char* text) {
    if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) ImGui::SetTooltip("%s", text);
}

// A message on one line that never grows the panel: cut at the panel's edge, the whole of it
// in the tooltip. The line is kept when there is no message, so nothing below it jumps.
void message_line(const std::string& text, bool failed) {
    if (failed) ImGui::PushStyleColor(ImGuiCol_Text, kErrorColor);
    ImGui::TextUnformatted(text.empty() ? " " : text.c_str());
    if (failed) ImGui::PopStyleColor();
    if (!text.empty()) tooltip(text.c_str());
}

// The studio's own file dialog (ui/file_dialog.h), shared by Open and Save as.
FileDialogState g_file_dialog;

void section(const char* title) {
    ImGui::Spacing();
    ImGui::TextDisabled("%s", title);
    ImGui::Separator();
}

// What the edited tree will cost, before anything runs: memory and time in one line (it never
// pushes the panel), the whole estimate in the tooltip. The grammar's segment count is only a
// lower bound (the willow's: 1 of 849) and unknown for space colonization, so the line leaves
// it to the tooltip.
void estimate_line(const StudioState& state) {
    const Cost& cost = state.estimate;
    const bool over = !state.cost_warning.empty();
    char line[128];
    std::snprintf(line, sizeof line, "estimate: %.2g GB, %.2g s or more%s", cost.bytes / 1e9,
                  cost.seconds, over ? " - asks first" : "");
    ImGui::PushStyleColor(ImGuiCol_Text,
                          over ? kWarningColor : ImGui::GetStyleColorVec4(ImGuiCol_TextDisabled));
    ImGui::TextUnformatted(line);
    ImGui::PopStyleColor();
    const std::string text =
        "estimated before the job starts (tree/cost.h), a lower bound: " + cost_text(cost) +
        "\n(the derived word's modules, the skeleton's segments, the meshing grids' cells, "
        "peak memory and time on two cores)";
    tooltip(text.c_str());
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
    ImGui::SameLine();
    ImGui::BeginDisabled(same_template(state.tree_template, state.original));
    if (ImGui::Button("reset")) reset_to_template(state);
    tooltip("back to the template as it was opened or picked (undo brings the edits back)");
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("?")) state.show_shortcuts = true;
    tooltip("keyboard shortcuts (F1)");
}

// Whether the template's growth method reads its grammar (the rules editor and the #define
// sliders act on it).
bool reads_grammar(const TreeTemplate& t) {
    const GrowthMethod* method = find_growth_method(t.growth);
    return !method || method->uses_grammar;
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
    // The unsaved-changes mark (the window's title carries it too, main).
    section(unsaved_changes(state) ? "Template  * unsaved changes" : "Template");
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
    if (ImGui::Button("Open...")) {
        g_file_dialog.saving = false;
        g_file_dialog.open_requested = true;
    }
    tooltip(
        "open a template file (.toml) or a grammar file (.lsys, .txt: the rules alone); "
        "Ctrl+O, or drop a file on the window");
    ImGui::SameLine();
    if (ImGui::Button("Save")) {
        if (std::filesystem::exists(state.template_path)) {
            save_template_to_file(state);
        } else {
            g_file_dialog.saving = true;
            g_file_dialog.open_requested = true;
        }
    }
    tooltip(
        ("save to " + state.template_path + " (Ctrl+S); comments of the file are kept").c_str());
    ImGui::SameLine();
    if (ImGui::Button("Save as...")) {
        g_file_dialog.saving = true;
        g_file_dialog.name = std::filesystem::path(state.template_path).filename().string();
        g_file_dialog.open_requested = true;
    }
    tooltip("the rules, parameters and colours as a template file (.toml)");
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    if (ImGui::BeginCombo("##recent", "recent", ImGuiComboFlags_HeightLarge)) {
        if (state.recent_files.empty()) ImGui::TextDisabled("(no files opened or saved yet)");
        for (const std::string& file : state.recent_files)
            if (ImGui::Selectable(file.c_str())) {
                state.template_path = file;
                open_template_file(state);
            }
        ImGui::EndCombo();
    }
    message_line(state.file_message, state.file_failed);
}

// The template's own knobs: its #define constants that carry a range
// (ui/state/template_controls.h), its colours, and the way back to it as it was opened.
void this_tree_section(StudioState& state) {
    section("This tree");
    TreeTemplate& t = state.tree_template;
    const std::vector<GrammarConstant> constants = grammar_constants(t.grammar);
    for (const GrammarConstant& c : constants) {
        bool changed = false;
        double value = c.value;
        if (c.integer) {
            int v = static_cast<int>(c.value);
            changed = ImGui::SliderInt(c.name.c_str(), &v, static_cast<int>(c.min),
                                       static_cast<int>(c.max));
            value = v;
        } else {
            float v = static_cast<float>(c.value);
            changed = ImGui::SliderFloat(c.name.c_str(), &v, static_cast<float>(c.min),
                                         static_cast<float>(c.max), "%.4g");
            value = round_for_range(v, c.min, c.max);
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s\n#define %s, line %d of the rules; range %g to %g",
                              c.help.empty() ? c.name.c_str() : c.help.c_str(), c.name.c_str(),
                              c.line, c.min, c.max);
        if (changed && value != c.value) set_grammar_constant(t.grammar, c.name, value);
    }
    if (constants.empty() && reads_grammar(t)) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled(
            "No constants with a range in the rules. A #define with \"# [min, max] help\" "
            "after its value becomes a slider here, e.g.  #define a 34  # [10, 60] fork angle");
        ImGui::PopTextWrapPos();
    }
    PartColors colors = t.colors;
    const ImGuiColorEditFlags flags = ImGuiColorEditFlags_Float;
    bool recolor = ImGui::ColorEdit3("bark", &colors.trunk.x, flags);
    tooltip("the trunk and branches' colour (linear RGB)");
    recolor |= ImGui::ColorEdit3("crown", &colors.crown.x, flags);
    tooltip("the crown mesh's colour");
    recolor |= ImGui::ColorEdit3("leaves", &colors.leaves.x, flags);
    tooltip("the leaf cards' colour");
    if (recolor) set_colors(state, colors);
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
bool parameter_widget(const ParamInfo& info, double& value, const SliderRange& range) {
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
    if (info.flag) {
        bool on = value != 0.0;
        bool changed = ImGui::Checkbox(key.c_str(), &on);
        value = on ? 1.0 : 0.0;
        return changed;
    }
    if (info.integer) {
        int v = static_cast<int>(value);
        bool changed = ImGui::SliderInt(key.c_str(), &v, static_cast<int>(range.min),
                                        static_cast<int>(range.max));
        value = v;
        return changed;
    }
    float v = static_cast<float>(value);
    bool changed = ImGui::SliderFloat(key.c_str(), &v, static_cast<float>(range.min),
                                      static_cast<float>(range.max), "%.3f");
    value = v;
    return changed;
}

void parameter_section(StudioState& state) {
    section("Parameters");
    TreeTemplate& t = state.tree_template;
    enum_combo("turtle", t.mode, {"abop", "lptg"},
               "abop: ABOP's H, L, U turtle; lptg: Heuer's elevation / azimuth turtle");
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
    // Parameters this tree's rules and growth never read are shown, greyed, with the reason.
    // (crown_merge and drop_hidden act in the full-detail view too: it is meshed for the
    // template's budget, as the game mesh is.) The rows come by group from the registry.
    std::optional<ParamGroup> group;
    for (const ParameterRow& row : parameter_rows(t)) {
        const ParamInfo& info = *row.info;
        if (group && *group != info.group) ImGui::Separator();
        group = info.group;
        double value = *get_param(params, info.key);
        const bool disabled = !row.unread.empty();
        ImGui::BeginDisabled(disabled);
        const double own = *get_param(state.original.params, info.key);
        const SliderRange range = slider_range(info.key, std::max(own, value));
        const bool changed = parameter_widget(info, value, range);
        ImGui::EndDisabled();
        if (ImGui::IsItemHovered(ImGuiHoveredFlags_AllowWhenDisabled)) {
            std::string help(info.help);
            help += budget_resolution_note(params, info.key);
            if (disabled)
                ImGui::SetTooltip("%s\nNot read by this tree: %s", help.c_str(),
                                  row.unread.c_str());
            else if (info.choices.empty())
                ImGui::SetTooltip("%s\nrange %g to %g (Ctrl+click to type)", help.c_str(), info.min,
                                  info.max);
            else
                ImGui::SetTooltip("%s", help.c_str());
        }
        if (changed) set_param(params, info.key, std::clamp(value, info.min, info.max));
    }
}

// The confirmation an expensive edit asks for before it runs (generations 12 on the oak),
// opened once per warning, at the top of the ID stack where draw_dialogs begins it.
constexpr const char* kCostDialog = "Expensive tree";

void cost_confirmation(StudioState& state) {
    static std::string asked;  // the warning already asked about
    if (state.cost_warning.empty()) {
        asked.clear();
        return;
    }
    if (asked != state.cost_warning) {
        asked = state.cost_warning;
        ImGui::OpenPopup(kCostDialog);
    }
    if (!ImGui::BeginPopupModal(
            kCostDialog, nullptr,
            ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings))
        return;
    ImGui::PushTextWrapPos(420.0f);
    ImGui::TextUnformatted(state.cost_warning.c_str());
    ImGui::TextDisabled(
        "The tree on screen stays until you decide. A running job can be "
        "cancelled from the status bar at any time.");
    ImGui::PopTextWrapPos();
    if (ImGui::Button("Run anyway")) {
        state.run_costly = true;
        start_generation(state);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Undo the edit")) {
        undo(state);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Not now")) ImGui::CloseCurrentPopup();
    tooltip("keep the edit without running it; \"run anyway\" stays under the rules");
    ImGui::EndPopup();
}

// Every key the studio answers to.
void shortcuts_window(StudioState& state) {
    if (!state.show_shortcuts) return;
    ImGui::SetNextWindowPos(ImGui::GetMainViewport()->GetCenter(), ImGuiCond_Appearing,
                            ImVec2(0.5f, 0.5f));
    if (ImGui::Begin("Shortcuts", &state.show_shortcuts,
                     ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings)) {
        static constexpr const char* kKeys[][2] = {
            {"Ctrl+Z", "undo"},
            {"Ctrl+Y, Ctrl+Shift+Z", "redo"},
            {"Ctrl+O", "open a template"},
            {"Ctrl+S", "save the template"},
            {"Ctrl+E", "export"},
            {"F", "frame the tree"},
            {"0 - 3", "show that LOD of the game mesh"},
            {"P", "screenshot of the 3D view"},
            {"T", "turntable on / off"},
            {"Esc", "cancel the running generation"},
            {"F1", "this list"},
            {"left drag", "orbit"},
            {"right / middle drag", "pan"},
            {"wheel", "zoom"},
            {"Ctrl+click a slider", "type a value"},
            {"drop a .toml", "open it"},
        };
        if (ImGui::BeginTable("keys", 2)) {
            for (const auto& row : kKeys) {
                ImGui::TableNextRow();
                ImGui::TableNextColumn();
                ImGui::TextUnformatted(row[0]);
                ImGui::TableNextColumn();
                ImGui::TextDisabled("%s", row[1]);
            }
            ImGui::EndTable();
        }
    }
    ImGui::End();
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
    if (!reads_grammar(state.tree_template)) {
        // No grammar to edit: the editor would only invite edits that change nothing.
        ImGui::PushTextWrapPos(0.0f);
        const std::string text = "Growth method " + state.tree_template.growth +
                                 " grows without rules: its parameters on the left shape the "
                                 "tree. Switch growth to \"lsystem\" to edit a grammar.";
        ImGui::TextDisabled("%s", text.c_str());
        ImGui::PopTextWrapPos();
        wrapped_text(state.error, true);
        if (!state.error.empty())
            ImGui::TextDisabled("(the tree on screen is the last one that worked)");
        cost_notice(state);
        return;
    }
    const TextMark mark{state.error_line, state.error_column};
    rules_editor("rules", state.tree_template.grammar, mark, editor, height);
    rules_warnings(state.tree_template, editor);
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
    ImGui::Checkbox("wind", &v.wind);
    tooltip("sway the tree with the wind data an export writes (docs/wind.glsl)");
    ImGui::SameLine();
    ImGui::Checkbox("low poly", &v.low_poly);
    tooltip(
        "the game mesh: trunk and crown reduced to triangle_budget, leaves thinned to their "
        "share, exactly what an export writes");
    ImGui::SameLine();
    ImGui::BeginDisabled(!v.low_poly);
    ImGui::SetNextItemWidth(90.0f);
    ImGui::SliderInt("##lod", &v.lod_level, 0, kImpostorSlot,
                     v.lod_level == kImpostorSlot ? "impostor" : "LOD %d");
    tooltip(
        "the level of the LOD chain an export with \"LOD chain\" writes: budget, 1/2, 1/4, "
        "1/8 (keys 0-3), then the octahedral impostor of export --impostor (key 4)");
    ImGui::EndDisabled();
    if (impostor_slot_shown(v)) {  // ui/impostor_view.h
        ImGui::SameLine();
        ImGui::Checkbox("tree", &v.impostor_tree);
        tooltip("show the tree the impostor stands for (LOD 0) in its place, to compare");
    }
    ImGui::SameLine();
    if (ImGui::Button("frame tree (F)")) state.frame_requested = true;
    ImGui::Checkbox("scale figure", &v.scale_figure);
    tooltip("a 1.8 m person beside the trunk");
    ImGui::SameLine();
    ImGui::Checkbox("turntable", &v.turntable);
    tooltip("the camera circles the tree (T)");
    ImGui::SameLine();
    if (ImGui::Button("screenshot (P)")) state.screenshot_requested = true;
    tooltip("saves the 3D view as a PNG in the working folder");
    message_line(state.screenshot_message, false);
    forest_preview_row(state);  // ui/forest_preview.h
#ifdef SYLVA_HAS_LAYOUT
    if (ImGui::Button("2D layouts...")) state.layout_requested = true;  // ui/layout_panel.h
    tooltip("ground plans grown from one drawn example, to plant as a forest");
#endif
    if (state.tree && grows_by_colonization(state.shown_template))
        colonization_view_row(v, last_iteration(state.tree->tree.skeleton));
    ImGui::TextDisabled("left drag orbit, right / middle drag pan, wheel zoom");
}

// The engine whose conventions the export follows (docs/engines.md, "Engine profiles").
void profile_combo(EngineProfile& profile) {
    ImGui::SetNextItemWidth(110.0f);
    if (ImGui::BeginCombo("profile", std::string(profile_info(profile).name).c_str())) {
        for (const ProfileInfo& p : engine_profiles()) {
            if (ImGui::Selectable(std::string(p.name).c_str(), p.profile == profile))
                profile = p.profile;
            tooltip(std::string(p.summary).c_str());
        }
        ImGui::EndCombo();
    }
    tooltip(std::string(profile_info(profile).summary).c_str());
}

void export_section(StudioState& state) {
    section("Export");
    ExportSettings& e = state.export_settings;
    ImGui::InputText("path", &e.path);
    tooltip(("the extension picks the format: " + name_list(format_extensions())).c_str());
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
    profile_combo(e.profile);
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

void request_file_dialog(bool saving) {
    g_file_dialog.saving = saving;
    g_file_dialog.open_requested = true;
}

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
    estimate_line(state);
    template_section(state);
    this_tree_section(state);
    parameter_section(state);
    if (!state.crown_notice.empty()) {
        ImGui::Spacing();
        ImGui::PushStyleColor(ImGuiCol_Text, kWarningColor);
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextUnformatted(state.crown_notice.c_str());
        ImGui::PopTextWrapPos();
        ImGui::PopStyleColor();
    }
    ImGui::PopItemWidth();
    ImGui::End();
    shortcuts_window(state);
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

void draw_status_bar(StudioState& state, const PanelLayout& layout, float fps) {
    ImGui::SetNextWindowPos(ImVec2(0.0f, layout.height - layout.bottom));
    ImGui::SetNextWindowSize(ImVec2(layout.width, layout.bottom));
    ImGui::Begin("status", nullptr,
                 ImGuiWindowFlags_NoDecoration | kDocked | ImGuiWindowFlags_NoFocusOnAppearing);
    if (state.job) {
        const JobProgress& p = *state.job->progress;
        const int stage = p.stage.load();
        const float fraction = p.fraction.load();
        const double elapsed =
            std::chrono::duration<double>(std::chrono::steady_clock::now() - state.job->started)
                .count();
        // Time left: from the stage's own fraction once it has one, else from the estimate
        // made before the job started.
        double left = std::max(state.job_estimate.seconds - elapsed, 0.0);
        float shown = static_cast<float>(
            std::min(elapsed / std::max(state.job_estimate.seconds, 1e-3), 0.95));
        if (fraction > 0.02f) {
            left = elapsed / fraction * (1.0 - fraction);
            shown = fraction;
        }
        char label[64];
        if (stage == JobProgress::Growing && fraction <= 0.02f)
            std::snprintf(label, sizeof label, "growing, ~%.0f s left", std::ceil(left));
        else
            std::snprintf(label, sizeof label, "%s %.0f%%, %.0f s left", stage_name(stage),
                          100.0f * fraction, std::ceil(left));
        ImGui::ProgressBar(shown, ImVec2(220.0f, 0.0f), label);
        ImGui::SameLine();
        if (ImGui::SmallButton("cancel")) cancel_generation(state);
        tooltip("stop this generation (Esc); the tree on screen stays");
        ImGui::SameLine();
    } else if (generation_running(state)) {
        ImGui::ProgressBar(0.0f, ImVec2(150.0f, 0.0f), "waiting");
        ImGui::SameLine();
    }
    if (!state.crown_notice.empty()) {
        ImGui::TextColored(kWarningColor, "crown vanished (hover: why)  ");
        tooltip(state.crown_notice.c_str());
        ImGui::SameLine();
    }
    if (state.tree) {
        const GeneratedTree& shown = *state.tree;
        const Tree& t = shown.tree;
        ImGui::Text("%s  ", state.shown_template.name.c_str());
        ImGui::SameLine(0.0f, 0.0f);
        if (shown.reduced() && impostor_slot_shown(state.view)) {
            ImGui::Text("impostor of LOD0: 2 triangles, 8 x 8 views of 128 px%s",
                        state.view.impostor_tree ? " (showing LOD0)" : "");
        } else if (shown.reduced()) {
            const GameMeshTotals totals = game_mesh_totals(shown, state.view.lod_level);
            const std::string label = "game mesh LOD" + std::to_string(totals.level) + ": ";
            totals_line(label, totals, false);
        } else {
            const ShownParts parts = shown_parts(shown, 0);
            ImGui::Text("trunk %zu  crown %zu  leaves %zu triangles%s",
                        parts.trunk.triangles.size(), parts.crown.triangles.size(),
                        parts.leaves.triangles.size(),
                        shown.draft ? " (draft: the game mesh follows)" : "");
        }
        // The time to the tree on screen; each stage's in the tooltip (the line is full).
        ImGui::SameLine(0.0f, 0.0f);
        if (shown.reduced())
            ImGui::Text("   |   %s %.0f ms, %.0f ms in all",
                        shown.reduction_reused ? "reduction kept" : "reduce", shown.reduce_ms,
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
        if (state.release_ms >= 0.0 && state.view.low_poly) {
            ImGui::SameLine(0.0f, 0.0f);
            ImGui::Text("   |   release %.0f ms", state.release_ms);
            tooltip(
                "From letting go of the last slider that changed the tree to its game mesh "
                "arriving; 0 when the game mesh was there before it was let go (the "
                "reduction runs while a slider is held still).");
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

void draw_dialogs(StudioState& state) {
    cost_confirmation(state);
    if (auto path = file_dialog(g_file_dialog, state.recent_files)) {
        state.template_path = *path;
        g_file_dialog.saving ? save_template_to_file(state) : open_template_file(state);
    }
}

bool cost_dialog_open() {
    return ImGui::IsPopupOpen(kCostDialog);
}

}  // namespace sylva::studio
