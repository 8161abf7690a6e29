// The template picker's thumbnails: each template's default tree, made once on a worker at a
// small triangle budget, drawn by the window into a small image and kept, in memory and in
// the user's cache folder, under a hash of the template's content. Opening the picker again
// (or the studio, with the cache folder) reuses them; a template whose text changed gets a
// new hash and is made again. Until its image is ready the picker shows a placeholder.
//
// The GL drawing stays in ui/ (ui/template_picker.h): this is the headless part, tested
// without a window. Thread safety: the public functions are for the UI thread; one worker
// thread of the cache makes the meshes, one template at a time, and waits while
// set_paused(true) (a generation runs), so it never takes the cores from the tree being
// edited.
#pragma once

#include <atomic>
#include <condition_variable>
#include <cstdint>
#include <deque>
#include <filesystem>
#include <functional>
#include <map>
#include <mutex>
#include <optional>
#include <string>
#include <string_view>
#include <thread>
#include <vector>

#include "core/mesh.h"
#include "core/tree_template.h"

namespace sylva::studio {

// Pixels per side of a thumbnail.
inline constexpr int kTemplateThumbnailSize = 96;

// A template the picker shows: its name, the text its content hash is taken of (a built-in
// template's own file text) and the template itself.
struct ThumbnailSource {
    std::string name;
    std::string text;
    TreeTemplate tree;
};

// What a thumbnail is drawn from: the default tree's game mesh at a small budget.
struct ThumbnailMeshes {
    Mesh trunk, crown, leaves;
    PartColors colors;
};

// Grows `tree` and reduces it to a thumbnail's budget; throws Cancelled once `cancel` is set.
// Any thread.
ThumbnailMeshes make_thumbnail_meshes(const TreeTemplate& tree, const std::atomic<bool>* cancel);

// The key a thumbnail is kept under: a 64-bit FNV-1a hash of the text, the thumbnail's size
// and the drawing's version (a changed look is drawn again).
std::uint64_t thumbnail_key(std::string_view text);

// Where thumbnails persist: $XDG_CACHE_HOME/sylva/thumbnails, else ~/.cache/sylva/thumbnails;
// empty when neither is set (memory only).
std::filesystem::path thumbnail_cache_folder();

class TemplateThumbnails {
  public:
    enum class Status {
        Waiting,  // queued for the worker
        Meshed,   // meshes made, waiting for the window to draw them
        Ready,    // pixels there
        Failed,   // the template did not grow: the placeholder stays
    };
    struct Entry {
        std::uint64_t key = 0;
        Status status = Status::Waiting;
        // RGBA, kTemplateThumbnailSize squared, the bottom row first (as GL reads them).
        std::vector<std::uint8_t> pixels;
        std::string error;
    };
    using MakeMeshes =
        std::function<ThumbnailMeshes(const TreeTemplate&, const std::atomic<bool>* cancel)>;

    // `folder`: where the images persist (empty: memory only). `make` grows a template
    // (tests count its calls); `wake` is called from the worker when meshes are ready.
    explicit TemplateThumbnails(std::filesystem::path folder,
                                MakeMeshes make = make_thumbnail_meshes,
                                std::function<void()> wake = {});
    ~TemplateThumbnails();  // cancels the worker and joins it
    TemplateThumbnails(const TemplateThumbnails&) = delete;
    TemplateThumbnails& operator=(const TemplateThumbnails&) = delete;

    // The picker opened with these templates: one already known under the same key is kept;
    // one on disk under its key is read; the others are queued for the worker. Cheap to call
    // again (every frame the picker is open).
    void request(const std::vector<ThumbnailSource>& templates);

    // The next template whose meshes wait to be drawn (its name), or nullopt. UI thread.
    std::optional<std::pair<std::string, ThumbnailMeshes>> take_meshed();
    // The window drew `name`'s meshes: the pixels are kept and written to the folder.
    void store(const std::string& name, std::vector<std::uint8_t> pixels);

    // `name`'s entry, or null when it was never requested.
    const Entry* find(const std::string& name) const;
    // True while any requested thumbnail is not Ready or Failed.
    bool busy() const;
    // Holds the worker before its next template (true while a generation runs).
    void set_paused(bool paused);

    // How many times `make` ran and images were read from the folder (for tests).
    int made() const { return made_.load(); }
    int read_from_disk() const { return read_; }

  private:
    void work(std::stop_token stop);
    std::filesystem::path file_of(std::uint64_t key) const;
    bool read_file(std::uint64_t key, std::vector<std::uint8_t>& pixels) const;

    std::filesystem::path folder_;
    MakeMeshes make_;
    std::function<void()> wake_;
    std::map<std::string, Entry, std::less<>> entries_;  // UI thread only

    // Shared with the worker, under mutex_.
    mutable std::mutex mutex_;
    std::condition_variable_any changed_;
    struct Queued {
        std::string name;
        std::uint64_t key;
        TreeTemplate tree;
    };
    std::deque<Queued> queue_;
    struct Made {
        std::string name;
        std::uint64_t key;
        std::optional<ThumbnailMeshes> meshes;  // nullopt: failed, `error` says why
        std::string error;
    };
    std::vector<Made> done_;
    std::deque<Made> pending_;  // meshes to draw; UI thread only
    bool paused_ = false;
    std::atomic<bool> cancel_{false};
    std::atomic<int> made_{0};
    int read_ = 0;
    std::jthread worker_;  // last: joined before the members it uses go
};

}  // namespace sylva::studio
