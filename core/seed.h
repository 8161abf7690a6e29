// Seeds: the whole numbers 0 to 2^53 - 1 that every part of Sylva makes, writes and reads
// (template files, --seed, batches' and forests' variants, the studio). A seed in this
// range is a plain TOML integer (TOML's integers are signed 64-bit) and a JSON number that
// every reader holds exactly, also those that read numbers as doubles (JavaScript, Godot's
// JSON parser), so manifests, placement lists and saved templates give back the same tree.
//
// Pure functions and constants: safe from any thread.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace sylva {

// The largest seed: 2^53 - 1 = 9007199254740991.
inline constexpr std::uint64_t kMaxSeed = (std::uint64_t{1} << 53) - 1;

constexpr bool is_seed(std::uint64_t value) {
    return value <= kMaxSeed;
}

// A 64-bit random number (splitmix64's output, core/random.h) made a seed: its top 53 bits,
// which are as evenly spread as all 64.
constexpr std::uint64_t seed_from_bits(std::uint64_t bits) {
    return bits >> 11;
}

// "0 to 9007199254740991 (2^53 - 1)", for messages and help.
std::string seed_range_text();

// The seed `text` spells in decimal digits (all of it, no sign, no spaces); nullopt for
// anything else, or a number above kMaxSeed.
std::optional<std::uint64_t> parse_seed(std::string_view text);

}  // namespace sylva
