// The one error family: messages name the place, relocation moves a grammar's lines into
// its file's, and the type survives a relocation and rethrow.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "core/atomic_file.h"
#include "core/errors.h"

namespace sylva {
namespace {

TEST(InputError, NamesSourceLineAndColumnAndShowsTheLine) {
    const InputError e("no '->'", {"oak.toml", 7, 3}, "F FF");
    EXPECT_EQ(std::string(e.what()), "oak.toml:7:3: no '->'\n    F FF\n      ^");
    EXPECT_EQ(e.reason(), "no '->'");
    EXPECT_EQ(e.where().source, "oak.toml");
    EXPECT_EQ(e.line(), 7);
    EXPECT_EQ(e.column(), 3);
}

TEST(InputError, WithoutASourceNamesTheLineInWords) {
    EXPECT_EQ(std::string(GrammarError("bad", 2, 5).what()), "line 2, column 5: bad");
    EXPECT_EQ(std::string(InputError("bad").what()), "bad");
    EXPECT_EQ(std::string(InputError("bad", {"--set"}).what()), "--set: bad");
}

TEST(InputError, RelocatingShiftsLinesIntoTheFileAndKeepsTheType) {
    try {
        try {
            throw GrammarError("division by zero", 2, 0, "A -> F(1/0)");
        } catch (InputError& e) {
            e.relocate("tree.toml", 5);  // the grammar's line 1 is the file's line 5
            throw;
        }
    } catch (const GrammarError& e) {
        EXPECT_EQ(e.line(), 6);
        EXPECT_EQ(e.where().source, "tree.toml");
        EXPECT_EQ(std::string(e.what()).rfind("tree.toml:6: division by zero", 0), 0u) << e.what();
        return;
    }
    FAIL() << "the GrammarError was lost";
}

TEST(InputError, RelocatingAPlacelessErrorOnlyNamesTheFile) {
    InputError e("the tree has no trunk");
    e.relocate("tree.toml", 5);
    EXPECT_EQ(e.line(), 0);
    EXPECT_EQ(std::string(e.what()), "tree.toml: the tree has no trunk");
}

TEST(IoError, NamesThePathThatFailed) {
    const std::filesystem::path dir = std::filesystem::temp_directory_path();
    try {
        write_file_atomically(dir, [](std::ostream& out) { out << "x"; });
        FAIL() << "expected IoError";
    } catch (const IoError& e) {
        EXPECT_EQ(e.path(), dir);
        EXPECT_NE(std::string(e.what()).find(dir.string()), std::string::npos) << e.what();
    }
}

}  // namespace
}  // namespace sylva
