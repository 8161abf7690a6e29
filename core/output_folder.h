// The folder a job writes into (a batch, a forest, layouts), made (or refused) before any
// work, so a job does not find out at its end that it cannot write. Folders it made are
// removed again unless the job keeps them, so a failed job leaves no empty folder. A writer of
// one file (an export, a saved template) makes the file's folder with it:
//
//   OutputFolder folder(path.parent_path());  // before the work; IoError names the folder
//   write_tree(path, ...);
//   folder.keep();
#pragma once

#include <filesystem>
#include <memory>
#include <vector>

#include "platform/signal_cleanup.h"

namespace sylva {

// The outermost folder of `dir` that does not exist yet: the first one OutputFolder(dir)
// would make, for a caller that asks before making it ("create 'out/trees'?"). Empty when
// `dir` exists (or is empty: the working folder). Says nothing of whether it can be made.
std::filesystem::path missing_folder(const std::filesystem::path& dir);

class OutputFolder {
  public:
    // Makes `dir` and any missing parents. Throws IoError naming `dir` when something other
    // than a folder is there or on the way, it cannot be made, or it is not writable.
    // An empty path is the working folder.
    explicit OutputFolder(const std::filesystem::path& dir);
    // Removes the folders it made, when empty (an interrupt does as well: each is
    // registered with signal_cleanup.h).
    ~OutputFolder();
    OutputFolder(const OutputFolder&) = delete;
    OutputFolder& operator=(const OutputFolder&) = delete;

    // The job succeeded: the folders stay.
    void keep() { made_.clear(), registrations_.clear(); }

  private:
    void remove_made();

    std::vector<std::filesystem::path> made_;  // outermost first
    std::vector<std::unique_ptr<TempRegistration>> registrations_;
};

}  // namespace sylva
