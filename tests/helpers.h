// What the tests of several modules share: a fresh folder per test, a file's bytes, a
// command's exit code and output, and the closed-manifold check with every failing count.
// Header-only; include as "tests/helpers.h".
#pragma once

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "core/mesh_checks.h"

namespace sylva::test {

// The bytes of a file; empty when it cannot be read.
inline std::string read_file(const std::filesystem::path& path) {
    std::ifstream in(path, std::ios::binary);
    std::ostringstream text;
    text << in.rdbuf();
    return text.str();
}

struct CommandResult {
    int code = -1;       // the exit code; -1 when the command did not exit (a signal)
    std::string output;  // stdout and stderr together
};

// Runs `command` through the shell with stderr joined to stdout. `seconds` > 0: killed after
// that long, so a hang fails the test instead of stalling it.
inline CommandResult run_command(const std::string& command, int seconds = 0) {
    const std::string timeout =
        seconds > 0 ? "timeout -s KILL " + std::to_string(seconds) + " " : std::string();
    CommandResult r;
    FILE* pipe = popen((timeout + command + " 2>&1").c_str(), "r");
    if (!pipe) return r;
    char buffer[4096];
    while (std::size_t n = std::fread(buffer, 1, sizeof buffer, pipe)) r.output.append(buffer, n);
    const int status = pclose(pipe);
    r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
    return r;
}

// A fixture with a fresh, empty folder per test (named for the suite and the process, so
// parallel test processes never share one), removed afterwards.
class TempFolderTest : public ::testing::Test {
  protected:
    void SetUp() override {
        const auto* test = ::testing::UnitTest::GetInstance()->current_test_info();
        dir_ = std::filesystem::temp_directory_path() /
               ("sylva_" + std::string(test->test_suite_name()) + "_" + test->name() + "_" +
                std::to_string(::getpid()));
        std::filesystem::remove_all(dir_);
        std::filesystem::create_directories(dir_);
    }
    void TearDown() override { std::filesystem::remove_all(dir_); }

    // A file's path in the folder, as text for a command line.
    std::string path(const std::string& name) const { return (dir_ / name).string(); }

    // The names in the folder, sorted.
    std::vector<std::string> listing() const {
        std::vector<std::string> names;
        for (const auto& entry : std::filesystem::directory_iterator(dir_))
            names.push_back(entry.path().filename().string());
        std::sort(names.begin(), names.end());
        return names;
    }

    std::filesystem::path dir_;
};

// The mesh is a closed, consistently oriented 2-manifold without degenerate or zero-area
// triangles; a failure reports every count.
inline void expect_closed_manifold(const Mesh& mesh) {
    const MeshTopology t = check_topology(mesh);
    EXPECT_TRUE(t.is_closed_manifold()) << to_string(t);
    EXPECT_EQ(t.zero_area_triangles, 0u) << to_string(t);
}

}  // namespace sylva::test
