// The command line reaches what the studio reaches: a template's #define constants (--set,
// batch --jitter NAME=J), help for every command, --version, one seed range for every --seed,
// output folders made before the work, and every template the studio saves as a variant
// exports.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/seed.h"
#include "forest/variation.h"
#include "tests/helpers.h"
#include "tree/template_file.h"
#include "tree/template_library.h"

namespace {

namespace fs = std::filesystem;
using Result = sylva::test::CommandResult;
using CliParity = sylva::test::TempFolderTest;

Result run(const std::string& args) {
    return sylva::test::run_command(std::string(SYLVA_BINARY_DIR) + "/app/sylva " + args, 120);
}

std::string read(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    std::stringstream text;
    text << in.rdbuf();
    return text.str();
}

// Every command `sylva --help` lists (a line "  sylva NAME ...") answers `NAME --help`.
TEST_F(CliParity, VersionAndEveryCommandsHelpExitZero) {
    const Result version = run("--version");
    EXPECT_EQ(version.code, 0) << version.output;
    EXPECT_EQ(version.output.rfind("sylva ", 0), 0u) << version.output;
    EXPECT_NE(version.output.find_first_of("0123456789"), std::string::npos) << version.output;
    const Result help = run("--help");
    ASSERT_EQ(help.code, 0) << help.output;
    std::vector<std::string> commands;
    std::istringstream lines(help.output);
    for (std::string line; std::getline(lines, line);)
        if (line.rfind("  sylva ", 0) == 0 && line.size() > 8 && line[8] != '-') {
            const std::string name = line.substr(8, line.find(' ', 8) - 8);
            if (std::find(commands.begin(), commands.end(), name) == commands.end())
                commands.push_back(name);
        }
    for (const char* known :
         {"export", "derive", "lint", "skeleton", "batch", "forest", "templates", "layout"})
        EXPECT_NE(std::find(commands.begin(), commands.end(), known), commands.end()) << known;
    for (const std::string& command : commands) {
        const Result usage = run(command + " --help");
        EXPECT_EQ(usage.code, 0) << command << ": " << usage.output;
        EXPECT_NE(usage.output.find("sylva " + command), std::string::npos) << usage.output;
    }
}

// `--set a=60` sets oak's `#define a 46 # [20, 75] ...`: the tree changes; outside the
// comment's range it is refused (exit 3) naming the range, before any file is written.
TEST_F(CliParity, SetReachesATemplatesGrammarConstants) {
    const std::string tree = "export -t oak --budget 200 -o ";
    ASSERT_EQ(run(tree + path("plain.obj")).code, 0);
    const Result set = run("export -t oak --set a=60 --budget 200 -o " + path("a60.obj"));
    ASSERT_EQ(set.code, 0) << set.output;
    EXPECT_NE(read(path("plain.obj")), read(path("a60.obj")));
    const Result far = run("export -t oak --set a=90 -o " + path("a90.obj"));
    EXPECT_EQ(far.code, 3) << far.output;
    EXPECT_NE(far.output.find("20 to 75"), std::string::npos) << far.output;
    const Result unknown = run("export -t oak --set zz=1 -o " + path("zz.obj"));
    EXPECT_EQ(unknown.code, 3) << unknown.output;
    EXPECT_NE(unknown.output.find("#define constants: a, f, s, d"), std::string::npos)
        << unknown.output;
    EXPECT_FALSE(fs::exists(path("a90.obj")));
    EXPECT_FALSE(fs::exists(path("zz.obj")));
}

// Every --seed takes the seeds 0 to 2^53 - 1 and refuses the next one (exit 2, naming the
// range), so a seed given on the command line is one a saved file holds.
TEST_F(CliParity, EverySeedFlagTakesTheOneRange) {
    const std::string past = " --seed 9007199254740992";
    for (const std::string& command :
         {"export -o " + path("t.glb"), std::string("derive"), "skeleton -o " + path("s.json"),
          "batch --count 1 -o " + path("b"), "forest --trees 1 -o " + path("f.glb"),
          "layout generate village -o " + path("l")}) {
        const Result r = run(command + past);
        EXPECT_EQ(r.code, 2) << command << ": " << r.output;
        EXPECT_NE(r.output.find("9007199254740991"), std::string::npos) << r.output;
    }
    EXPECT_TRUE(listing().empty());
    const Result top = run("derive -t oak --steps 1 --seed 9007199254740991");
    EXPECT_EQ(top.code, 0) << top.output;
}

// `batch --jitter a=0.5` varies oak's #define a within [20, 75] and lists it in the manifest;
// a key that cannot be jittered is refused before any folder is made.
TEST_F(CliParity, BatchJittersGrammarConstants) {
    const Result r = run("batch -t oak --count 3 --jitter a=0.5 --budget 100 -o " + path("oaks"));
    ASSERT_EQ(r.code, 0) << r.output;
    const std::string manifest = read(dir_ / "oaks" / "manifest.json");
    EXPECT_NE(manifest.find("\"a\""), std::string::npos) << manifest;
    const Result unknown = run("batch -t oak --count 1 --jitter zz=0.1 -o " + path("zz"));
    EXPECT_EQ(unknown.code, 3) << unknown.output;
    EXPECT_FALSE(fs::exists(path("zz")));
    EXPECT_EQ(run("batch -t oak --count 1 --jitter a=2 -o " + path("zz")).code, 2);
    EXPECT_EQ(run("forest --trees 1 --jitter a=0.1 -o " + path("f.glb")).code, 2);
}

// A missing output folder is made before the work (with its parents); something in the way
// is refused with exit 4 naming it before any tree is grown; a failed command leaves no
// folder behind.
TEST_F(CliParity, OutputFoldersAreMadeBeforeTheWork) {
    const Result exported = run("export -t oak --budget 100 -o " + path("new/deeper/tree.obj"));
    EXPECT_EQ(exported.code, 0) << exported.output;
    EXPECT_TRUE(fs::is_regular_file(path("new/deeper/tree.obj")));
    EXPECT_EQ(run("skeleton -o " + path("s/k.json")).code, 0);
    EXPECT_TRUE(fs::is_regular_file(path("s/k.json")));
    EXPECT_EQ(run("derive --steps 1 -o " + path("d/word.txt")).code, 0);
    EXPECT_TRUE(fs::is_regular_file(path("d/word.txt")));

    std::ofstream(path("file")) << "x";
    const Result blocked = run("export -o " + path("file/tree.obj"));
    EXPECT_EQ(blocked.code, 4) << blocked.output;
    EXPECT_NE(blocked.output.find(path("file")), std::string::npos) << blocked.output;
    EXPECT_EQ(blocked.output.find("marching cubes"), std::string::npos) << blocked.output;
    const Result failed = run("export -t no_such_template -o " + path("gone/tree.obj"));
    EXPECT_EQ(failed.code, 3) << failed.output;
    EXPECT_FALSE(fs::exists(path("gone")));
}

// What the studio's Save writes for a variant of the Variants strip (a seed of variant_seed()
// with the largest base, jittered parameters, the template's comments kept) exports with
// `sylva export -t FILE`, for every built-in template.
TEST_F(CliParity, AVariantSavedByTheStudioExportsForEveryTemplate) {
    for (const sylva::TreeTemplate* t : sylva::builtin_templates()) {
        sylva::TreeTemplate variant = *t;
        const std::uint64_t seed = sylva::variant_seed(~std::uint64_t{0}, 1);
        variant.params = sylva::varied_params(t->params, seed, 0.1);
        const std::string file = path(t->name + ".toml");
        sylva::save_template_file(file, variant, sylva::builtin_template_text(t->name));
        const Result r = run("export -t " + file + " -o " + path(t->name + ".glb"));
        EXPECT_EQ(r.code, 0) << t->name << ": " << r.output;
        EXPECT_NE(read(file).find("seed = " + std::to_string(seed) + "\n"), std::string::npos);
    }
}

}  // namespace
