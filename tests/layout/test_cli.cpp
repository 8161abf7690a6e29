// `sylva layout`: files for every variation and the sheet, grammars that generate, usage
// errors exit 2, bad input throws, jobs over the limits are refused before they run, and a
// failed job leaves no folder behind.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "app/layout_cli.h"
#include "core/errors.h"

namespace sylva {
namespace {

namespace fs = std::filesystem;

struct Null {
    std::FILE* f = std::fopen("/dev/null", "w");
    ~Null() { std::fclose(f); }
};

fs::path scratch(const std::string& tag) {
    const fs::path dir =
        fs::temp_directory_path() / ("sylva_layout_" + tag + "_" + std::to_string(::getpid()));
    fs::remove_all(dir);
    return dir;
}

TEST(LayoutCli, GenerateWritesJsonAndSvgForEveryVariation) {
    const fs::path dir = scratch("cli");
    Null null;
    EXPECT_EQ(
        run_layout_cli({"layout", "generate", "village", "--count", "3", "--seed", "5", "--size",
                        "12", "--sheet", (dir / "sheet.svg").string(), "-o", dir.string()},
                       null.f, null.f),
        0);
    for (const char* f : {"layout_000.json", "layout_000.svg", "layout_002.json", "sheet.svg"})
        EXPECT_TRUE(fs::exists(dir / f)) << f;
    EXPECT_FALSE(fs::exists(dir / "layout_003.json"));
    const fs::path grammar = dir / "g.json";
    EXPECT_EQ(
        run_layout_cli({"layout", "derive", "l_shape", "-o", grammar.string()}, null.f, null.f), 0);
    EXPECT_EQ(run_layout_cli({"layout", "generate", grammar.string(), "--count", "2", "-o",
                              (dir / "g").string()},
                             null.f, null.f),
              0);
    EXPECT_TRUE(fs::exists(dir / "g" / "layout_001.svg"));
    EXPECT_THROW(run_layout_cli({"layout", "derive", "no_such_example", "-o", grammar.string()},
                                null.f, null.f),
                 InputError);
    fs::remove_all(dir);
}

TEST(LayoutCli, UsageErrorsExitTwo) {
    Null null;
    for (const std::vector<std::string>& args : std::vector<std::vector<std::string>>{
             {"layout", "generate", "square", "--bogus", "-o", "x"},
             {"layout", "generate", "village", "--count", "0", "-o", "x"},
             {"layout", "generate", "village", "--size", "9..3", "-o", "x"},
             {"layout", "generate", "village", "--length", "meadow", "-o", "x"},
             {"layout", "derive", "village", "--count", "3", "-o", "x"},
             {"layout", "frobnicate"}})
        EXPECT_EQ(run_layout_cli(args, null.f, null.f), 2) << args[2];
}

TEST(LayoutCli, UnknownEdgeClassesAndJobsOverTheLimitsAreRefused) {
    const fs::path dir = scratch("limits");
    Null null;
    try {
        run_layout_cli(
            {"layout", "generate", "village", "--length", "swamp/outside=1..2", "-o", dir.string()},
            null.f, null.f);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("meadow/outside"), std::string::npos) << e.what();
    }
    try {
        run_layout_cli({"layout", "generate", "village", "--count", "100000", "--size", "100000",
                        "-o", dir.string()},
                       null.f, null.f);
        ADD_FAILURE() << "accepted";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("estimated"), std::string::npos) << e.what();
        EXPECT_NE(std::string(e.what()).find("--max-seconds"), std::string::npos) << e.what();
    }
    EXPECT_FALSE(fs::exists(dir));  // refused before any folder was made for it
    fs::remove_all(dir);
}

// The output folder is made or refused before any layout is derived, and a generate that
// fails leaves no folder it made.
TEST(LayoutCli, TheOutputFolderIsRefusedFirstAndNotLeftBehind) {
    const fs::path dir = scratch("out");
    fs::create_directories(dir);
    Null null;
    { std::ofstream(dir / "plain") << "x"; }
    const fs::path under_file = dir / "plain" / "out";
    try {
        run_layout_cli({"layout", "generate", "no_such_example", "-o", under_file.string()}, null.f,
                       null.f);
        ADD_FAILURE() << "accepted";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find(under_file.string()), std::string::npos) << e.what();
    }
    const fs::path made = dir / "a" / "b";
    EXPECT_THROW(run_layout_cli({"layout", "generate", "no_such_example", "-o", made.string()},
                                null.f, null.f),
                 InputError);
    EXPECT_FALSE(fs::exists(dir / "a"));
    fs::remove_all(dir);
}

}  // namespace
}  // namespace sylva
