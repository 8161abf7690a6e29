#include "ui/rules_editor.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <cctype>
#include <cstdio>
#include <string_view>

namespace sylva::studio {
namespace {

const ImU32 kErrorBand = IM_COL32(220, 60, 50, 70);
const ImU32 kErrorBar = IM_COL32(255, 95, 80, 255);
const ImU32 kWarningLine = IM_COL32(255, 190, 60, 255);

// The width of what a mark at 1-based `column` of `line` points at: the name or number
// starting there, else one character.
float marked_width(std::string_view line, int column, float char_width) {
    const std::size_t start = static_cast<std::size_t>(std::max(column - 1, 0));
    if (start >= line.size()) return char_width;
    std::size_t end = start;
    auto word = [](char c) {
        return std::isalnum(static_cast<unsigned char>(c)) || c == '_' || c == '.';
    };
    while (end < line.size() && word(line[end])) ++end;
    if (end == start) end = start + 1;
    return ImGui::CalcTextSize(line.data() + start, line.data() + end).x;
}

// The text of a 1-based line, without its newline; empty past the end.
std::string_view line_text(std::string_view text, int line) {
    std::size_t start = 0;
    for (int i = 1; i < line; ++i) {
        start = text.find('\n', start);
        if (start == std::string_view::npos) return {};
        ++start;
    }
    std::size_t end = text.find('\n', start);
    return text.substr(start, end == std::string_view::npos ? text.size() - start : end - start);
}

struct TextExtent {
    int lines = 1;
    float widest = 0.0f;  // pixels
};

TextExtent measure(std::string_view text) {
    TextExtent extent;
    std::size_t start = 0;
    while (true) {
        std::size_t end = text.find('\n', start);
        std::string_view line =
            text.substr(start, end == std::string_view::npos ? text.size() - start : end - start);
        extent.widest =
            std::max(extent.widest, ImGui::CalcTextSize(line.data(), line.data() + line.size()).x);
        if (end == std::string_view::npos) return extent;
        ++extent.lines;
        start = end + 1;
    }
}

// Pixels from the start of `line` to its 1-based `column`.
float column_x(std::string_view line, int column) {
    const std::size_t n = std::min(line.size(), static_cast<std::size_t>(std::max(column - 1, 0)));
    return ImGui::CalcTextSize(line.data(), line.data() + n).x;
}

// Runs every frame the field is active: moves to a requested place, remembers the cursor.
int on_edit_callback(ImGuiInputTextCallbackData* data) {
    auto* editor = static_cast<RulesEditorState*>(data->UserData);
    if (editor->select_line > 0) {
        // The cursor goes to the column, with nothing selected: a keystroke must not
        // replace the line.
        std::string_view text(data->Buf, static_cast<std::size_t>(data->BufTextLen));
        std::string_view line = line_text(text, editor->select_line);
        const int start = static_cast<int>(line.data() - text.data());
        const int column = std::clamp(editor->select_column - 1, 0, static_cast<int>(line.size()));
        data->SelectionStart = data->SelectionEnd = data->CursorPos = start + column;
        editor->select_line = 0;
    }
    editor->cursor = data->CursorPos;
    return 0;
}

// Keeps a rectangle of the scrolling child (in screen coordinates) in view.
void scroll_into_view(ImVec2 min, ImVec2 max) {
    const ImVec2 window = ImGui::GetWindowPos();
    const ImVec2 size = ImGui::GetWindowSize();
    const float bar = ImGui::GetStyle().ScrollbarSize;
    const float top = min.y - window.y, bottom = max.y - window.y;
    const float left = min.x - window.x, right = max.x - window.x;
    if (top < 0.0f)
        ImGui::SetScrollY(ImGui::GetScrollY() + top);
    else if (bottom > size.y - bar)
        ImGui::SetScrollY(ImGui::GetScrollY() + bottom - (size.y - bar));
    if (left < 0.0f)
        ImGui::SetScrollX(ImGui::GetScrollX() + left);
    else if (right > size.x - bar)
        ImGui::SetScrollX(ImGui::GetScrollX() + right - (size.x - bar));
}

}  // namespace

void reveal(RulesEditorState& editor, TextMark mark) {
    editor.select_line = std::max(mark.line, 0);
    editor.select_column = std::max(mark.column, 1);
}

bool ctrl_enter_in_editor(const RulesEditorState& editor) {
    ImGuiIO& io = ImGui::GetIO();
    bool pressed = false;
    for (ImGuiKey key : {ImGuiKey_Enter, ImGuiKey_KeyPadEnter}) {
        const int index = ImGui::GetKeyIndex(key);
        if (!editor.active || !io.KeyCtrl || !ImGui::IsKeyPressed(index, false)) continue;
        // The field would end its editing on it (and lose the characters typed while it
        // takes the keyboard back): it never sees this press.
        io.KeysDownDuration[index] = -1.0f;
        pressed = true;
    }
    return pressed;
}

bool rules_editor(const char* id, std::string& text, TextMark mark, RulesEditorState& editor,
                  float height, const std::vector<TextMark>& underlines) {
    const ImGuiStyle& style = ImGui::GetStyle();
    const float line_height = ImGui::GetTextLineHeight();
    const float char_width = ImGui::CalcTextSize("M").x;
    const TextExtent extent = measure(text);
    const bool marked = mark.line > 0 && mark.line <= extent.lines;

    // Line numbers in a column of their own that scrolls with the text vertically only;
    // they are drawn once the text's scroll is known, below.
    const float gutter = ImGui::CalcTextSize("000").x + 2.0f * style.FramePadding.x;
    const ImVec2 top_left = ImGui::GetCursorScreenPos();
    ImGui::SetCursorScreenPos(ImVec2(top_left.x + gutter, top_left.y));

    ImGui::PushStyleColor(ImGuiCol_ChildBg, style.Colors[ImGuiCol_FrameBg]);
    ImGui::PushStyleVar(ImGuiStyleVar_WindowPadding, ImVec2(0.0f, 0.0f));
    ImGui::BeginChild(id, ImVec2(0.0f, height), false, ImGuiWindowFlags_HorizontalScrollbar);
    ImDrawList* draw = ImGui::GetWindowDrawList();
    const ImVec2 origin = ImGui::GetCursorScreenPos();  // content top-left, scrolled
    const ImVec2 text_origin(origin.x + style.FramePadding.x, origin.y + style.FramePadding.y);
    const ImVec2 field_size(
        std::max(ImGui::GetContentRegionAvail().x, extent.widest + 4.0f * char_width),
        std::max(ImGui::GetContentRegionAvail().y,
                 static_cast<float>(extent.lines + 1) * line_height + 2.0f * style.FramePadding.y));

    // The mark goes under the text: the field's own background is made transparent below.
    if (marked) {
        const float y = text_origin.y + static_cast<float>(mark.line - 1) * line_height;
        draw->AddRectFilled(ImVec2(origin.x, y), ImVec2(origin.x + field_size.x, y + line_height),
                            kErrorBand);
        std::string_view line = line_text(text, mark.line);
        const float x = text_origin.x + column_x(line, mark.column);
        const float w = mark.column > 0
                            ? char_width
                            : ImGui::CalcTextSize(line.data(), line.data() + line.size()).x;
        draw->AddRectFilled(ImVec2(x, y + line_height - 1.0f),
                            ImVec2(x + std::max(w, 4.0f), y + line_height + 2.0f), kErrorBar);
        if (editor.select_line > 0)
            scroll_into_view(ImVec2(x - 8.0f * char_width, y - line_height),
                             ImVec2(x + 8.0f * char_width, y + 2.0f * line_height));
    }

    // The warnings: an orange underline under the word each points at.
    for (const TextMark& w : underlines) {
        if (w.line <= 0 || w.line > extent.lines) continue;
        const std::string_view line = line_text(text, w.line);
        const float y = text_origin.y + static_cast<float>(w.line) * line_height;
        const float x = text_origin.x + (w.column > 0 ? column_x(line, w.column) : 0.0f);
        const float width = w.column > 0
                                ? marked_width(line, w.column, char_width)
                                : ImGui::CalcTextSize(line.data(), line.data() + line.size()).x;
        draw->AddLine(ImVec2(x, y), ImVec2(x + std::max(width, 4.0f), y), kWarningLine, 2.0f);
    }

    ImGui::PushStyleColor(ImGuiCol_FrameBg, IM_COL32(0, 0, 0, 0));
    if (editor.select_line > 0) ImGui::SetKeyboardFocusHere();
    const bool changed = ImGui::InputTextMultiline("##text", &text, field_size,
                                                   ImGuiInputTextFlags_AllowTabInput |
                                                       ImGuiInputTextFlags_NoHorizontalScroll |
                                                       ImGuiInputTextFlags_CallbackAlways,
                                                   on_edit_callback, &editor);
    ImGui::PopStyleColor();

    // The field never scrolls itself (it is as large as its text); this child does, and
    // follows the cursor.
    if (ImGui::IsItemActive() && editor.cursor >= 0) {
        const std::string_view before(
            text.data(), std::min(static_cast<std::size_t>(editor.cursor), text.size()));
        const std::size_t newline = before.rfind('\n');
        const std::size_t line_start = newline == std::string_view::npos ? 0 : newline + 1;
        const auto line = static_cast<float>(std::count(before.begin(), before.end(), '\n'));
        const float x =
            text_origin.x +
            ImGui::CalcTextSize(before.data() + line_start, before.data() + before.size()).x;
        const float y = text_origin.y + line * line_height;
        scroll_into_view(ImVec2(x - 4.0f * char_width, y),
                         ImVec2(x + 4.0f * char_width, y + line_height));
        editor.line_x = ImGui::GetWindowPos().x;
        editor.line_y = y;
        editor.line_width = ImGui::GetWindowSize().x;
        editor.line_height = line_height;
    } else {
        editor.cursor = -1;
    }
    editor.active = ImGui::IsItemActive();
    ImGui::EndChild();
    ImGui::PopStyleVar();
    ImGui::PopStyleColor();

    ImDrawList* panel = ImGui::GetWindowDrawList();
    const ImVec2 gutter_max(top_left.x + gutter, top_left.y + height);
    panel->PushClipRect(top_left, gutter_max, true);
    panel->AddRectFilled(top_left, gutter_max, ImGui::GetColorU32(ImGuiCol_FrameBg));
    for (int i = 1; i <= extent.lines; ++i) {
        const float y = text_origin.y + static_cast<float>(i - 1) * line_height;
        if (y + line_height < top_left.y || y > gutter_max.y) continue;
        char number[16];
        std::snprintf(number, sizeof number, "%d", i);
        const bool error_line = marked && i == mark.line;
        const bool warning_line = std::any_of(underlines.begin(), underlines.end(),
                                              [i](const TextMark& w) { return w.line == i; });
        if (error_line)
            panel->AddRectFilled(ImVec2(top_left.x, y), ImVec2(gutter_max.x, y + line_height),
                                 kErrorBand);
        panel->AddText(
            ImVec2(gutter_max.x - style.FramePadding.x - ImGui::CalcTextSize(number).x, y),
            error_line     ? kErrorBar
            : warning_line ? kWarningLine
                           : ImGui::GetColorU32(ImGuiCol_TextDisabled),
            number);
    }
    panel->PopClipRect();
    return changed;
}

}  // namespace sylva::studio
