// Several files written all or nothing: each file is written into a staging folder beside
// its target (same file system, so the moves are renames), and commit() moves them into
// place only once every one was written. A FileSet dropped without commit() (an exception,
// a failed write) removes its staging folders, and every existing target stays as it was:
// an OBJ export that fails keeps the old .mtl, a LOD chain that fails at LOD2 leaves no
// LOD0. Exports go through one (export/export.h); write_file_atomically() is a set of one.
//
// Targets: a symlink is followed (the file it points to is replaced, the link stays); a
// directory, device, FIFO or socket is refused. The staging folders and files are
// registered with signal_cleanup.h, so an interrupted CLI leaves nothing behind.
#pragma once

#include <filesystem>
#include <functional>
#include <memory>
#include <ostream>
#include <vector>

namespace sylva {

class TempRegistration;

// Where a write to `path` lands: `path` itself, or the file a symlink at `path` points to
// (through chains of links, relative ones read from the link's folder; a dangling link's
// target is created). Throws IoError naming `path` when what is there (or linked) is not a
// regular file (a directory, a device such as /dev/null, a FIFO, a socket), or the links
// loop.
std::filesystem::path output_target(const std::filesystem::path& path);

class FileSet {
  public:
    FileSet();
    // Without commit(): removes the staging folders; the targets stay untouched.
    ~FileSet();
    FileSet(const FileSet&) = delete;
    FileSet& operator=(const FileSet&) = delete;

    // Writes one file's content now, into its staging copy. `target` goes through
    // output_target(); each target is added once. Returns where the file will land. Throws
    // IoError naming the target when it is refused, its folder cannot take the staging
    // folder, or writing fails; rethrows what `write` throws.
    std::filesystem::path add(const std::filesystem::path& target,
                              const std::function<void(std::ostream&)>& write);

    // Moves every file into place, in the order added, and returns where they landed. When a
    // move fails, the files moved before it are put back (their previous content, or removed
    // when they are new) and IoError names the target. SIGINT/SIGTERM meanwhile wait until
    // the moves are done. Call once.
    std::vector<std::filesystem::path> commit();

  private:
    struct Folder;
    struct Staged;
    Folder& folder_for(const std::filesystem::path& dir, const std::filesystem::path& requested);
    void roll_back() noexcept;

    std::vector<std::unique_ptr<Folder>> folders_;
    std::vector<std::unique_ptr<Staged>> files_;
    bool committed_ = false;
};

}  // namespace sylva
