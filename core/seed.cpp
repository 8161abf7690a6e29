#include "core/seed.h"

#include <charconv>

namespace sylva {

std::string seed_range_text() {
    return "0 to " + std::to_string(kMaxSeed) + " (2^53 - 1)";
}

std::optional<std::uint64_t> parse_seed(std::string_view text) {
    std::uint64_t value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() || !is_seed(value))
        return std::nullopt;
    return value;
}

}  // namespace sylva
