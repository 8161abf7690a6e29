// The studio's own file dialog for Open and Save as: an ImGui modal that lists a folder's
// subfolders and template files (.toml, .lsys, .txt), with a name field and the recent
// files. No native dialog library: Debian offers none that fits a GLFW + ImGui window
// without pulling in a toolkit.
#pragma once

#include <filesystem>
#include <optional>
#include <string>
#include <vector>

namespace sylva::studio {

// One row of a folder listing: folders first, then files, each sorted by name.
struct FolderEntry {
    std::string name;
    bool folder = false;
};
// Subfolders and files ending in one of `extensions` (hidden ones left out). Empty when the
// folder cannot be read.
std::vector<FolderEntry> list_folder(const std::filesystem::path& folder,
                                     const std::vector<std::string>& extensions);

struct FileDialogState {
    bool open_requested = false;  // set to open the dialog on the next frame
    bool saving = false;          // Save as (a new name may be typed) or Open
    std::string folder;           // the folder shown
    std::string name;             // the file name field
    // What it lists and names: template files by default; the first extension is the one a
    // new name gets. `what` names them in the title ("template", "layout example") and is
    // the popup's ID, so each kind of dialog is its own.
    std::vector<std::string> extensions{".toml", ".lsys", ".txt"};
    std::string what = "template";
};

// Draws the dialog while it is open; returns the chosen path once, when the user confirms.
std::optional<std::string> file_dialog(FileDialogState& dialog,
                                       const std::vector<std::string>& recent_files);

}  // namespace sylva::studio
