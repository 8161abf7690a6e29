// The one reader of input files: regular files only, within a size limit, and a FIFO
// never blocks it.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <fstream>

#include "core/errors.h"
#include "core/input_file.h"

namespace {

namespace fs = std::filesystem;
using namespace sylva;

class InputFile : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sylva_input_file_" + std::to_string(::getpid()));
        fs::remove_all(dir_);
        fs::create_directories(dir_);
    }
    void TearDown() override {
        ::unsetenv("SYLVA_MAX_INPUT_MB");
        fs::remove_all(dir_);
    }
    std::string message_of(const fs::path& path, std::uintmax_t limit = kDefaultInputLimit) {
        try {
            read_input_file(path, "template", limit);
        } catch (const IoError& e) {
            return e.what();
        }
        return "";
    }
    fs::path dir_;
};

TEST_F(InputFile, ReadsARegularFileWhole) {
    const std::string bytes("axiom: F\0F -> FF\n", 17);
    std::ofstream(dir_ / "t.txt", std::ios::binary) << bytes;
    EXPECT_EQ(read_input_file(dir_ / "t.txt", "template"), bytes);
}

TEST_F(InputFile, RefusesDevicesDirectoriesAndFifosAtOnce) {
    EXPECT_NE(message_of("/dev/zero").find("a device"), std::string::npos);
    EXPECT_NE(message_of(dir_).find("a directory"), std::string::npos);
    ASSERT_EQ(::mkfifo((dir_ / "pipe").c_str(), 0600), 0);
    // No writer ever comes: the reader must not wait for one.
    EXPECT_NE(message_of(dir_ / "pipe").find("a FIFO"), std::string::npos);
    EXPECT_NE(message_of(dir_ / "missing.toml").find("no such file"), std::string::npos);
}

TEST_F(InputFile, RefusesFilesOverTheLimitNamingIt) {
    std::ofstream(dir_ / "big.toml") << std::string(2000, 'x');
    const std::string message = message_of(dir_ / "big.toml", 1000);
    EXPECT_NE(message.find("2000 bytes"), std::string::npos) << message;
    EXPECT_NE(message.find("SYLVA_MAX_INPUT_MB"), std::string::npos) << message;
    EXPECT_NE(message.find("big.toml"), std::string::npos) << message;
    EXPECT_EQ(message_of(dir_ / "big.toml", 2000), "");
}

TEST_F(InputFile, TheLimitIsSetByTheEnvironment) {
    EXPECT_EQ(input_size_limit(), kDefaultInputLimit);
    ::setenv("SYLVA_MAX_INPUT_MB", "3", 1);
    EXPECT_EQ(input_size_limit(), 3u << 20);
    for (const char* bad : {"0", "-1", "abc", "3x", "99999999999999999999"}) {
        ::setenv("SYLVA_MAX_INPUT_MB", bad, 1);
        EXPECT_EQ(input_size_limit(), kDefaultInputLimit) << bad;
    }
}

}  // namespace
