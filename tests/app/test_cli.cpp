// The `sylva` command line as scripts see it: exit codes, messages, files left behind.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "tests/helpers.h"

namespace {

namespace fs = std::filesystem;

using Result = sylva::test::CommandResult;

Result run(const std::string& args) {
    return sylva::test::run_command(std::string(SYLVA_BINARY_DIR) + "/app/sylva " + args);
}

using Cli = sylva::test::TempFolderTest;

TEST_F(Cli, ExportWritesAClosedObjAndSaysWhere) {
    Result r = run("export -o " + path("tree.obj"));
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("tree.obj")));
    EXPECT_NE(r.output.find("tree.obj"), std::string::npos);
    EXPECT_NE(r.output.find("closed"), std::string::npos) << r.output;
    EXPECT_EQ(r.output.find("NOT closed"), std::string::npos) << r.output;
}

TEST_F(Cli, HelpAndUsageErrors) {
    Result help = run("--help");
    EXPECT_EQ(help.code, 0);
    EXPECT_NE(help.output.find("sylva export"), std::string::npos);
    EXPECT_NE(help.output.find("trunk_resolution"), std::string::npos);
    EXPECT_EQ(run("").code, 2);
    EXPECT_EQ(run("frobnicate").code, 2);
    EXPECT_EQ(run("export").code, 2);  // no -o
    EXPECT_EQ(run("export --bogus -o x.obj").code, 2);
    EXPECT_EQ(run("export -o " + path("x.dae")).code, 2);  // no such format
    EXPECT_EQ(run("export --format fbx -o " + path("x.obj")).code, 2);
}

// derive takes -o like every other command (it was ignored and the word went to stdout).
TEST_F(Cli, DeriveWritesTheWordToOutput) {
    const Result printed = run("derive -t spruce --steps 2");
    ASSERT_EQ(printed.code, 0) << printed.output;
    const Result written = run("derive -t spruce --steps 2 -o " + path("word.txt"));
    ASSERT_EQ(written.code, 0) << written.output;
    std::ifstream in(path("word.txt"));
    std::stringstream word;
    word << in.rdbuf();
    EXPECT_EQ(word.str(), printed.output);
    EXPECT_EQ(written.output.find(word.str()), std::string::npos);  // not on stdout as well
    fs::create_directories(path("folder"));
    EXPECT_EQ(run("derive -t spruce -o " + path("folder")).code, 4);
}

// Help after a command is that command's usage, exit 0 (it was "unknown option '--help'").
TEST_F(Cli, HelpAfterACommandPrintsItsUsage) {
    const Result exporting = run("export --help");
    EXPECT_EQ(exporting.code, 0) << exporting.output;
    EXPECT_NE(exporting.output.find("sylva export   [-t NAME|FILE]"), std::string::npos)
        << exporting.output;
    EXPECT_NE(exporting.output.find("--budget N"), std::string::npos) << exporting.output;
    EXPECT_EQ(exporting.output.find("sylva batch"), std::string::npos) << exporting.output;
    EXPECT_FALSE(fs::exists(path("x.obj")));
    const Result skeleton = run("skeleton -t oak -h");
    EXPECT_EQ(skeleton.code, 0) << skeleton.output;
    EXPECT_NE(skeleton.output.find("sylva skeleton"), std::string::npos) << skeleton.output;
    const Result batch = run("batch --help");
    EXPECT_EQ(batch.code, 0) << batch.output;
    EXPECT_NE(batch.output.find("--count N"), std::string::npos) << batch.output;
    EXPECT_EQ(batch.output.find("sylva forest"), std::string::npos) << batch.output;
    const Result forest = run("forest --help");
    EXPECT_EQ(forest.code, 0) << forest.output;
    EXPECT_NE(forest.output.find("--tree-spacing"), std::string::npos) << forest.output;
    const Result layout = run("layout generate --help");
    EXPECT_EQ(layout.code, 0) << layout.output;
    EXPECT_NE(layout.output.find("sylva layout generate"), std::string::npos) << layout.output;
    EXPECT_EQ(run("frobnicate --help").code, 2);
}

// A budget past the triangle_budget range (0 to 10^7) is a usage error: above about 1e18
// it overflowed and acted like a budget of 1.
TEST_F(Cli, ABudgetPastItsRangeIsAUsageErrorNamingTheRange) {
    for (const char* flag : {"--budget", "--budget-trunk", "--budget-crown", "--budget-leaves"}) {
        Result r =
            run(std::string("export ") + flag + " 18446744073709551615 -o " + path("tree.glb"));
        EXPECT_EQ(r.code, 2) << flag << ": " << r.output;
        EXPECT_NE(r.output.find("0 to 10000000"), std::string::npos) << r.output;
    }
    EXPECT_EQ(run("export --budget 10000001 -o " + path("tree.glb")).code, 2);
    EXPECT_TRUE(listing().empty());
}

// --format ply -o x.glb wrote PLY bytes into a .glb: a known extension of another format is
// refused before any work; an extension no format claims still takes --format.
TEST_F(Cli, AFormatThatContradictsTheExtensionIsAUsageError) {
    Result r = run("export --format ply -o " + path("tree.glb"));
    EXPECT_EQ(r.code, 2) << r.output;
    EXPECT_NE(r.output.find(".ply"), std::string::npos) << r.output;
    EXPECT_TRUE(listing().empty());
    r = run("export --format glb --budget 200 -o " + path("tree.glb"));
    EXPECT_EQ(r.code, 0) << r.output;
}

TEST_F(Cli, BrokenGrammarIsExitCode3NamingFileLineAndColumnAndNoFileIsWritten) {
    { std::ofstream(path("broken.lsys")) << "axiom: F\nF -> F[+F]F\nF FF\n"; }
    Result r = run("export -t " + path("broken.lsys") + " -o " + path("tree.obj"));
    EXPECT_EQ(r.code, 3) << r.output;
    EXPECT_NE(r.output.find("broken.lsys:3:1: "), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("->"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("tree.obj")));
}

// A grammar inside a template file: errors count the file's lines, not the grammar's.
TEST_F(Cli, BrokenRuleInATemplateFileNamesTheFilesLine) {
    {
        std::ofstream(path("broken.toml")) << "# a comment\n"
                                              "name = \"broken\"\n"
                                              "\n"
                                              "grammar = '''\n"
                                              "axiom: A\n"
                                              "A -> F[+A]\n"
                                              "B FF\n"
                                              "'''\n";
    }
    Result r = run("export -t " + path("broken.toml") + " -o " + path("tree.obj"));
    EXPECT_EQ(r.code, 3) << r.output;
    EXPECT_NE(r.output.find("broken.toml:7:1: "), std::string::npos) << r.output;
    // Found while deriving: the rule on the file's line 4 divides by zero.
    {
        std::ofstream(path("zero.toml")) << "name = \"zero\"\n"
                                            "grammar = \"\"\"\n"
                                            "axiom: A\n"
                                            "A -> F(1/0)\n"
                                            "\"\"\"\n";
    }
    r = run("export -t " + path("zero.toml") + " -o " + path("tree.obj"));
    EXPECT_EQ(r.code, 3) << r.output;
    EXPECT_NE(r.output.find("zero.toml:4"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("division by zero"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("tree.obj")));
}

// Cost is known before work starts: a derivation that would take gigabytes is
// refused at once, naming the estimate and the overrides, and runs when they are raised.
TEST_F(Cli, CostlyWorkIsRefusedBeforeItStartsWithTheEstimateAndTheOverride) {
    { std::ofstream(path("ff.lsys")) << "axiom: !(0.1)F(0.001)\nF(l) -> F(l)F(l)\n"; }
    Result r = run("skeleton -t " + path("ff.lsys") + " --steps 21 -o " + path("s.json"));
    EXPECT_EQ(r.code, 3) << r.output;
    EXPECT_NE(r.output.find("--max-memory"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("estimated"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("s.json")));
    // A reduction's cost shows once the meshes are made: refused before it starts (the
    // trunk's surface reduced; prisms are drawn, not reduced).
    // (96 cells make more handles than the template's own 80, which bind only above 1,422
    // triangles with drop_hidden.)
    r =
        run("export -t ternary --set generations=8 --set drop_hidden=0 --set trunk_resolution=96 "
            "--set branch_style=surface --max-seconds 1 -o " +
            path("t.glb"));
    EXPECT_EQ(r.code, 3) << r.output;
    EXPECT_NE(r.output.find("handles to reduce"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("t.glb")));
}

TEST_F(Cli, BadParameterIsExitCode3NamingTheKey) {
    Result r = run("export --set trunk_taper=nan -o " + path("tree.obj"));
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.output.find("trunk_taper"), std::string::npos) << r.output;
    EXPECT_EQ(run("export -t no-such-template -o " + path("tree.obj")).code, 3);
    EXPECT_FALSE(fs::exists(path("tree.obj")));
}

// --set on the wind: the values land in each glb material's extras (what the engine kits
// read); out of range is exit 3 naming the key.
TEST_F(Cli, SetWindReachesEveryMaterial) {
    Result r =
        run("export -t birch --set wind_strength=0.6 --set wind_gust_frequency=0.5 "
            "--set wind_flutter=0.3 -o " +
            path("w.glb"));
    ASSERT_EQ(r.code, 0) << r.output;
    const std::string glb = sylva::test::read_file(path("w.glb"));
    auto count = [&](const std::string& text) {
        std::size_t n = 0;
        for (auto at = glb.find(text); at != std::string::npos; at = glb.find(text, at + 1)) ++n;
        return n;
    };
    EXPECT_EQ(count("\"sylva_wind_strength\":0.6}"), 3u) << "trunk, crown, leaves";
    EXPECT_EQ(count("\"sylva_wind_gust_frequency\":0.5,"), 3u);
    EXPECT_EQ(count("\"sylva_wind_flutter\":0.3,"), 3u);
    Result bad = run("export --set wind_flutter=1.5 -o " + path("x.glb"));
    EXPECT_EQ(bad.code, 3);
    EXPECT_NE(bad.output.find("wind_flutter"), std::string::npos) << bad.output;
}

// A folder that cannot be made (a file stands in its path) is exit 4 naming it, and nothing is
// left; a missing folder is made (tests/app/test_cli_parity.cpp).
TEST_F(Cli, UnwritablePathIsExitCode4AndLeavesNothing) {
    { std::ofstream(path("missing")) << "a file\n"; }
    Result r = run("export -o " + path("missing/dir/tree.obj"));
    EXPECT_EQ(r.code, 4) << r.output;
    EXPECT_NE(r.output.find("missing/dir"), std::string::npos) << r.output;
    EXPECT_TRUE(fs::is_regular_file(path("missing")));
    EXPECT_EQ(listing(), (std::vector<std::string>{"missing"}));
}

std::string slurp(const fs::path& path) {
    std::ifstream in(path);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(Cli, ASymlinkAtOutputIsWrittenThrough) {
    fs::create_directories(dir_ / "assets");
    { std::ofstream(path("assets/oak.obj")) << "old\n"; }
    fs::create_symlink("assets/oak.obj", dir_ / "tree.obj");
    Result r = run("export -o " + path("tree.obj"));
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_NE(r.output.find("wrote " + path("assets/oak.obj")), std::string::npos) << r.output;
    EXPECT_TRUE(fs::is_symlink(dir_ / "tree.obj"));
    EXPECT_NE(slurp(dir_ / "tree.obj").find("mtllib oak.mtl"), std::string::npos);
    EXPECT_TRUE(fs::exists(dir_ / "assets/oak.mtl"));
    EXPECT_EQ(listing(), (std::vector<std::string>{"assets", "tree.obj"}));
}

TEST_F(Cli, AFifoAtOutputIsExitCode4NamingThePath) {
    // Only a FIFO of our own: a regression run as root would replace a real /dev/null
    // (tests/core/test_file_set.cpp checks devices without writing).
    ASSERT_EQ(::mkfifo(path("tree.ply").c_str(), 0600), 0);
    Result r = run("export -o " + path("tree.ply"));
    EXPECT_EQ(r.code, 4) << r.output;
    EXPECT_NE(r.output.find("'" + path("tree.ply") + "': it is a FIFO"), std::string::npos)
        << r.output;
    EXPECT_TRUE(fs::is_fifo(path("tree.ply")));
    EXPECT_EQ(listing(), std::vector<std::string>{"tree.ply"});
}

// Runs `sylva export ARGS -o dir/OUT` with every staged file followed by a long pause (the
// test seam SYLVA_TEST_STAGING_DELAY_MS), waits until its staging folder holds a file, and
// sends `signal_number`. Returns the wait status.
int interrupt_export(const fs::path& dir, const std::vector<std::string>& args, int signal_number) {
    const pid_t child = ::fork();
    if (child == 0) {
        ::setenv("SYLVA_TEST_STAGING_DELAY_MS", "60000", 1);
        std::FILE* quiet = std::freopen("/dev/null", "w", stdout);
        (void)quiet;
        const std::string binary = std::string(SYLVA_BINARY_DIR) + "/app/sylva";
        std::vector<char*> argv{const_cast<char*>(binary.c_str())};
        for (const std::string& arg : args) argv.push_back(const_cast<char*>(arg.c_str()));
        argv.push_back(nullptr);
        ::execv(binary.c_str(), argv.data());
        ::_exit(127);
    }
    const auto staged = [&] {
        for (const auto& entry : fs::directory_iterator(dir))
            if (entry.path().filename().string().rfind(".sylva-", 0) == 0 && entry.is_directory() &&
                !fs::is_empty(entry.path()))
                return true;
        return false;
    };
    int status = 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
    while (!staged() && std::chrono::steady_clock::now() < deadline) {
        if (::waitpid(child, &status, WNOHANG) == child) return status;  // ended on its own
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    ::kill(child, signal_number);
    ::waitpid(child, &status, 0);
    return status;
}

// Interrupted, the CLI leaves the old .mtl as it was and no `tree.obj.tmp-PID`: it removes
// its staging folder and dies by the signal.
TEST_F(Cli, AnInterruptedExportLeavesNothingNew) {
    { std::ofstream(path("tree.mtl")) << "old mtl\n"; }
    const std::vector<std::pair<std::vector<std::string>, int>> cases = {
        {{"export", "--lod", "-o", path("tree.obj")}, SIGTERM},
        {{"export", "-o", path("tree.obj")}, SIGINT},
        {{"export", "-o", path("tree.glb")}, SIGTERM},
    };
    for (const auto& [args, signal_number] : cases) {
        SCOPED_TRACE(args.back());
        const int status = interrupt_export(dir_, args, signal_number);
        ASSERT_TRUE(WIFSIGNALED(status)) << "status " << status;
        EXPECT_EQ(WTERMSIG(status), signal_number);
        EXPECT_EQ(listing(), std::vector<std::string>{"tree.mtl"});
        EXPECT_EQ(slurp(path("tree.mtl")), "old mtl\n");
    }
}

TEST_F(Cli, DeriveAndTemplates) {
    { std::ofstream(path("abop.lsys")) << "axiom: F\nF -> F[+F]F[-F]F\n"; }
    Result r = run("derive -t " + path("abop.lsys") + " --steps 2");
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_EQ(r.output, "F[+F]F[-F]F[+F[+F]F[-F]F]F[+F]F[-F]F[-F[+F]F[-F]F]F[+F]F[-F]F\n");
    Result list = run("templates");
    EXPECT_EQ(list.code, 0);
    EXPECT_EQ(list.output.rfind("oak\t", 0), 0u) << "the default tree first: " << list.output;
    EXPECT_NE(list.output.find("spruce\t"), std::string::npos);
}

TEST_F(Cli, SkeletonJson) {
    Result r = run("skeleton --set generations=3 -o " + path("skeleton.json"));
    EXPECT_EQ(r.code, 0) << r.output;
    std::ifstream in(path("skeleton.json"));
    std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
    EXPECT_NE(text.find("\"format\": \"sylva-skeleton\""), std::string::npos);
    EXPECT_NE(text.find("\"segments\""), std::string::npos);
    EXPECT_NE(text.find("\"generations\": 3"), std::string::npos);
}

}  // namespace

namespace {

std::string read_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    return {std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>()};
}

TEST_F(Cli, EngineProfilesNameCollisionAndBadEngineOptionsAreUsageErrors) {
    Result bad = run("export --profile cryengine -o " + path("t.glb"));
    EXPECT_EQ(bad.code, 2);
    EXPECT_NE(bad.output.find("generic, unity, unreal or godot"), std::string::npos) << bad.output;
    EXPECT_EQ(run("export --collision maybe -o " + path("t.glb")).code, 2);
    EXPECT_EQ(run("export --tint-variation 2 -o " + path("t.glb")).code, 2);
    EXPECT_TRUE(listing().empty()) << "a usage error writes nothing";

    Result unreal = run("export -t palm --profile unreal --palette -o " + path("palm.obj"));
    ASSERT_EQ(unreal.code, 0) << unreal.output;
    const std::string obj = read_text(path("palm.obj"));
    EXPECT_NE(obj.find("o UCX_tree_00"), std::string::npos);
    EXPECT_NE(obj.find("centimeters"), std::string::npos);
    EXPECT_NE(obj.find("\nvt "), std::string::npos);
    EXPECT_NE(read_text(path("palm.mtl")).find("map_Kd palm_palette.png"), std::string::npos);
    EXPECT_TRUE(fs::exists(path("palm_palette.png")));

    ASSERT_EQ(run("export -t palm --profile godot -o " + path("palm.glb")).code, 0);
    EXPECT_NE(read_text(path("palm.glb")).find("tree_collision_0-convcolonly"), std::string::npos);
}

}  // namespace

namespace {

// What the dynamic loader maps for the program before main (ldd's listing).
std::string loaded_at_start() {
    const std::string command =
        "LD_TRACE_LOADED_OBJECTS=1 " + std::string(SYLVA_BINARY_DIR) + "/app/sylva 2>&1";
    std::string out;
    FILE* pipe = popen(command.c_str(), "r");
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) out.append(buffer, n);
    pclose(pipe);
    return out;
}

}  // namespace

// OpenVDB's relocations slow every process start: the program loads it only when the
// vdb mesher is asked for (marching/vdb_mesher.h), and then it still meshes.
TEST_F(Cli, StartsWithoutOpenVdbAndLoadsItForTheVdbMesher) {
    const std::string libraries = loaded_at_start();
    EXPECT_NE(libraries.find("libc.so"), std::string::npos) << libraries;
    EXPECT_EQ(libraries.find("openvdb"), std::string::npos) << libraries;
    const Result r = run("export -t cypress --mesher vdb -o " + path("tree.obj"));
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("tree.obj")));
}

// --crown-shape: hulls draw the crown as a few convex pieces; a wrong name is refused.
TEST_F(Cli, CrownShapeHullsAndAWrongName) {
    const Result hulls =
        run("export -t honda --budget 200 --crown-shape hulls -o " + path("hulls.obj"));
    EXPECT_EQ(hulls.code, 0) << hulls.output;
    const Result blobs =
        run("export -t honda --budget 200 --crown-shape blobs -o " + path("blobs.obj"));
    EXPECT_EQ(blobs.code, 0) << blobs.output;
    std::ifstream a(path("hulls.obj")), b(path("blobs.obj"));
    const std::string hull_text((std::istreambuf_iterator<char>(a)), {});
    const std::string blob_text((std::istreambuf_iterator<char>(b)), {});
    EXPECT_NE(hull_text, blob_text) << "the crown shape changed nothing";
    // The template's crown_shape is the default; the option overrides it.
    const Result by_template =
        run("export -t honda --budget 200 --set crown_shape=hulls -o " + path("template.obj"));
    EXPECT_EQ(by_template.code, 0) << by_template.output;
    const Result overridden =
        run("export -t honda --budget 200 --set crown_shape=hulls "
            "--crown-shape blobs -o " +
            path("overridden.obj"));
    EXPECT_EQ(overridden.code, 0) << overridden.output;
    std::ifstream t(path("template.obj")), o(path("overridden.obj"));
    const std::string template_text((std::istreambuf_iterator<char>(t)), {});
    const std::string overridden_text((std::istreambuf_iterator<char>(o)), {});
    // The OBJ names its .mtl file: compare past that line.
    const auto body = [](const std::string& text) { return text.substr(text.find("\no ")); };
    EXPECT_EQ(body(template_text), body(hull_text));
    EXPECT_EQ(body(overridden_text), body(blob_text));
    const Result wrong = run("export --crown-shape cubes -o " + path("x.obj"));
    EXPECT_NE(wrong.code, 0);
    EXPECT_NE(wrong.output.find("--crown-shape expects auto, blobs or hulls"), std::string::npos)
        << wrong.output;
    EXPECT_FALSE(fs::exists(path("x.obj")));
}

namespace {

// `--format fbx` writes an FBX and `--engine-kit DIR` the profile's kit beside it, both
// reported as written.
TEST_F(Cli, ExportWritesAnFbxAndTheEngineKit) {
    Result r =
        run("export --lod --profile godot -o " + path("tree.fbx") + " --engine-kit " + path("kit"));
    EXPECT_EQ(r.code, 0) << r.output;
    EXPECT_TRUE(fs::exists(path("tree.fbx")));
    for (const char* file : {"kit/godot3/sylva_post_import.gd", "kit/godot3/sylva_lod.gd",
                             "kit/godot3/sylva_wind.shader", "kit/godot4/sylva_post_import.gd",
                             "kit/godot4/sylva_wind.gdshader"}) {
        EXPECT_TRUE(fs::exists(path(file))) << file;
        EXPECT_NE(r.output.find(file), std::string::npos) << r.output;
    }
    EXPECT_FALSE(fs::exists(path("kit/unity"))) << "only the profile's kits";
}

}  // namespace
