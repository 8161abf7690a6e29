#include "turtle/word.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>

namespace sylva {
namespace {

// Every one-byte symbol as text of its own, for symbol_name()'s view.
constexpr std::array<char, kFirstWordSymbol> kCharacters = [] {
    std::array<char, kFirstWordSymbol> table{};
    for (int c = 0; c < kFirstWordSymbol; ++c)
        table[static_cast<std::size_t>(c)] = static_cast<char>(c);
    return table;
}();

}  // namespace

std::size_t Word::count(char symbol) const {
    return static_cast<std::size_t>(std::count(symbols_.begin(), symbols_.end(), symbol));
}

std::string_view Word::symbol_name(char symbol) const {
    if (!is_word_symbol(symbol)) return {&kCharacters[static_cast<unsigned char>(symbol)], 1};
    const auto index =
        static_cast<std::size_t>(static_cast<unsigned char>(symbol) - kFirstWordSymbol);
    if (!names_ || index >= names_->size()) return "?";
    return (*names_)[index];
}

std::string Word::to_string() const {
    std::string out;
    out.reserve(symbols_.size() + params_.size() * 6);
    char buffer[32];
    // What reads back as other modules when written together: two names (a word, or a
    // letter, digit or '_') where the grammar has words (single letters would join into a
    // word there; "~" with a name becomes an organ), or a '~' before a name.
    auto name_like = [](char c) {
        return is_word_symbol(c) || std::isalnum(static_cast<unsigned char>(c)) || c == '_';
    };
    for (std::size_t i = 0; i < size(); ++i) {
        const char c = symbols_[i];
        const std::string_view text = symbol_name(c);
        if (i > 0 && args(i - 1).empty()) {
            const char before = symbols_[i - 1];
            const bool names = name_like(before) && name_like(c) &&
                               (names_ || is_word_symbol(before) || is_word_symbol(c));
            const bool tilde = before == '~' && !text.empty() &&
                               std::isalpha(static_cast<unsigned char>(text.front()));
            if (names || tilde) out.push_back(' ');
        }
        out.append(text);
        std::span<const double> a = args(i);
        if (a.empty()) continue;
        out.push_back('(');
        for (std::size_t k = 0; k < a.size(); ++k) {
            if (k) out.push_back(',');
            auto result = std::to_chars(buffer, buffer + sizeof buffer, a[k]);
            out.append(buffer, result.ptr);
        }
        out.push_back(')');
    }
    return out;
}

}  // namespace sylva
