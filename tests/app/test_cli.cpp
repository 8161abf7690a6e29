// The `sylva` command line as scripts see it: exit codes, messages, files left behind.
#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <string>

namespace {

namespace fs = std::filesystem;

struct Result {
    int code = -1;
    std::string output;  // stdout and stderr together
};

Result run(const std::string& args) {
    std::string command = std::string(SYLVA_BINARY_DIR) + "/app/sylva " + args + " 2>&1";
    Result r;
    FILE* pipe = popen(command.c_str(), "r");
    char buffer[4096];
    while (size_t n = fread(buffer, 1, sizeof buffer, pipe)) r.output.append(buffer, n);
    int status = pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

class Cli : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sylva_cli_" + std::to_string(::getpid()));
        fs::create_directories(dir_);
    }
    void TearDown() override { fs::remove_all(dir_); }
    std::string path(const std::string& name) const { return (dir_ / name).string(); }
    fs::path dir_;
};

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
    EXPECT_EQ(run("export -o " + path("x.fbx")).code, 2);  // no such format
    EXPECT_EQ(run("export --format fbx -o " + path("x.obj")).code, 2);
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

// Cost is known before work starts (issue 16): a derivation that would take gigabytes is
// refused at once, naming the estimate and the overrides, and runs when they are raised.
TEST_F(Cli, CostlyWorkIsRefusedBeforeItStartsWithTheEstimateAndTheOverride) {
    { std::ofstream(path("ff.lsys")) << "axiom: !(0.1)F(0.001)\nF(l) -> F(l)F(l)\n"; }
    Result r = run("skeleton -t " + path("ff.lsys") + " --steps 21 -o " + path("s.json"));
    EXPECT_EQ(r.code, 3) << r.output;
    EXPECT_NE(r.output.find("--max-memory"), std::string::npos) << r.output;
    EXPECT_NE(r.output.find("estimated"), std::string::npos) << r.output;
    EXPECT_FALSE(fs::exists(path("s.json")));
}

TEST_F(Cli, BadParameterIsExitCode3NamingTheKey) {
    Result r = run("export --set trunk_taper=nan -o " + path("tree.obj"));
    EXPECT_EQ(r.code, 3);
    EXPECT_NE(r.output.find("trunk_taper"), std::string::npos) << r.output;
    EXPECT_EQ(run("export -t no-such-template -o " + path("tree.obj")).code, 3);
    EXPECT_FALSE(fs::exists(path("tree.obj")));
}

TEST_F(Cli, UnwritablePathIsExitCode4AndLeavesNothing) {
    Result r = run("export -o " + path("missing/dir/tree.obj"));
    EXPECT_EQ(r.code, 4) << r.output;
    EXPECT_NE(r.output.find("missing/dir/tree."), std::string::npos)
        << r.output;  // .obj or its .mtl
    EXPECT_FALSE(fs::exists(path("missing")));
    EXPECT_EQ(std::distance(fs::directory_iterator(dir_), fs::directory_iterator()), 0);
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
