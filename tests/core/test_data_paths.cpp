// Paths and names from data files: a stranger's file can name nothing outside its folder,
// and a name built from data is a plain file name.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>

#include "core/data_paths.h"
#include "core/errors.h"

namespace {

namespace fs = std::filesystem;
using namespace sylva;

class DataPaths : public ::testing::Test {
  protected:
    void SetUp() override {
        root_ = fs::temp_directory_path() / ("sylva_data_paths_" + std::to_string(::getpid()));
        fs::remove_all(root_);
        fs::create_directories(root_ / "plans" / "trees");
        std::ofstream(root_ / "plans" / "trees" / "birch.toml") << "name = \"birch\"\n";
        std::ofstream(root_ / "secret.txt") << "secret\n";
    }
    void TearDown() override { fs::remove_all(root_); }
    fs::path root_;
};

TEST_F(DataPaths, RelativeNamesResolveInsideTheFolder) {
    const fs::path folder = root_ / "plans";
    EXPECT_EQ(resolve_data_reference("trees/birch.toml", folder, "s.json"),
              folder / "trees/birch.toml");
    EXPECT_EQ(resolve_data_reference("./trees/birch.toml", folder, "s.json"),
              folder / "./trees/birch.toml");
}

TEST_F(DataPaths, AbsoluteParentAndEmptyNamesAreRefused) {
    const fs::path folder = root_ / "plans";
    for (const char* name :
         {"/etc/shadow", "../secret.txt", "trees/../../secret.txt", "..", "", "/dev/zero"}) {
        try {
            resolve_data_reference(name, folder, "s.json: species[0].template");
            FAIL() << "accepted '" << name << "'";
        } catch (const InputError& e) {
            // The message says where the name was written.
            EXPECT_NE(std::string(e.what()).find("species[0].template"), std::string::npos)
                << e.what();
        }
    }
    EXPECT_THROW(resolve_data_reference(std::string_view("a\0b", 3), folder, "s"), InputError);
}

TEST_F(DataPaths, ALinkOutOfTheFolderIsRefused) {
    const fs::path folder = root_ / "plans";
    fs::create_symlink(root_ / "secret.txt", folder / "inner.toml");
    fs::create_directory_symlink(root_, folder / "up");
    fs::create_symlink(folder / "trees" / "birch.toml", folder / "alias.toml");
    EXPECT_THROW(resolve_data_reference("inner.toml", folder, "s"), InputError);
    EXPECT_THROW(resolve_data_reference("up/secret.txt", folder, "s"), InputError);
    // A link that stays inside is fine.
    EXPECT_EQ(resolve_data_reference("alias.toml", folder, "s"), folder / "alias.toml");
}

TEST_F(DataPaths, TextFromNoFileNamesNoFile) {
    EXPECT_THROW(resolve_data_reference("birch.toml", {}, "s"), InputError);
}

TEST(SafeFileName, KeepsPlainNamesAndFlattensTheRest) {
    EXPECT_EQ(safe_file_name("oak"), "oak");
    EXPECT_EQ(safe_file_name("red-maple_2.v1"), "red-maple_2.v1");
    EXPECT_EQ(safe_file_name("../../../escaped"), "escaped");
    EXPECT_EQ(safe_file_name("/etc/passwd"), "etc_passwd");
    EXPECT_EQ(safe_file_name("a..b"), "a_b");
    EXPECT_EQ(safe_file_name("my tree"), "my_tree");
    EXPECT_EQ(safe_file_name(".hidden"), "hidden");
    EXPECT_EQ(safe_file_name(".."), "tree");
    EXPECT_EQ(safe_file_name(""), "tree");
    EXPECT_EQ(safe_file_name("/", "x"), "x");
    EXPECT_EQ(safe_file_name("Eiche \xc3\xa4"), "Eiche");
    EXPECT_EQ(safe_file_name(std::string(300, 'a')).size(), 64u);
    // Whatever goes in, the result is one plain component.
    for (const char* name : {"a/b", "a\\b", "..\\..", "a\nb", "c:\\x"}) {
        const std::string safe = safe_file_name(name);
        EXPECT_EQ(safe.find('/'), std::string::npos) << name;
        EXPECT_EQ(safe.find('\\'), std::string::npos) << name;
        EXPECT_NE(safe.front(), '.') << name;
        EXPECT_EQ(safe.find(".."), std::string::npos) << name;
    }
}

}  // namespace
