// A derived word: a string of modules (a symbol with an optional list of numbers), stored
// flat so derivation appends without allocating per module.
//
// A module's symbol is one byte: a character of the grammar (below kFirstWordSymbol) or a
// word module (`plant`, `~apple`; docs/grammar.md), whose name the word's alphabet holds.
// One byte keeps single-character grammars as fast as ever and gives a grammar 128 words.
#pragma once

#include <cstdint>
#include <memory>
#include <span>
#include <string>
#include <string_view>
#include <vector>

namespace sylva {

// Symbols from here on are words: symbol kFirstWordSymbol + i is the alphabet's word i.
inline constexpr int kFirstWordSymbol = 128;
inline constexpr int kMaxWords = 256 - kFirstWordSymbol;

// The names of a grammar's word modules, in the order the grammar introduces them; shared
// by the grammar and every word derived from it.
using WordNames = std::vector<std::string>;

inline bool is_word_symbol(char symbol) {
    return static_cast<unsigned char>(symbol) >= kFirstWordSymbol;
}

class Word {
  public:
    std::size_t size() const { return symbols_.size(); }
    bool empty() const { return symbols_.empty(); }
    char symbol(std::size_t i) const { return symbols_[i]; }
    std::span<const double> args(std::size_t i) const {
        return {params_.data() + offsets_[i], offsets_[i + 1] - offsets_[i]};
    }

    void push(char symbol, std::span<const double> args = {}) {
        symbols_.push_back(symbol);
        params_.insert(params_.end(), args.begin(), args.end());
        offsets_.push_back(static_cast<std::uint32_t>(params_.size()));
    }
    void clear() {
        symbols_.clear();
        params_.clear();
        offsets_.assign(1, 0);
    }
    void reserve(std::size_t modules, std::size_t params) {
        symbols_.reserve(modules);
        offsets_.reserve(modules + 1);
        params_.reserve(params);
    }
    std::size_t param_count() const { return params_.size(); }

    // The names of the word symbols (null when the grammar has no words); kept by clear().
    void set_names(std::shared_ptr<const WordNames> names) { names_ = std::move(names); }
    const std::shared_ptr<const WordNames>& names() const { return names_; }
    // A symbol's text: the character, or the word's name ("?" for a word without a name).
    std::string_view symbol_name(char symbol) const;

    // Counts modules with this symbol.
    std::size_t count(char symbol) const;

    // Text form: modules with their numbers in shortest round-trip form, e.g. "F(1.5)+(90)";
    // a word module stands apart from a neighbouring name by a space ("seg F seg"), so the
    // text reads back as the same modules.
    std::string to_string() const;

  private:
    std::shared_ptr<const WordNames> names_;
    std::vector<char> symbols_;
    std::vector<double> params_;
    std::vector<std::uint32_t> offsets_{0};  // args of module i: [offsets_[i], offsets_[i+1])
};

}  // namespace sylva
