#include "turtle/grammar_error.h"

namespace sylva {
namespace {

std::string format(const std::string& message, int line, int column, const std::string& text) {
    if (line <= 0) return message;
    std::string out = "line ";
    out.append(std::to_string(line));
    if (column > 0) out.append(", column ").append(std::to_string(column));
    out.append(": ").append(message);
    if (!text.empty()) {
        out.append("\n    ").append(text).append("\n    ");
        if (column > 0) out.append(static_cast<size_t>(column - 1), ' ').append("^");
    }
    return out;
}

}  // namespace

GrammarError::GrammarError(const std::string& message, int line, int column,
                           const std::string& source_line)
    : std::runtime_error(format(message, line, column, source_line)),
      reason_(message),
      line_(line),
      column_(column) {}

}  // namespace sylva
