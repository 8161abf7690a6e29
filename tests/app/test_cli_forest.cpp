// `sylva batch` and `sylva forest` as scripts see them: exit codes, files, shards, and an
// interrupted batch leaving nothing.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/helpers.h"

namespace {

namespace fs = std::filesystem;

using sylva::test::read_file;
using Result = sylva::test::CommandResult;

// `seconds` > 0: killed after that long (a hang fails the test instead of stalling it).
Result run(const std::string& args, int seconds = 0) {
    return sylva::test::run_command(std::string(SYLVA_BINARY_DIR) + "/app/sylva " + args, seconds);
}

using CliForest = sylva::test::TempFolderTest;

TEST_F(CliForest, BatchUsageErrors) {
    EXPECT_EQ(run("batch -t spruce -o " + path("b")).code, 2);  // no --count
    EXPECT_EQ(run("batch -t spruce --count 2").code, 2);        // no -o
    EXPECT_EQ(run("batch -t spruce --count 2 --shard 5/4 -o " + path("b")).code, 2);
    EXPECT_EQ(run("batch -t spruce --count 2 --jitter 2 -o " + path("b")).code, 2);
    EXPECT_EQ(run("batch -t spruce --count 2 --bogus -o " + path("b")).code, 2);
    EXPECT_EQ(run("batch -t nosuchtree --count 2 -o " + path("b")).code, 3);
    EXPECT_FALSE(fs::exists(path("b")));
}

TEST_F(CliForest, BatchShardWritesItsShare) {
    const Result r =
        run("batch -t spruce --count 5 --budget 150 --shard 2/2 --format obj -o " + path("b"));
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("batch: 2/2 spruce_0003.obj"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::exists(path("b/spruce_0001.obj")));
    EXPECT_TRUE(fs::exists(path("b/spruce_0001.mtl")));
    EXPECT_TRUE(fs::exists(path("b/spruce_0003.obj")));
    EXPECT_FALSE(fs::exists(path("b/spruce_0000.obj")));
    EXPECT_NE(read_file(path("b/manifest_2of2.json")).find("\"spruce_0003.obj\""),
              std::string::npos);
}

TEST_F(CliForest, ForestWritesSceneAndPlacements) {
    const Result r =
        run("forest --area 30x20 --species spruce,pine:2 --variants 1 --budget 150 "
            "--spacing 4 -o " +
            path("f.glb"));
    ASSERT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("f.glb")));
    const std::string csv = read_file(path("f.placements.csv"));
    EXPECT_EQ(csv.rfind("index,species,variant,x,y,z,yaw_degrees,scale,age,class\n", 0), 0u);
    EXPECT_NE(csv.find(",pine,pine_v0,"), std::string::npos);
    EXPECT_TRUE(fs::exists(path("f.placements.json")));
    EXPECT_EQ(run("forest --area 30 -o " + path("g.glb")).code, 2);
    EXPECT_EQ(run("forest --species spruce:0 -o " + path("g.glb")).code, 2);  // a flag's value
    { std::ofstream(path("ground.json")) << "{\"polygons\": [\n  {\"points\": 3}\n]}"; }
    const Result bad = run("forest --ground " + path("ground.json") + " -o " + path("g.glb"));
    EXPECT_EQ(bad.code, 3);
    EXPECT_NE(bad.output.find("polygons[0]"), std::string::npos) << bad.output;
    EXPECT_FALSE(fs::exists(path("g.glb")));
}

TEST_F(CliForest, ForestPlantsALayoutPlan) {
    const std::string plan = std::string(SYLVA_SOURCE_DIR) + "/tests/forest/data/farm_plan.json";
    const Result r = run("forest --layout " + plan +
                         " --layout-scale 3 --species spruce --orchard-species birch "
                         "--variants 1 --budget 150 --row-spacing 5 -o " +
                         path("farm.glb"));
    ASSERT_EQ(r.code, 0) << r.output;
    const std::string csv = read_file(path("farm.placements.csv"));
    EXPECT_NE(csv.find(",spruce,spruce_v0,"), std::string::npos);
    EXPECT_NE(csv.find(",birch,birch_orchard_v0,"), std::string::npos);
    EXPECT_NE(csv.find(",orchard\n"), std::string::npos);
    EXPECT_EQ(csv.find(",path\n"), std::string::npos);
    EXPECT_EQ(csv.find(",meadow\n"), std::string::npos);
    EXPECT_EQ(run("forest --layout-scale 3 -o " + path("g.glb")).code, 2);  // without --layout
    EXPECT_EQ(run("forest --layout " + plan + " --layout-scale 0 -o " + path("g.glb")).code, 2);
    EXPECT_EQ(run("forest --layout " + plan + " --tree-spacing -1 -o " + path("g.glb")).code, 2);
    EXPECT_FALSE(fs::exists(path("g.glb")));
}

// The trees are generated before any file is staged: a SIGINT then leaves no file at all,
// and the process still dies by the signal.
TEST_F(CliForest, AnInterruptedBatchLeavesNothing) {
    const std::string binary = std::string(SYLVA_BINARY_DIR) + "/app/sylva";
    const std::string out = path("b");
    const pid_t child = ::fork();
    ASSERT_GE(child, 0);
    if (child == 0) {
        std::freopen("/dev/null", "w", stderr);
        std::freopen("/dev/null", "w", stdout);
        ::execl(binary.c_str(), binary.c_str(), "batch", "-t", "oak", "--count", "40", "-o",
                out.c_str(), static_cast<char*>(nullptr));
        ::_exit(127);
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(400));
    ::kill(child, SIGINT);
    int status = 0;
    ::waitpid(child, &status, 0);
    ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
    EXPECT_EQ(WTERMSIG(status), SIGINT);
    EXPECT_FALSE(fs::exists(out));  // nor the folder made for it
}

// A batch or forest is estimated as a whole before any work: else a billion trees would end
// in bad_alloc, a forest of many variants would be checked one variant at a time, and an
// orchard spacing of 1e-9 m would hang. Each is refused at once (exit 3) with the figure.
TEST_F(CliForest, ManyTreeJobsAreRefusedWholeBeforeAnyWork) {
    const auto start = std::chrono::steady_clock::now();
    const Result billion = run("batch -t spruce --count 1000000000 -o " + path("b"), 20);
    EXPECT_EQ(billion.code, 3) << billion.output;
    EXPECT_NE(billion.output.find("this batch of 1e+09 trees is estimated at"), std::string::npos)
        << billion.output;
    EXPECT_NE(billion.output.find("--max-seconds"), std::string::npos) << billion.output;
    EXPECT_EQ(billion.output.find("batch: 1/"), std::string::npos) << billion.output;
    EXPECT_FALSE(fs::exists(path("b")));

    // --max-seconds holds for the whole batch and forest, not for each tree.
    const Result hundred = run("batch -t spruce --count 100 --max-seconds 1 -o " + path("b"), 20);
    EXPECT_EQ(hundred.code, 3) << hundred.output;
    EXPECT_NE(hundred.output.find("this batch of 100 trees"), std::string::npos) << hundred.output;
    const Result variants =
        run("forest --area 30x20 --species spruce,pine --variants 50 --max-seconds 1 -o " +
                path("f.glb"),
            20);
    EXPECT_EQ(variants.code, 3) << variants.output;
    EXPECT_NE(variants.output.find("100 variants"), std::string::npos) << variants.output;
    EXPECT_EQ(variants.output.find("forest: variant"), std::string::npos) << variants.output;

    const std::string plan = std::string(SYLVA_SOURCE_DIR) + "/tests/forest/data/farm_plan.json";
    const Result orchard =
        run("forest --layout " + plan + " --tree-spacing 1e-9 -o " + path("f.glb"), 20);
    EXPECT_EQ(orchard.code, 3) << orchard.output;
    EXPECT_NE(orchard.output.find("trees"), std::string::npos) << orchard.output;
    EXPECT_NE(orchard.output.find("limit"), std::string::npos) << orchard.output;
    EXPECT_FALSE(fs::exists(path("f.glb")));
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(20));
}

// The output folder is made, or refused with exit 4 naming it, before any tree is generated
// (a batch found out only after every tree); a job that fails leaves no folder it made.
TEST_F(CliForest, OutputFoldersAreRefusedFirstAndNotLeftBehind) {
    { std::ofstream(path("plain")) << "x"; }
    const std::string blocked = path("plain") + "/b";
    const Result batch = run("batch -t spruce --count 3 -o " + blocked, 60);
    EXPECT_EQ(batch.code, 4) << batch.output;
    EXPECT_NE(batch.output.find(blocked), std::string::npos) << batch.output;
    EXPECT_EQ(batch.output.find("batch: 1/"), std::string::npos) << batch.output;
    const Result forest =
        run("forest --area 20x20 --variants 1 -o " + path("plain") + "/f/forest.glb", 60);
    EXPECT_EQ(forest.code, 4) << forest.output;
    EXPECT_NE(forest.output.find(path("plain") + "/f"), std::string::npos) << forest.output;
    EXPECT_EQ(forest.output.find("forest: variant"), std::string::npos) << forest.output;
    const Result layout = run("layout generate village --count 1 -o " + blocked, 60);
    EXPECT_EQ(layout.code, 4) << layout.output;
    EXPECT_NE(layout.output.find(blocked), std::string::npos) << layout.output;

    // A grammar that fails only when grown: the batch fails after its folder was made.
    { std::ofstream(path("bad.txt")) << "axiom: F\nF -> F[\n"; }
    const Result bad = run("batch -t " + path("bad.txt") + " --count 2 -o " + path("new/b"), 60);
    EXPECT_EQ(bad.code, 3) << bad.output;
    EXPECT_FALSE(fs::exists(path("new"))) << bad.output;
}

// A flag's bad value is a usage error (exit 2) whether it is no number or out of range
// (--spacing abc was 2, --spacing 0 was 3), and flags that say the same thing twice over
// are refused naming both (--area with --layout planted the layout silently).
TEST_F(CliForest, ForestFlagsAreUsageErrorsNamingTheFlags) {
    const std::string plan = std::string(SYLVA_SOURCE_DIR) + "/tests/forest/data/farm_plan.json";
    const std::string out = " -o " + path("g.glb");
    for (const std::string bad :
         {"--spacing abc", "--spacing 0", "--spacing -4", "--density 0", "--stand-size 0",
          "--min-age 2", "--scale-jitter 1", "--variants 0", "--row-spacing 0", "--tree-spacing 0",
          "--orchard-margin -1", "--meadow-density -1", "--species oak:-1"}) {
        const Result r = run("forest " + bad + out);
        EXPECT_EQ(r.code, 2) << bad << ": " << r.output;
        EXPECT_NE(r.output.find(bad.substr(0, bad.find(' '))), std::string::npos) << r.output;
    }
    const Result area_layout = run("forest --area 30x20 --layout " + plan + out);
    EXPECT_EQ(area_layout.code, 2) << area_layout.output;
    EXPECT_NE(area_layout.output.find("--area and --layout"), std::string::npos)
        << area_layout.output;
    const Result ground_area = run("forest --ground " + plan + " --area 30x20" + out);
    EXPECT_EQ(ground_area.code, 2) << ground_area.output;
    EXPECT_NE(ground_area.output.find("--ground and --area"), std::string::npos)
        << ground_area.output;
    const Result count = run("forest --density 50 --trees 10" + out);
    EXPECT_EQ(count.code, 2) << count.output;
    EXPECT_NE(count.output.find("--density and --trees"), std::string::npos) << count.output;
    EXPECT_FALSE(fs::exists(path("g.glb")));
}

// Every usage error of `sylva layout` exits 2, as the other commands' do (bad flag values
// exited 3).
TEST_F(CliForest, LayoutUsageErrorsExitTwo) {
    const std::string out = " -o " + path("l");
    for (const std::string bad : {"generate village --count abc", "generate village --count 0",
                                  "generate village --steps -1", "generate village --seed x",
                                  "derive village --max-graphs 0", "generate village --bogus",
                                  "generate", "frobnicate village"}) {
        const Result r = run("layout " + bad + out);
        EXPECT_EQ(r.code, 2) << bad << ": " << r.output;
    }
    EXPECT_FALSE(fs::exists(path("l")));
}

}  // namespace
