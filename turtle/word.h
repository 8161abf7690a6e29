// A derived word: a string of modules (a symbol with an optional list of numbers), stored
// flat so derivation appends without allocating per module.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace sylva {

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

    // Counts modules with this symbol.
    std::size_t count(char symbol) const;

    // Text form: modules with their numbers in shortest round-trip form, e.g. "F(1.5)+(90)".
    std::string to_string() const;

  private:
    std::vector<char> symbols_;
    std::vector<double> params_;
    std::vector<std::uint32_t> offsets_{0};  // args of module i: [offsets_[i], offsets_[i+1])
};

}  // namespace sylva
