#include "ui/rules_warnings.h"

#include <imgui.h>

#include <string>
#include <vector>

#include "tree/organ_surfaces.h"
#include "turtle/lint.h"
#include "turtle/lsystem_growth.h"

namespace sylva::studio {
namespace {

const ImVec4 kWarning(1.0f, 0.75f, 0.25f, 1.0f);

// The last grammar and parameters linted, and their warnings: a frame redraws them without
// parsing again.
struct LintCache {
    std::string grammar;
    Constants constants;
    std::vector<LintWarning> warnings;
    bool valid = false;
};

const std::vector<LintWarning>& warnings_of(const TreeTemplate& tree) {
    static LintCache cache;
    Constants constants = param_constants(tree.params);
    if (!cache.valid || cache.grammar != tree.grammar || cache.constants != constants) {
        cache.grammar = tree.grammar;
        cache.constants = std::move(constants);
        cache.valid = true;
        try {
            cache.warnings = lint_grammar(cache.grammar, cache.constants, organ_surface_names());
        } catch (const std::exception&) {
            cache.warnings.clear();  // the editor marks the error
        }
    }
    return cache.warnings;
}

}  // namespace

void rules_warnings(const TreeTemplate& tree, RulesEditorState& editor) {
    if (tree.growth != lsystem_growth.name) return;
    const std::vector<LintWarning>& warnings = warnings_of(tree);
    if (warnings.empty()) return;
    ImGui::TextColored(kWarning, "%zu warning%s (click one to go there)", warnings.size(),
                       warnings.size() == 1 ? "" : "s");
    ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
    ImGui::PushTextWrapPos(0.0f);
    for (std::size_t i = 0; i < warnings.size(); ++i) {
        const LintWarning& w = warnings[i];
        const std::string text = std::to_string(w.line) + ":" + std::to_string(w.column) + "  " +
                                 w.message + "##warning" + std::to_string(i);
        if (ImGui::Selectable(text.c_str(), false)) reveal(editor, {w.line, w.column});
    }
    ImGui::PopTextWrapPos();
    ImGui::PopStyleColor();
}

}  // namespace sylva::studio
