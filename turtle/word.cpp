#include "turtle/word.h"

#include <algorithm>
#include <charconv>

namespace sylva {

std::size_t Word::count(char symbol) const {
    return static_cast<std::size_t>(std::count(symbols_.begin(), symbols_.end(), symbol));
}

std::string Word::to_string() const {
    std::string out;
    out.reserve(symbols_.size() + params_.size() * 6);
    char buffer[32];
    for (std::size_t i = 0; i < size(); ++i) {
        out.push_back(symbols_[i]);
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
