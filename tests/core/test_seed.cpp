// The one seed range (core/seed.h): what parses, what is refused, and that a 64-bit random
// number made a seed lands inside it.
#include <gtest/gtest.h>

#include "core/seed.h"

namespace {

using namespace sylva;

TEST(Seed, TheRangeIsEveryIntegerADoubleHoldsExactly) {
    EXPECT_EQ(kMaxSeed, 9007199254740991u);
    const double top = static_cast<double>(kMaxSeed);
    EXPECT_EQ(static_cast<std::uint64_t>(top), kMaxSeed);  // JSON readers that use doubles
    // One past the range, two seeds read back as one number.
    const volatile std::uint64_t past = kMaxSeed + 2;
    EXPECT_EQ(static_cast<double>(past), static_cast<double>(kMaxSeed + 1));
    EXPECT_NE(seed_range_text().find("9007199254740991"), std::string::npos);
}

TEST(Seed, ParsesEveryWholeNumberOfTheRangeAndNothingElse) {
    EXPECT_EQ(parse_seed("0"), 0u);
    EXPECT_EQ(parse_seed("1"), 1u);
    EXPECT_EQ(parse_seed("9007199254740991"), kMaxSeed);
    for (const char* bad : {"9007199254740992", "13757245211066428519", "18446744073709551616",
                            "-1", "+1", " 1", "1 ", "", "1e3", "0x10", "1.0", "seed"})
        EXPECT_FALSE(parse_seed(bad)) << bad;
}

TEST(Seed, RandomBitsBecomeSeedsOfTheRange) {
    EXPECT_EQ(seed_from_bits(~std::uint64_t{0}), kMaxSeed);
    EXPECT_EQ(seed_from_bits(0), 0u);
    EXPECT_TRUE(is_seed(seed_from_bits(13757245211066428519u)));
    EXPECT_FALSE(is_seed(kMaxSeed + 1));
}

}  // namespace
