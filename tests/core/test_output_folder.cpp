// The folder an export or a job writes into (core/output_folder.h): what is missing is named
// before it is made, made with its parents, kept on success and removed on failure.
#include <gtest/gtest.h>

#include <fstream>

#include "core/errors.h"
#include "core/output_folder.h"
#include "tests/helpers.h"

namespace {

using namespace sylva;
namespace fs = std::filesystem;
using OutputFolderTest = sylva::test::TempFolderTest;

TEST_F(OutputFolderTest, NamesTheOutermostMissingFolderThenMakesAndKeepsIt) {
    EXPECT_EQ(missing_folder(dir_), fs::path());
    EXPECT_EQ(missing_folder(""), fs::path());
    EXPECT_EQ(missing_folder(dir_ / "a" / "b" / "c"), dir_ / "a");
    {
        OutputFolder folder(dir_ / "a" / "b" / "c");
        EXPECT_TRUE(fs::is_directory(dir_ / "a" / "b" / "c"));
        folder.keep();
    }
    EXPECT_TRUE(fs::is_directory(dir_ / "a" / "b" / "c"));
    EXPECT_EQ(missing_folder(dir_ / "a" / "b" / "c"), fs::path());
}

TEST_F(OutputFolderTest, AFailedJobLeavesNoFolderAndAFileInTheWayIsAnIoErrorNamingIt) {
    { OutputFolder folder(dir_ / "x" / "y"); }  // not kept: the job failed
    EXPECT_FALSE(fs::exists(dir_ / "x"));
    { std::ofstream(dir_ / "file") << "x"; }
    try {
        OutputFolder folder(dir_ / "file" / "sub");
        ADD_FAILURE() << "expected IoError";
    } catch (const IoError& e) {
        EXPECT_NE(std::string(e.what()).find((dir_ / "file").string()), std::string::npos)
            << e.what();
    }
    EXPECT_EQ(listing(), (std::vector<std::string>{"file"}));
}

}  // namespace
