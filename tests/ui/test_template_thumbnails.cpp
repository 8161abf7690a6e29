// The template picker's thumbnail cache (ui/state/template_thumbnails.h) without a window: a
// template is grown once; asking again, or a new studio with the same cache folder, reuses
// its image; a template whose text changed is grown and drawn again. The growing and the
// drawing are stand-ins that count their calls.
#include <gtest/gtest.h>

#include <atomic>
#include <chrono>
#include <filesystem>
#include <string>
#include <thread>
#include <vector>

#include "tree/template_library.h"
#include "ui/state/template_thumbnails.h"

namespace sylva::studio {
namespace {

// Stands in for the growth: one triangle, and a count of the templates grown.
ThumbnailMeshes one_triangle(const TreeTemplate&, const std::atomic<bool>*) {
    ThumbnailMeshes meshes;
    meshes.trunk.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}};
    meshes.trunk.triangles = {{0, 1, 2}};
    return meshes;
}

// Stands in for the window: draws every template whose meshes are made, as each frame does,
// until none is left to make. False when that takes more than a few seconds.
bool draw_all(TemplateThumbnails& thumbnails, std::uint8_t shade) {
    const auto until = std::chrono::steady_clock::now() + std::chrono::seconds(20);
    while (thumbnails.busy()) {
        if (std::chrono::steady_clock::now() > until) return false;
        while (auto meshed = thumbnails.take_meshed())
            thumbnails.store(meshed->first, std::vector<std::uint8_t>(
                                                static_cast<std::size_t>(kTemplateThumbnailSize) *
                                                    kTemplateThumbnailSize * 4,
                                                shade));
        std::this_thread::sleep_for(std::chrono::milliseconds(1));
    }
    return true;
}

std::vector<ThumbnailSource> sources(int count) {
    std::vector<ThumbnailSource> out;
    for (const TreeTemplate* t : builtin_templates()) {
        if (static_cast<int>(out.size()) == count) break;
        out.push_back({t->name, std::string(builtin_template_text(t->name)), *t});
    }
    return out;
}

struct Folder {
    std::filesystem::path path =
        std::filesystem::temp_directory_path() /
        ("sylva_test_thumbnails_" +
         std::to_string(::testing::UnitTest::GetInstance()->random_seed()));
    Folder() { std::filesystem::remove_all(path); }
    ~Folder() { std::filesystem::remove_all(path); }
};

TEST(TemplateThumbnails, AreMadeOnceAndReusedUntilTheTemplateChanges) {
    const Folder folder;
    std::vector<ThumbnailSource> templates = sources(3);
    ASSERT_EQ(templates.size(), 3u);
    {
        TemplateThumbnails thumbnails(folder.path, one_triangle);
        thumbnails.request(templates);
        EXPECT_TRUE(thumbnails.busy());
        EXPECT_EQ(thumbnails.find(templates[0].name)->status,
                  TemplateThumbnails::Status::Waiting);  // the placeholder shows meanwhile
        ASSERT_TRUE(draw_all(thumbnails, 7));
        EXPECT_EQ(thumbnails.made(), 3);
        for (const ThumbnailSource& t : templates) {
            ASSERT_NE(thumbnails.find(t.name), nullptr);
            EXPECT_EQ(thumbnails.find(t.name)->status, TemplateThumbnails::Status::Ready);
        }
        thumbnails.request(templates);  // the picker opened again: nothing to make
        EXPECT_FALSE(thumbnails.busy());
        EXPECT_EQ(thumbnails.made(), 3);
    }
    // The next studio reads them from the folder.
    {
        TemplateThumbnails thumbnails(folder.path, one_triangle);
        thumbnails.request(templates);
        EXPECT_FALSE(thumbnails.busy());
        EXPECT_EQ(thumbnails.made(), 0);
        EXPECT_EQ(thumbnails.read_from_disk(), 3);
        EXPECT_EQ(thumbnails.find(templates[1].name)->pixels.at(0), 7);
    }
    // One template's text changed: it alone is made and drawn again, under a new key.
    {
        templates[1].text += "\n# edited\n";
        TemplateThumbnails thumbnails(folder.path, one_triangle);
        thumbnails.request(templates);
        EXPECT_TRUE(thumbnails.busy());
        ASSERT_TRUE(draw_all(thumbnails, 9));
        EXPECT_EQ(thumbnails.made(), 1);
        EXPECT_EQ(thumbnails.read_from_disk(), 2);
        EXPECT_EQ(thumbnails.find(templates[1].name)->pixels.at(0), 9);
        EXPECT_EQ(thumbnails.find(templates[0].name)->pixels.at(0), 7);
    }
}

// The worker waits while a generation runs, and a template that fails to grow keeps its
// placeholder with the reason.
TEST(TemplateThumbnails, WaitWhilePausedAndKeepTheFailure) {
    std::atomic<int> calls = 0;
    TemplateThumbnails thumbnails({}, [&](const TreeTemplate& t, const std::atomic<bool>* c) {
        ++calls;
        if (t.name == sources(2)[1].name) throw std::runtime_error("does not grow");
        return one_triangle(t, c);
    });
    thumbnails.set_paused(true);
    thumbnails.request(sources(2));
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
    EXPECT_EQ(calls.load(), 0);
    thumbnails.set_paused(false);
    ASSERT_TRUE(draw_all(thumbnails, 1));
    EXPECT_EQ(calls.load(), 2);
    const auto* failed = thumbnails.find(sources(2)[1].name);
    EXPECT_EQ(failed->status, TemplateThumbnails::Status::Failed);
    EXPECT_EQ(failed->error, "does not grow");
}

// The real growth gives a closed game mesh small enough for a thumbnail.
TEST(TemplateThumbnails, TheDefaultTreeGrowsAtAThumbnailsBudget) {
    const TreeTemplate& tree = *builtin_templates().front();
    const ThumbnailMeshes meshes = make_thumbnail_meshes(tree, nullptr);
    EXPECT_GT(meshes.trunk.triangles.size(), 0u);
    EXPECT_LE(meshes.trunk.triangles.size() + meshes.crown.triangles.size(), 300u);
}

}  // namespace
}  // namespace sylva::studio
