#include "ui/state/template_thumbnails.h"

#include <cstdio>
#include <cstdlib>
#include <exception>
#include <fstream>
#include <iterator>
#include <utility>

#include "core/atomic_file.h"
#include "core/cancel.h"
#include "core/color_variation.h"
#include "export/export_tree.h"
#include "tree/pipeline.h"
#include "ui/state/thread_priority.h"

namespace sylva::studio {
namespace {

// A thumbnail shows the silhouette and colours; a small game mesh draws them and grows fast.
constexpr std::size_t kThumbnailBudget = 300;
// Bumped when the drawing changes, so the cached images are drawn again.
constexpr std::string_view kDrawingVersion = "template-thumbnail 1";
constexpr std::string_view kFileMagic = "sylva-thumbnail";

constexpr std::size_t pixel_bytes() {
    return static_cast<std::size_t>(kTemplateThumbnailSize) * kTemplateThumbnailSize * 4;
}

std::uint64_t fnv1a(std::uint64_t hash, std::string_view bytes) {
    for (const char c : bytes) {
        hash ^= static_cast<unsigned char>(c);
        hash *= 0x100000001b3ull;
    }
    return hash;
}

}  // namespace

ThumbnailMeshes make_thumbnail_meshes(const TreeTemplate& tree, const std::atomic<bool>* cancel) {
    MeshOptions mesh;
    mesh.budget = kThumbnailBudget;
    mesh.cancel = cancel;
    mesh.threads = 1;  // beside the edited tree's job, never in its way
    FinishSettings finish;
    finish.budget.total = kThumbnailBudget;
    finish.decimate.cancel = cancel;
    const Tree generated = generate_tree(tree, mesh);
    FinishedTree finished = finish_tree(generated, finish);
    ThumbnailMeshes out;
    out.trunk = std::move(finished.levels.at(0).trunk);
    out.crown = std::move(finished.levels.at(0).crown);
    out.leaves = std::move(finished.levels.at(0).leaves);
    out.colors = tree_colors(tree);
    return out;
}

std::uint64_t thumbnail_key(std::string_view text) {
    std::uint64_t hash = fnv1a(0xcbf29ce484222325ull, kDrawingVersion);
    hash = fnv1a(hash, std::to_string(kTemplateThumbnailSize));
    return fnv1a(hash, text);
}

std::filesystem::path thumbnail_cache_folder() {
    if (const char* cache = std::getenv("XDG_CACHE_HOME"); cache && *cache)
        return std::filesystem::path(cache) / "sylva" / "thumbnails";
    if (const char* home = std::getenv("HOME"); home && *home)
        return std::filesystem::path(home) / ".cache" / "sylva" / "thumbnails";
    return {};
}

TemplateThumbnails::TemplateThumbnails(std::filesystem::path folder, MakeMeshes make,
                                       std::function<void()> wake)
    : folder_(std::move(folder)), make_(std::move(make)), wake_(std::move(wake)) {}

TemplateThumbnails::~TemplateThumbnails() {
    cancel_.store(true);
    if (worker_.joinable()) {
        worker_.request_stop();
        changed_.notify_all();
        worker_.join();
    }
}

std::filesystem::path TemplateThumbnails::file_of(std::uint64_t key) const {
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.rgba", static_cast<unsigned long long>(key));
    return folder_ / name;
}

// The file: "sylva-thumbnail <size>\n", then the RGBA bytes. Anything else is a miss.
bool TemplateThumbnails::read_file(std::uint64_t key, std::vector<std::uint8_t>& pixels) const {
    if (folder_.empty()) return false;
    std::ifstream in(file_of(key), std::ios::binary);
    if (!in) return false;
    std::string magic;
    int size = 0;
    in >> magic >> size;
    if (magic != kFileMagic || size != kTemplateThumbnailSize || in.get() != '\n') return false;
    std::vector<std::uint8_t> bytes(pixel_bytes());
    in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
    if (static_cast<std::size_t>(in.gcount()) != bytes.size() || in.peek() != EOF) return false;
    pixels = std::move(bytes);
    return true;
}

void TemplateThumbnails::request(const std::vector<ThumbnailSource>& templates) {
    bool queued = false;
    for (const ThumbnailSource& source : templates) {
        const std::uint64_t key = thumbnail_key(source.text);
        auto found = entries_.find(source.name);
        if (found != entries_.end() && found->second.key == key) continue;  // known
        Entry entry;
        entry.key = key;
        if (read_file(key, entry.pixels)) {
            entry.status = Status::Ready;
            ++read_;
        } else {
            const std::lock_guard lock(mutex_);
            queue_.push_back({source.name, key, source.tree});
            queued = true;
        }
        entries_.insert_or_assign(source.name, std::move(entry));
    }
    if (!queued) return;
    if (!worker_.joinable()) worker_ = std::jthread([this](std::stop_token stop) { work(stop); });
    changed_.notify_all();
}

void TemplateThumbnails::work(std::stop_token stop) {
    lower_thread_priority();
    while (true) {
        Queued next;
        {
            std::unique_lock lock(mutex_);
            if (!changed_.wait(lock, stop, [this] { return !paused_ && !queue_.empty(); }))
                return;  // stop requested
            next = std::move(queue_.front());
            queue_.pop_front();
        }
        Made made{next.name, next.key, std::nullopt, {}};
        try {
            made.meshes = make_(next.tree, &cancel_);
            made_.fetch_add(1);
        } catch (const Cancelled&) {
            return;
        } catch (const std::exception& e) {
            made.error = e.what();
        }
        {
            const std::lock_guard lock(mutex_);
            done_.push_back(std::move(made));
        }
        if (wake_) wake_();
    }
}

std::optional<std::pair<std::string, ThumbnailMeshes>> TemplateThumbnails::take_meshed() {
    std::vector<Made> done;
    {
        const std::lock_guard lock(mutex_);
        done.swap(done_);
    }
    for (Made& made : done) {
        auto found = entries_.find(made.name);
        if (found == entries_.end() || found->second.key != made.key) continue;  // replaced
        Entry& entry = found->second;
        if (made.meshes) {
            entry.status = Status::Meshed;
            pending_.push_back(std::move(made));
        } else {
            entry.status = Status::Failed;
            entry.error = made.error;
        }
    }
    while (!pending_.empty()) {
        Made next = std::move(pending_.front());
        pending_.pop_front();
        const Entry* entry = find(next.name);
        if (!entry || entry->key != next.key) continue;  // the template changed meanwhile
        return std::pair{std::move(next.name), std::move(*next.meshes)};
    }
    return std::nullopt;
}

void TemplateThumbnails::store(const std::string& name, std::vector<std::uint8_t> pixels) {
    auto found = entries_.find(name);
    if (found == entries_.end() || pixels.size() != pixel_bytes()) return;
    Entry& entry = found->second;
    entry.pixels = std::move(pixels);
    entry.status = Status::Ready;
    if (folder_.empty()) return;
    try {
        std::filesystem::create_directories(folder_);
        write_file_atomically(file_of(entry.key), [&](std::ostream& out) {
            out << kFileMagic << ' ' << kTemplateThumbnailSize << '\n';
            out.write(reinterpret_cast<const char*>(entry.pixels.data()),
                      static_cast<std::streamsize>(entry.pixels.size()));
        });
    } catch (const std::exception&) {
        // A cache that cannot be written only costs drawing the thumbnail again next time.
    }
}

const TemplateThumbnails::Entry* TemplateThumbnails::find(const std::string& name) const {
    auto found = entries_.find(name);
    return found == entries_.end() ? nullptr : &found->second;
}

bool TemplateThumbnails::busy() const {
    for (const auto& [name, entry] : entries_)
        if (entry.status == Status::Waiting || entry.status == Status::Meshed) return true;
    return false;
}

void TemplateThumbnails::set_paused(bool paused) {
    {
        const std::lock_guard lock(mutex_);
        if (paused_ == paused) return;
        paused_ = paused;
    }
    changed_.notify_all();
}

}  // namespace sylva::studio
