// The error raised for a broken grammar: names the line and column, shows the line with a
// caret under the column, so a person can find and fix the mistake.
#pragma once

#include <stdexcept>
#include <string>

namespace sylva {

class GrammarError : public std::runtime_error {
public:
    // line and column are 1-based; 0 means "not tied to a place in the text".
    GrammarError(const std::string& message, int line = 0, int column = 0,
                 const std::string& source_line = {});

    const std::string& reason() const { return reason_; }
    int line() const { return line_; }
    int column() const { return column_; }

private:
    std::string reason_;
    int line_;
    int column_;
};

}  // namespace sylva
