// Noise: seeded and deterministic, inside [-1, 1] and using that range, continuous, zero on
// the lattice (gradient) or through the lattice values (value noise), and fbm's settings.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <string>

#include "core/errors.h"
#include "core/noise.h"
#include "core/random.h"

namespace sylva {
namespace {

// Extremes and mean of |f| over n random points in a 64-unit cube.
template <class F>
void sample_stats(F&& f, int n, double& lo, double& hi, double& mean) {
    Random random(7);
    lo = 1e9;
    hi = -1e9;
    double sum = 0.0;
    for (int i = 0; i < n; ++i) {
        const double v = f(random.uniform() * 64.0 - 32.0, random.uniform() * 64.0 - 32.0,
                           random.uniform() * 64.0);
        lo = std::min(lo, v);
        hi = std::max(hi, v);
        sum += v;
    }
    mean = sum / n;
}

TEST(GradientNoise, SameSeedSameValuesOtherSeedOtherValues) {
    const GradientNoise a(42), b(42), c(43);
    int differ = 0;
    for (int i = 0; i < 100; ++i) {
        const double x = 0.37 * i, y = 1.3 - 0.11 * i, z = 0.05 * i * i;
        EXPECT_EQ(a(x), b(x));
        EXPECT_EQ(a(x, y), b(x, y));
        EXPECT_EQ(a(x, y, z), b(x, y, z));
        differ += a(x, y, z) != c(x, y, z);
    }
    EXPECT_GT(differ, 90);
}

// Pinned values: gradient noise is pure integer and double arithmetic, so these are the same
// on every machine; a change here changes every tree that uses noise (and the batch/forest
// outputs built on it).
TEST(GradientNoise, PinnedValues) {
    const GradientNoise n(2026);
    EXPECT_DOUBLE_EQ(n(0.3), n(0.3));
    const double v1 = n(0.3), v2 = n(0.3, 1.7), v3 = n(0.3, 1.7, 2.9);
    EXPECT_NEAR(v1, -0.14609279999999997, 1e-15);
    EXPECT_NEAR(v2, -0.13151684448000006, 1e-15);
    EXPECT_NEAR(v3, 0.23843427918177443, 1e-15);
}

TEST(GradientNoise, ZeroOnTheLattice) {
    const GradientNoise n(5);
    for (int i = -3; i <= 3; ++i) {
        EXPECT_EQ(n(i), 0.0);
        EXPECT_EQ(n(i, 2 * i), 0.0);
        EXPECT_EQ(n(i, 2 * i, -i), 0.0);
    }
}

TEST(GradientNoise, StaysInRangeUsesItAndAveragesNearZero) {
    const GradientNoise n(11);
    double lo, hi, mean;
    sample_stats([&](double x, double, double) { return n(x); }, 200000, lo, hi, mean);
    EXPECT_GE(lo, -1.0);
    EXPECT_LE(hi, 1.0);
    EXPECT_GT(hi - lo, 1.2) << "1D";
    EXPECT_NEAR(mean, 0.0, 0.05);
    sample_stats([&](double x, double y, double) { return n(x, y); }, 200000, lo, hi, mean);
    EXPECT_GE(lo, -1.0);
    EXPECT_LE(hi, 1.0);
    EXPECT_GT(hi - lo, 1.2) << "2D";
    EXPECT_NEAR(mean, 0.0, 0.05);
    sample_stats([&](double x, double y, double z) { return n(x, y, z); }, 200000, lo, hi, mean);
    EXPECT_GE(lo, -1.0);
    EXPECT_LE(hi, 1.0);
    EXPECT_GT(hi - lo, 1.2) << "3D";
    EXPECT_NEAR(mean, 0.0, 0.05);
}

TEST(GradientNoise, IsContinuous) {
    const GradientNoise n(3);
    Random random(1);
    const double h = 1e-5;
    for (int i = 0; i < 2000; ++i) {
        const double x = random.uniform() * 50, y = random.uniform() * 50,
                     z = random.uniform() * 50;
        // Slopes are bounded (a few units per unit), so a tiny step moves the value a little.
        EXPECT_LT(std::abs(n(x + h) - n(x)), 10 * h);
        EXPECT_LT(std::abs(n(x, y + h) - n(x, y)), 10 * h);
        EXPECT_LT(std::abs(n(x, y, z + h) - n(x, y, z)), 10 * h);
    }
}

TEST(GradientNoise, NonFiniteGivesZeroAndHugeInputsStayInRange) {
    const GradientNoise n(9);
    const double inf = std::numeric_limits<double>::infinity();
    const double nan = std::numeric_limits<double>::quiet_NaN();
    EXPECT_EQ(n(inf), 0.0);
    EXPECT_EQ(n(1.5, nan), 0.0);
    EXPECT_EQ(n(0.5, 0.5, -inf), 0.0);
    for (const double big : {1e16, -3e20, 1e300}) {
        EXPECT_LE(std::abs(n(big + 0.5, 0.25, -big)), 1.0);
        EXPECT_TRUE(std::isfinite(n(big, big)));
    }
}

TEST(ValueNoise, AllInterpolationsPassThroughTheSameLatticeValues) {
    const ValueNoise linear(8, Interpolation::linear), cosine(8, Interpolation::cosine),
        cubic(8, Interpolation::cubic);
    for (int i = -4; i <= 4; ++i) {
        EXPECT_DOUBLE_EQ(linear(i), cosine(i));
        EXPECT_DOUBLE_EQ(linear(i), cubic(i));
        EXPECT_DOUBLE_EQ(linear(i, 3 - i), cosine(i, 3 - i));
        EXPECT_DOUBLE_EQ(linear(i, 3 - i), cubic(i, 3 - i));
        EXPECT_DOUBLE_EQ(linear(i, 3 - i, i * i), cosine(i, 3 - i, i * i));
        EXPECT_DOUBLE_EQ(linear(i, 3 - i, i * i), cubic(i, 3 - i, i * i));
    }
    // Linear halfway is the mean of the neighbours; cosine is flat at a lattice point.
    EXPECT_DOUBLE_EQ(linear(2.5), 0.5 * (linear(2.0) + linear(3.0)));
    const double h = 1e-4;
    EXPECT_LT(std::abs(cosine(2.0 + h) - cosine(2.0)), 1e-6);
    EXPECT_GT(std::abs(linear(2.0 + h) - linear(2.0)), 1e-7);
}

TEST(ValueNoise, InRangeDeterministicAndSeeded) {
    for (const auto mode : {Interpolation::linear, Interpolation::cosine, Interpolation::cubic}) {
        const ValueNoise n(21, mode), same(21, mode), other(22, mode);
        double lo, hi, mean;
        sample_stats([&](double x, double y, double z) { return n(x, y, z); }, 50000, lo, hi, mean);
        EXPECT_GE(lo, -1.0);
        EXPECT_LE(hi, 1.0);
        EXPECT_GT(hi - lo, 1.2);
        EXPECT_EQ(n(1.25, 2.5, 3.75), same(1.25, 2.5, 3.75));
        EXPECT_NE(n(1.25, 2.5, 3.75), other(1.25, 2.5, 3.75));
    }
}

TEST(Fbm, OneOctaveIsTheNoiseAtTheFrequency) {
    const GradientNoise n(4);
    const FbmSettings one{1, 2.5, 0.5, 2.0};
    EXPECT_DOUBLE_EQ(fbm(n, 0.3, one), n(0.75));
    EXPECT_DOUBLE_EQ(fbm(n, 0.3, 0.7, one), n(0.75, 1.75));
    EXPECT_DOUBLE_EQ(fbm(n, 0.3, 0.7, 1.1, one), n(0.75, 1.75, 2.75));
    // Zero persistence silences the higher octaves.
    const FbmSettings silent{6, 2.5, 0.0, 2.0};
    EXPECT_DOUBLE_EQ(fbm(n, 0.3, 0.7, 1.1, silent), n(0.75, 1.75, 2.75));
}

TEST(Fbm, MoreOctavesAddDetailAndStayInRange) {
    const GradientNoise n(4);
    const ValueNoise v(4);
    const FbmSettings s{6, 1.0, 0.6, 2.0};
    double lo, hi, mean;
    sample_stats([&](double x, double y, double z) { return fbm(n, x, y, z, s); }, 20000, lo, hi,
                 mean);
    EXPECT_GE(lo, -1.0);
    EXPECT_LE(hi, 1.0);
    sample_stats([&](double x, double y, double z) { return fbm(v, x, y, z, s); }, 20000, lo, hi,
                 mean);
    EXPECT_GE(lo, -1.0);
    EXPECT_LE(hi, 1.0);
    // Detail: over a short step the 6-octave sum changes more than the first octave alone.
    double rough = 0.0, smooth = 0.0;
    const FbmSettings one{1, 1.0, 0.6, 2.0};
    for (int i = 0; i < 1000; ++i) {
        const double x = 0.013 * i;
        rough += std::abs(fbm(n, x + 0.01, s) - fbm(n, x, s));
        smooth += std::abs(fbm(n, x + 0.01, one) - fbm(n, x, one));
    }
    EXPECT_GT(rough, 1.2 * smooth);
}

TEST(Fbm, ValidateNamesTheKey) {
    EXPECT_NO_THROW(validate(FbmSettings{}));
    const auto message = [](FbmSettings s) {
        try {
            validate(s, "bend");
        } catch (const InputError& e) {
            return std::string(e.what());
        }
        return std::string();
    };
    EXPECT_NE(message({0, 1, 0.5, 2}).find("bend.octaves"), std::string::npos);
    EXPECT_NE(message({17, 1, 0.5, 2}).find("bend.octaves"), std::string::npos);
    EXPECT_NE(message({4, 0, 0.5, 2}).find("bend.frequency"), std::string::npos);
    EXPECT_NE(message({4, 1, 1.5, 2}).find("bend.persistence"), std::string::npos);
    EXPECT_NE(message({4, 1, 0.5, 0.5}).find("bend.lacunarity"), std::string::npos);
}

TEST(DeriveSeed, StreamsDifferAndRepeat) {
    EXPECT_EQ(derive_seed(1, 2), derive_seed(1, 2));
    EXPECT_NE(derive_seed(1, 2), derive_seed(1, 3));
    EXPECT_NE(derive_seed(1, 2), derive_seed(2, 2));
}

}  // namespace
}  // namespace sylva
