// The one error family of Sylva. Bad input (a grammar, a template, a parameter, a file's
// contents) raises InputError, which names where: the source (a file name, or "axiom",
// "--set"), the 1-based line and column, and the line itself with a caret under the column.
// GrammarError is the InputError of the grammar language. A file that cannot be read or
// written raises IoError. Internal invariants are asserts, not exceptions. The CLI and the
// studio catch these at their boundary (the CLI: InputError exit 3, IoError exit 4).
#pragma once

#include <filesystem>
#include <stdexcept>
#include <string>

namespace sylva {

// Where bad input was found. Empty source: the text has no name (a grammar given alone);
// line or column 0: not tied to a place.
struct SourceLocation {
    std::string source;
    int line = 0;
    int column = 0;
};

class InputError : public std::runtime_error {
  public:
    explicit InputError(const std::string& reason, SourceLocation where = {},
                        const std::string& source_line = {});

    const char* what() const noexcept override { return message_.c_str(); }
    // What is wrong, without the place.
    const std::string& reason() const { return reason_; }
    const SourceLocation& where() const { return where_; }
    int line() const { return where_.line; }
    int column() const { return where_.column; }

    // For text embedded in a file (a grammar inside a template file): the error now names
    // `source`, and its line counts from `first_line`, the file's line of the text's line 1.
    // A place-less error gets the source alone. Rethrow with `throw;` to keep the type.
    void relocate(const std::string& source, int first_line);

  private:
    void format();

    std::string reason_;
    SourceLocation where_;
    std::string source_line_;
    std::string message_;
};

// An InputError in the grammar language (docs/grammar.md).
class GrammarError : public InputError {
  public:
    explicit GrammarError(const std::string& reason, int line = 0, int column = 0,
                          const std::string& source_line = {})
        : InputError(reason, {{}, line, column}, source_line) {}
};

// A file could not be read or written; the message names the path and the reason.
class IoError : public std::runtime_error {
  public:
    explicit IoError(const std::string& message, std::filesystem::path path = {})
        : std::runtime_error(message), path_(std::move(path)) {}
    const std::filesystem::path& path() const { return path_; }

  private:
    std::filesystem::path path_;
};

}  // namespace sylva
