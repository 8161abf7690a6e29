#include "ui/panels.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <glm/trigonometric.hpp>
#include <optional>
#include <random>
#include <string>

#include "core/name_list.h"
#include "core/seed.h"
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
#include "ui/state/forest_export.h"
#include "ui/state/template_controls.h"
#include "ui/template_picker.h"

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

// The studio's own file dialog (ui/file_dialog.h), shared by Open and Save as; the export
// path's Browse has one of its own.
FileDialogState g_file_dialog;
FileDialogState g_export_dialog{.saving = true,
                                .folder = {},
                                .name = {},
                                .extensions = {".glb", ".obj", ".ply"},
                                .what = "export"};

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

// Save: to the file the template came from, or through the dialog when there is none yet.
void save_or_ask(StudioState& state) {
    if (std::filesystem::exists(state.template_path)) {
        save_template_to_file(state);
    } else {
        g_file_dialog.saving = true;
        g_file_dialog.open_requested = true;
    }
}

void template_section(StudioState& state) {
    // The unsaved-changes mark (the window's title carries it too, main).
    section(unsaved_changes(state) ? "Template  * unsaved changes" : "Template");
    template_picker_row(template_picker(), state);  // ui/template_picker.h
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
    if (ImGui::Button("Save")) save_or_ask(state);
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
            if (ImGui::Selectable(file.c_str())) open_template_file(state, file);
        ImGui::EndCombo();
    }
    message_line(state.file_message, state.file_failed);
}

// The template's own knobs: its #define constants that carry a range
// (ui/state/template_controls.h), labelled by their help comment, and its colours.
void this_tree_section(StudioState& state) {
    const std::string& query = state.parameter_search;
    if (!query.empty()) ImGui::SetNextItemOpen(true, ImGuiCond_Always);
    if (!ImGui::CollapsingHeader("This tree", ImGuiTreeNodeFlags_DefaultOpen)) return;
    TreeTemplate& t = state.tree_template;
    const std::vector<GrammarConstant> constants = grammar_constants(t.grammar);
    for (const GrammarConstant& c : constants) {
        const std::string label = constant_label(c);
        if (!search_finds(query, label + " " + c.name + " " + c.help)) continue;
        // A label longer than the column beside the sliders goes above its slider, wrapped,
        // so it is never cut at the panel's edge.
        const float label_room = ImGui::GetContentRegionAvail().x - ImGui::CalcItemWidth() -
                                 ImGui::GetStyle().ItemInnerSpacing.x;
        const bool label_above = ImGui::CalcTextSize(label.c_str()).x > label_room;
        if (label_above) {
            ImGui::PushTextWrapPos(0.0f);
            ImGui::TextUnformatted(label.c_str());
            ImGui::PopTextWrapPos();
            ImGui::SetNextItemWidth(-1.0f);
        }
        const std::string id = (label_above ? "" : label) + "##define " + c.name;
        bool changed = false;
        double value = c.value;
        if (c.integer) {
            int v = static_cast<int>(c.value);
            changed =
                ImGui::SliderInt(id.c_str(), &v, static_cast<int>(c.min), static_cast<int>(c.max));
            value = v;
        } else {
            float v = static_cast<float>(c.value);
            changed = ImGui::SliderFloat(id.c_str(), &v, static_cast<float>(c.min),
                                         static_cast<float>(c.max), "%.4g");
            value = round_for_range(v, c.min, c.max);
        }
        if (ImGui::IsItemHovered())
            ImGui::SetTooltip("%s\n#define %s, line %d of the rules; range %g to %g",
                              c.help.empty() ? c.name.c_str() : c.help.c_str(), c.name.c_str(),
                              c.line, c.min, c.max);
        if (changed && value != c.value) set_grammar_constant(t.grammar, c.name, value);
    }
    if (constants.empty() && reads_grammar(t) && query.empty()) {
        ImGui::PushTextWrapPos(0.0f);
        ImGui::TextDisabled(
            "No constants with a range in the rules. A #define with \"# [min, max] help\" "
            "after its value becomes a slider here, e.g.  #define a 34  # [10, 60] fork angle");
        ImGui::PopTextWrapPos();
    }
    if (!search_finds(query, "colours colors bark crown leaves")) return;
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

// The registry's parameters under a collapsible header per group (Shape, Branches, ...,
// core/param_table.h), filtered by the search field; the turtle and width model head Shape,
// the seed heads Variation.
void parameter_section(StudioState& state) {
    TreeTemplate& t = state.tree_template;
    TreeParams& params = t.params;
    const std::string& query = state.parameter_search;
    const std::vector<ParameterRow> rows = parameter_rows(t);
    for (const ParamGroup group : param_groups()) {
        const std::string title(group_title(group));
        const bool shape = group == ParamGroup::Shape, variation = group == ParamGroup::Variation;
        const bool turtle_found =
            shape && search_finds(query, "turtle abop lptg widths explicit taper pipe Shape");
        const bool seed_found = variation && search_finds(query, "seed random Variation");
        std::vector<const ParameterRow*> found;
        for (const ParameterRow& row : rows)
            if (row.info->group == group && search_finds(query, parameter_search_text(*row.info)))
                found.push_back(&row);
        if (found.empty() && !turtle_found && !seed_found) continue;
        if (!query.empty()) ImGui::SetNextItemOpen(true, ImGuiCond_Always);
        if (!ImGui::CollapsingHeader(title.c_str(), shape ? ImGuiTreeNodeFlags_DefaultOpen : 0))
            continue;
        ImGui::PushID(title.c_str());
        if (turtle_found) {
            enum_combo("turtle", t.mode, {"abop", "lptg"},
                       "abop: ABOP's H, L, U turtle; lptg: Heuer's elevation / azimuth turtle");
            enum_combo("widths", t.width_model, {"explicit", "taper", "pipe"},
                       "explicit: ! sets widths; taper: trunk_taper / branch_taper per segment; "
                       "pipe: Murray's pipe model from tip_width");
        }
        if (seed_found) {
            const std::uint64_t step = 1;
            // Held to the one seed range (core/seed.h), so a saved template always reopens.
            if (ImGui::InputScalar("seed", ImGuiDataType_U64, &params.seed, &step))
                params.seed = std::min(params.seed, kMaxSeed);
            tooltip(
                "the random choices of stochastic rules and rand(); same seed, same tree "
                "(0 to 2^53 - 1)");
            ImGui::SameLine();
            if (ImGui::Button("new")) params.seed = std::random_device{}() % 1000000;
            tooltip("a new random seed");
        }
        // Parameters this tree's rules and growth never read are shown, greyed, with the
        // reason. (crown_merge and drop_hidden act in the full-detail view too: it is meshed
        // for the template's budget, as the game mesh is.)
        for (const ParameterRow* row : found) {
            const ParamInfo& info = *row->info;
            double value = *get_param(params, info.key);
            const bool disabled = !row->unread.empty();
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
                                      row->unread.c_str());
                else if (info.choices.empty())
                    ImGui::SetTooltip("%s\nrange %g to %g (Ctrl+click to type)", help.c_str(),
                                      info.min, info.max);
                else
                    ImGui::SetTooltip("%s", help.c_str());
            }
            if (changed) set_param(params, info.key, std::clamp(value, info.min, info.max));
        }
        ImGui::PopID();
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
    // Rules applied on a typing pause show the estimate beside the editor instead; and no
    // dialog takes the keyboard from a text field being typed into.
    if (asked != state.cost_warning && !state.cost_warning_quiet && !ImGui::GetIO().WantTextInput) {
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
        undo_refused_edit(state);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Not now")) ImGui::CloseCurrentPopup();
    tooltip("keep the edit without running it; \"run anyway\" stays under the rules");
    ImGui::EndPopup();
}

constexpr const char* kDiscardDialog = "Discard changes?";

// Asked when another template is picked or opened over unsaved edits (switch_template()):
// opened here, at the top of the ID stack, and begun every frame while it is open.
void discard_dialog(StudioState& state) {
    if (state.pending_switch && !ImGui::IsPopupOpen(kDiscardDialog) &&
        !ImGui::GetIO().WantTextInput)
        ImGui::OpenPopup(kDiscardDialog);
    if (!ImGui::BeginPopupModal(
            kDiscardDialog, nullptr,
            ImGuiWindowFlags_AlwaysAutoResize | ImGuiWindowFlags_NoSavedSettings))
        return;
    if (!state.pending_switch) {  // answered elsewhere
        ImGui::CloseCurrentPopup();
        ImGui::EndPopup();
        return;
    }
    const TemplateSwitch& next = *state.pending_switch;
    ImGui::PushTextWrapPos(420.0f);
    ImGui::Text("\"%s\" has unsaved changes. Open \"%s\" and discard them?",
                state.tree_template.name.c_str(),
                next.path.empty() ? next.tree_template.name.c_str() : next.path.c_str());
    ImGui::TextDisabled("Undo (Ctrl+Z) brings the edits back.");
    ImGui::PopTextWrapPos();
    if (ImGui::Button("Discard and open")) {
        confirm_switch(state);
        ImGui::CloseCurrentPopup();
    }
    ImGui::SameLine();
    if (ImGui::Button("Keep editing")) {
        cancel_switch(state);
        ImGui::CloseCurrentPopup();
    }
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
            {"Ctrl+Enter", "apply the rules being typed (else after a pause)"},
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
    ImGui::SameLine();
    if (ImGui::Button("undo the edit")) undo_refused_edit(state);
    tooltip("back to the edit before this one; the view frames the tree again");
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
    // The editor edits a draft (ui/state/rules_draft.h): it becomes the grammar on a typing
    // pause or Ctrl+Enter, and only when it parses.
    sync_rules_draft(state);
    RulesDraft& draft = state.rules;
    const bool refused = !draft.error.empty();
    const TextMark mark = refused ? TextMark{draft.error_line, draft.error_column}
                                  : TextMark{state.error_line, state.error_column};
    const bool ctrl_enter = ctrl_enter_in_editor(editor);
    if (rules_editor("rules", draft.text, mark, editor, height, warning_marks(draft)))
        rules_typed(state, std::chrono::steady_clock::now());
    const auto now = std::chrono::steady_clock::now();
    lint_rules_draft(state, now);
    apply_rules_draft(state, now, ctrl_enter);
    rules_warnings(draft, editor);
    if (draft.pending) {
        ImGui::TextDisabled("typing: applied after a pause, or Ctrl+Enter");
    } else if (mark.line > 0) {
        ImGui::TextColored(kErrorColor, "line %d, column %d", mark.line, mark.column);
        ImGui::SameLine();
        if (ImGui::SmallButton("show")) reveal(editor, mark);
        tooltip("put the cursor there");
    }
    if (!draft.pending && refused) {
        wrapped_text(draft.error, true);
        ImGui::TextDisabled("(not applied: the tree is of the last rules that parsed)");
    } else {
        wrapped_text(state.error, true);
        if (!state.error.empty())
            ImGui::TextDisabled("(the tree on screen is the last one that worked)");
    }
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

// The wind panel: the template's wind parameters (core/wind_params.h), which the view sways
// the tree in and exports carry to the engine kits' shaders (docs/engines.md). They move
// the tree without regrowing it.
void wind_row(TreeParams& params) {
    struct Slider {
        const char* key;
        const char* label;
        float max;
        const char* format;
    };
    constexpr Slider kSliders[] = {{"wind_strength", "strength", 2.0f, "%.2f m"},
                                   {"wind_direction", "direction", 360.0f, "%.0f deg"},
                                   {"wind_gust_frequency", "gusts", 1.0f, "%.2f /s"},
                                   {"wind_flutter", "flutter", 1.0f, "%.2f"}};
    for (std::size_t i = 0; i < std::size(kSliders); ++i) {
        const Slider& s = kSliders[i];
        const ParamInfo& info = *find_param(s.key);
        float value = static_cast<float>(*get_param(params, s.key));
        if (i % 2) ImGui::SameLine();
        ImGui::SetNextItemWidth(110.0f);
        if (ImGui::SliderFloat(s.label, &value, static_cast<float>(info.min),
                               std::max(s.max, value), s.format))
            set_param(params, s.key, std::clamp(static_cast<double>(value), info.min, info.max));
        tooltip(std::string(info.help).c_str());
    }
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
    if (v.wind) wind_row(state.tree_template.params);
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

// What the export writes, a line per part and a column per LOD level, when the view has the
// game mesh at the export's budget: trunk and crown share one target, leaves have their own.
void budget_table(const StudioState& state) {
    const GeneratedTree* shown = state.tree.get();
    const std::size_t budget = export_budget(state);
    if (!shown || !shown->reduced() || shown->budget != budget) {
        ImGui::PushTextWrapPos(0.0f);
        if (shown && shown->reduced())
            ImGui::TextDisabled(
                "(the view shows the game mesh at the template's %zu; this export reduces to "
                "%zu)",
                shown->budget, budget);
        else
            ImGui::TextDisabled("(switch low poly on to see the game mesh's triangles)");
        ImGui::PopTextWrapPos();
        return;
    }
    const int levels =
        state.export_settings.lod ? static_cast<int>(shown->finished.levels.size()) : 1;
    if (!ImGui::BeginTable(
            "budget", levels + 1,
            ImGuiTableFlags_SizingFixedFit | ImGuiTableFlags_RowBg | ImGuiTableFlags_BordersInnerV))
        return;
    ImGui::TableSetupColumn("writes");
    for (int level = 0; level < levels; ++level)
        ImGui::TableSetupColumn(levels > 1 ? ("LOD" + std::to_string(level)).c_str()
                                           : "triangles / target");
    ImGui::TableHeadersRow();
    std::vector<std::vector<BudgetLine>> columns;
    std::string notes;
    for (int level = 0; level < levels; ++level) {
        const GameMeshTotals totals = game_mesh_totals(*shown, level);
        columns.push_back(budget_lines(totals));
        if (!totals.note.empty())
            notes += "LOD" + std::to_string(level) + ": " + totals.note + "\n";
    }
    for (std::size_t row = 0; row < columns.front().size(); ++row) {
        ImGui::TableNextRow();
        ImGui::TableNextColumn();
        ImGui::TextUnformatted(columns.front()[row].part.c_str());
        for (const std::vector<BudgetLine>& column : columns) {
            const BudgetLine& line = column[row];
            ImGui::TableNextColumn();
            char cell[64];
            if (line.target == 0)
                std::snprintf(cell, sizeof cell, "%zu", line.triangles);
            else if (line.target == SIZE_MAX)
                std::snprintf(cell, sizeof cell, "%zu / all", line.triangles);
            else
                std::snprintf(cell, sizeof cell, "%zu / %zu", line.triangles, line.target);
            if (line.over)
                ImGui::TextColored(kWarningColor, "%s over", cell);
            else
                ImGui::TextUnformatted(cell);
            if (line.over && !notes.empty()) tooltip(notes.c_str());
        }
    }
    ImGui::EndTable();
}

void export_section(StudioState& state) {
    section("Export");
    ExportSettings& e = state.export_settings;
    ImGui::PushItemWidth(ImGui::CalcItemWidth() - ImGui::CalcTextSize("Browse...").x -
                         2.0f * ImGui::GetStyle().FramePadding.x -
                         ImGui::GetStyle().ItemInnerSpacing.x);
    if (ImGui::InputText("##path", &e.path)) state.export_missing_folder.clear();
    ImGui::PopItemWidth();
    tooltip(("the extension picks the format: " + name_list(format_extensions())).c_str());
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    if (ImGui::Button("Browse...")) {
        const std::filesystem::path path(e.path);
        std::error_code ec;
        g_export_dialog.folder = std::filesystem::absolute(path, ec).parent_path().string();
        g_export_dialog.name = path.filename().string();
        g_export_dialog.open_requested = true;
    }
    tooltip("pick the folder and name to export to");
    ImGui::SameLine(0.0f, ImGui::GetStyle().ItemInnerSpacing.x);
    ImGui::TextUnformatted("path");
    if (!state.export_missing_folder.empty()) {
        ImGui::TextColored(kWarningColor, "%s does not exist.",
                           state.export_missing_folder.c_str());
        ImGui::SameLine();
        if (ImGui::SmallButton("create it and export")) create_export_folder(state);
    }
    const ExportFormat* format = format_from_extension(e.path);
    if (ImGui::BeginCombo("format", format ? std::string(format->name).c_str() : "(extension?)")) {
        for (const ExportFormat* f : export_formats())
            if (ImGui::Selectable(std::string(f->name).c_str(), format == f))
                e.path = std::filesystem::path(e.path).replace_extension(f->extension).string();
        ImGui::EndCombo();
    }
    // The export's own budget: editing it is no edit of the template until "keep" is pressed.
    const int template_budget = state.tree_template.params.triangle_budget;
    int budget = static_cast<int>(export_budget(state));
    if (ImGui::InputInt("budget", &budget, 100, 1000)) e.budget = std::max(budget, 0);
    tooltip(
        "trunk + crown triangles of this export after reduction (0 keeps every triangle); "
        "leaves get as many again. Changing it edits no template.");
    if (e.budget >= 0 && e.budget != template_budget) {
        ImGui::TextDisabled("the template's is %d:", template_budget);
        ImGui::SameLine();
        if (ImGui::SmallButton("keep in template")) keep_export_budget(state);
        tooltip("make this the template's triangle_budget (the view and a save follow)");
        ImGui::SameLine();
        if (ImGui::SmallButton("use template's")) e.budget = -1;
    }
    ImGui::Checkbox("LOD chain", &e.lod);
    tooltip("four levels: budget, 1/2, 1/4, 1/8 (one .glb, or a file per level)");
    profile_combo(e.profile);
    ImGui::SameLine();
    ImGui::BeginDisabled(state.export_job.valid() || !state.tree);
    if (ImGui::Button("Export (Ctrl+E)")) start_export(state);
    ImGui::EndDisabled();
    budget_table(state);
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
    layout.top = ImGui::GetFrameHeight();  // BeginMainMenuBar's height
    return layout;
}

void draw_menu_bar(StudioState& state, bool& variants_open, bool& infer_open, bool* layout_open) {
    if (!ImGui::BeginMainMenuBar()) return;
    if (ImGui::BeginMenu("File")) {
        if (ImGui::MenuItem("Open...", "Ctrl+O")) request_file_dialog(false);
        if (ImGui::BeginMenu("Open recent", !state.recent_files.empty())) {
            for (const std::string& file : state.recent_files)
                if (ImGui::MenuItem(file.c_str())) open_template_file(state, file);
            ImGui::EndMenu();
        }
        if (ImGui::MenuItem("Save", "Ctrl+S")) save_or_ask(state);
        if (ImGui::MenuItem("Save as...")) {
            g_file_dialog.name = std::filesystem::path(state.template_path).filename().string();
            request_file_dialog(true);
        }
        ImGui::Separator();
        const bool exporting = state.export_job.valid();
        if (ImGui::MenuItem("Export tree", "Ctrl+E", false, !exporting && state.tree))
            start_export(state);
        tooltip(("the tree on screen to " + state.export_settings.path).c_str());
        if (ImGui::MenuItem("Export forest", nullptr, false, !exporting))
            start_forest_export(state);
        tooltip(("the forest preview's square, planted at the template's budget, to " +
                 forest_export_path(state.export_settings.path).string() +
                 " with its placement lists (as sylva forest writes)")
                    .c_str());
        ImGui::Separator();
        if (ImGui::MenuItem("Quit")) state.quit_requested = true;
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("Edit")) {
        if (ImGui::MenuItem("Undo", "Ctrl+Z")) undo(state);
        if (ImGui::MenuItem("Redo", "Ctrl+Y", false, !state.redo.empty())) redo(state);
        if (ImGui::MenuItem("Reset to the template")) reset_to_template(state);
        ImGui::EndMenu();
    }
    if (ImGui::BeginMenu("View")) {
        ImGui::MenuItem("Variants strip", nullptr, &variants_open);
        if (layout_open) ImGui::MenuItem("Layout panel", nullptr, layout_open);
        ImGui::MenuItem("Rules from a tree", nullptr, &infer_open);
        tooltip(
            "rules that regrow a tree you already have (a skeleton file, or the one on screen)");
        ImGui::MenuItem("Forest preview", nullptr, &state.view.forest);
        ImGui::MenuItem("Low poly (game mesh)", nullptr, &state.view.low_poly);
        ImGui::MenuItem("Wind", nullptr, &state.view.wind);
        if (ImGui::MenuItem("Frame tree", "F")) state.frame_requested = true;
        ImGui::Separator();
        ImGui::MenuItem("Shortcuts", "F1", &state.show_shortcuts);
        ImGui::EndMenu();
    }
    ImGui::EndMainMenuBar();
}

void draw_tree_panel(StudioState& state, const PanelLayout& layout) {
    ImGui::SetNextWindowPos(ImVec2(0.0f, layout.top));
    ImGui::SetNextWindowSize(ImVec2(layout.left, layout.height - layout.bottom - layout.top));
    ImGui::Begin("Tree", nullptr, kDocked);
    ImGui::PushItemWidth(-130.0f);
    actions_row(state);
    estimate_line(state);
    template_section(state);
    section("Parameters");
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputTextWithHint("##search", "search parameters (e.g. leaf, angle)",
                             &state.parameter_search);
    tooltip("shows the parameters whose name, help or group has every word typed");
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
    ImGui::SetNextWindowPos(ImVec2(layout.width - layout.right, layout.top));
    ImGui::SetNextWindowSize(ImVec2(layout.right, layout.height - layout.bottom - layout.top));
    ImGui::Begin("Rules and export", nullptr, kDocked);
    ImGui::PushItemWidth(-80.0f);
    // The editor takes what the other sections leave.
    const float below = 24.0f * ImGui::GetFrameHeightWithSpacing();
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
        if (g_file_dialog.saving) {
            state.template_path = *path;
            save_template_to_file(state);
        } else {
            open_template_file(state, *path);
        }
    }
    discard_dialog(state);
    if (auto path = file_dialog(g_export_dialog, {})) {
        state.export_settings.path = *path;
        state.export_missing_folder.clear();
    }
}

bool cost_dialog_open() {
    return ImGui::IsPopupOpen(kCostDialog);
}

bool discard_dialog_open() {
    return ImGui::IsPopupOpen(kDiscardDialog);
}

}  // namespace sylva::studio
