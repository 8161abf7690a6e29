#include "ui/rules_warnings.h"

#include <imgui.h>

#include <string>

namespace sylva::studio {
namespace {

const ImVec4 kWarning(1.0f, 0.75f, 0.25f, 1.0f);

}  // namespace

std::vector<TextMark> warning_marks(const RulesDraft& draft) {
    std::vector<TextMark> marks;
    if (draft.linted != draft.text) return marks;
    for (const LintWarning& w : draft.warnings) marks.push_back({w.line, w.column});
    return marks;
}

void rules_warnings(const RulesDraft& draft, RulesEditorState& editor) {
    const std::vector<LintWarning>& warnings = draft.warnings;
    if (warnings.empty()) return;
    ImGui::TextColored(kWarning, "%zu warning%s (click one to go there)", warnings.size(),
                       warnings.size() == 1 ? "" : "s");
    ImGui::PushStyleColor(ImGuiCol_Text, kWarning);
    for (std::size_t i = 0; i < warnings.size(); ++i) {
        const LintWarning& w = warnings[i];
        const std::string text =
            std::to_string(w.line) + ":" + std::to_string(w.column) + "  " + w.message;
        // A selectable as tall as the message wrapped at the panel's edge, the message over
        // it: the whole of it shows, and a click anywhere on it goes there.
        const float width = ImGui::GetContentRegionAvail().x;
        const float height = ImGui::CalcTextSize(text.c_str(), nullptr, false, width).y;
        const ImVec2 at = ImGui::GetCursorPos();
        ImGui::PushID(static_cast<int>(i));
        if (ImGui::Selectable("##warning", false, 0, ImVec2(width, height)))
            reveal(editor, {w.line, w.column});
        ImGui::PopID();
        const ImVec2 after = ImGui::GetCursorPos();
        ImGui::SetCursorPos(at);
        ImGui::PushTextWrapPos(at.x + width);
        ImGui::TextUnformatted(text.c_str());
        ImGui::PopTextWrapPos();
        ImGui::SetCursorPos(after);
    }
    ImGui::PopStyleColor();
}

}  // namespace sylva::studio
