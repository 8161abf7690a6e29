#include "core/errors.h"

namespace sylva {

InputError::InputError(const std::string& reason, SourceLocation where,
                       const std::string& source_line)
    : std::runtime_error(reason),
      reason_(reason),
      where_(std::move(where)),
      source_line_(source_line) {
    format();
}

void InputError::relocate(const std::string& source, int first_line) {
    where_.source = source;
    if (where_.line > 0) where_.line += first_line - 1;
    format();
}

namespace {

// A NUL byte would end the message for every C-string consumer (what(), printf); other
// control characters would garble a terminal. Both are shown escaped, as \xNN.
std::string printable(const std::string& text) {
    std::string out;
    for (unsigned char c : text) {
        if (c >= 0x20 || c == '\t') {
            out.push_back(static_cast<char>(c));
        } else {
            static constexpr char kHex[] = "0123456789abcdef";
            out += "\\x";
            out.push_back(kHex[c >> 4]);
            out.push_back(kHex[c & 15]);
        }
    }
    return out;
}

}  // namespace

// "file:7:12: reason" when the source has a name (as compilers write it), "line 7, column
// 12: reason" when it has none; then the line with a caret under the column.
void InputError::format() {
    const SourceLocation& w = where_;
    std::string place;
    if (!w.source.empty()) {
        place = w.source;
        if (w.line > 0) place += ":" + std::to_string(w.line);
        if (w.line > 0 && w.column > 0) place += ":" + std::to_string(w.column);
    } else if (w.line > 0) {
        place = "line " + std::to_string(w.line);
        if (w.column > 0) place += ", column " + std::to_string(w.column);
    }
    message_ = printable(place.empty() ? reason_ : place + ": " + reason_);
    if (w.line > 0 && !source_line_.empty()) {
        message_ += "\n    " + printable(source_line_) + "\n    ";
        if (w.column > 0) message_ += std::string(static_cast<size_t>(w.column - 1), ' ') + "^";
    }
}

}  // namespace sylva
