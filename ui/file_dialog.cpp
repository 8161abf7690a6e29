#include "ui/file_dialog.h"

#include <imgui.h>
#include <imgui_stdlib.h>

#include <algorithm>
#include <system_error>

namespace sylva::studio {

namespace fs = std::filesystem;

std::vector<FolderEntry> list_folder(const fs::path& folder,
                                     const std::vector<std::string>& extensions) {
    std::vector<FolderEntry> entries;
    std::error_code ec;
    for (fs::directory_iterator it(folder, ec), end; !ec && it != end; it.increment(ec)) {
        const std::string name = it->path().filename().string();
        if (name.empty() || name.front() == '.') continue;
        std::error_code type_ec;
        if (it->is_directory(type_ec)) {
            entries.push_back({name, true});
        } else if (std::find(extensions.begin(), extensions.end(),
                             it->path().extension().string()) != extensions.end()) {
            entries.push_back({name, false});
        }
    }
    std::sort(entries.begin(), entries.end(), [](const FolderEntry& a, const FolderEntry& b) {
        return a.folder != b.folder ? a.folder : a.name < b.name;
    });
    return entries;
}

std::optional<std::string> file_dialog(FileDialogState& dialog,
                                       const std::vector<std::string>& recent_files) {
    const std::string title_text =
        (dialog.saving ? "Save " + dialog.what + " as###" : "Open " + dialog.what + "###") +
        dialog.what;
    const char* title = title_text.c_str();
    if (dialog.open_requested) {
        dialog.open_requested = false;
        std::error_code ec;
        if (dialog.folder.empty() || !fs::is_directory(dialog.folder, ec))
            dialog.folder = fs::current_path(ec).string();
        ImGui::OpenPopup(title);
    }
    const ImGuiViewport* viewport = ImGui::GetMainViewport();
    ImGui::SetNextWindowPos(ImVec2(viewport->Size.x * 0.5f, viewport->Size.y * 0.5f),
                            ImGuiCond_Appearing, ImVec2(0.5f, 0.5f));
    ImGui::SetNextWindowSize(ImVec2(560.0f, 440.0f), ImGuiCond_Appearing);
    std::optional<std::string> chosen;
    if (!ImGui::BeginPopupModal(title, nullptr, ImGuiWindowFlags_NoSavedSettings)) return chosen;

    const fs::path folder(dialog.folder);
    if (ImGui::Button("up")) dialog.folder = folder.parent_path().string();
    ImGui::SameLine();
    ImGui::SetNextItemWidth(-1.0f);
    ImGui::InputText("##folder", &dialog.folder);
    const std::vector<FolderEntry> entries = list_folder(folder, dialog.extensions);
    const float list_height = ImGui::GetContentRegionAvail().y -
                              3.0f * ImGui::GetFrameHeightWithSpacing() -
                              (recent_files.empty() ? 0.0f : ImGui::GetFrameHeightWithSpacing());
    ImGui::BeginChild("entries", ImVec2(0.0f, list_height), true);
    std::string enter;  // a folder double-clicked
    for (const FolderEntry& entry : entries) {
        const std::string label = entry.folder ? entry.name + "/" : entry.name;
        if (ImGui::Selectable(label.c_str(), !entry.folder && entry.name == dialog.name,
                              ImGuiSelectableFlags_AllowDoubleClick)) {
            if (entry.folder) {
                enter = entry.name;
            } else {
                dialog.name = entry.name;
                if (ImGui::IsMouseDoubleClicked(ImGuiMouseButton_Left))
                    chosen = (folder / entry.name).string();
            }
        }
    }
    if (entries.empty()) ImGui::TextDisabled("(no folders or %s files here)", dialog.what.c_str());
    ImGui::EndChild();
    if (!enter.empty()) dialog.folder = (folder / enter).string();

    if (!recent_files.empty()) {
        ImGui::SetNextItemWidth(-1.0f);
        if (ImGui::BeginCombo("##recent", "recent files")) {
            for (const std::string& file : recent_files)
                if (ImGui::Selectable(file.c_str())) {
                    dialog.folder = fs::path(file).parent_path().string();
                    dialog.name = fs::path(file).filename().string();
                }
            ImGui::EndCombo();
        }
    }
    ImGui::SetNextItemWidth(-1.0f);
    const std::string first = dialog.extensions.empty() ? "" : dialog.extensions.front();
    const std::string hint = "file name (" + first + ")";
    const bool entered = ImGui::InputTextWithHint("##name", hint.c_str(), &dialog.name,
                                                  ImGuiInputTextFlags_EnterReturnsTrue);
    const bool can_confirm = !dialog.name.empty();
    ImGui::BeginDisabled(!can_confirm);
    if ((ImGui::Button(dialog.saving ? "Save" : "Open") || entered) && can_confirm) {
        fs::path path =
            fs::path(dialog.name).is_absolute() ? fs::path(dialog.name) : folder / dialog.name;
        if (dialog.saving && !path.has_extension()) path += first;
        chosen = path.string();
    }
    ImGui::EndDisabled();
    ImGui::SameLine();
    if (ImGui::Button("Cancel") || ImGui::IsKeyPressed(ImGui::GetKeyIndex(ImGuiKey_Escape)))
        ImGui::CloseCurrentPopup();
    if (chosen) ImGui::CloseCurrentPopup();
    ImGui::EndPopup();
    return chosen;
}

}  // namespace sylva::studio
