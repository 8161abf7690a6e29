// One noise field of a chosen kind (gradient or Limbach's value noises), and noise that
// loops in time: periodic, continuous, and as varied as the plain noise.
#include <gtest/gtest.h>

#include <cmath>

#include "core/noise.h"

namespace sylva {
namespace {

TEST(NoiseField, EachKindIsItsNoise) {
    const GradientNoise gradient(5);
    const ValueNoise linear(5, Interpolation::linear), cosine(5, Interpolation::cosine),
        cubic(5, Interpolation::cubic);
    const NoiseField g(5), l(5, NoiseKind::value_linear), c(5, NoiseKind::value_cosine),
        k(5, NoiseKind::value_cubic);
    for (int i = 0; i < 50; ++i) {
        const double x = 0.31 * i - 4.0, y = 1.7 - 0.13 * i, z = 0.07 * i;
        EXPECT_EQ(g(x), gradient(x));
        EXPECT_EQ(g(x, y, z), gradient(x, y, z));
        EXPECT_EQ(l(x, y), linear(x, y));
        EXPECT_EQ(c(x, y, z), cosine(x, y, z));
        EXPECT_EQ(k(x), cubic(x));
    }
    const FbmSettings s{3, 1.0, 0.5, 2.0};
    EXPECT_EQ(fbm(g, 0.3, 0.9, s), fbm(gradient, 0.3, 0.9, s));
    EXPECT_EQ(fbm(c, 0.3, 0.9, 1.1, s), fbm(cosine, 0.3, 0.9, 1.1, s));
}

TEST(LoopingNoise, RepeatsWithItsPeriodAndIsContinuous) {
    for (NoiseKind kind : {NoiseKind::gradient, NoiseKind::value_cosine}) {
        const NoiseField n(9, kind);
        const double period = 7.5;
        double lo = 1.0, hi = -1.0;
        for (int i = 0; i < 300; ++i) {
            const double t = 0.05 * i, x = 0.4;
            EXPECT_NEAR(looping_noise(n, x, t, period), looping_noise(n, x, t + period, period),
                        1e-6);
            EXPECT_NEAR(looping_noise(n, x, t, period), looping_noise(n, x, t - 2 * period, period),
                        1e-6);
            const FbmSettings s{4, 1.0, 0.5, 2.0};
            EXPECT_NEAR(looping_fbm(n, x, t, period, s), looping_fbm(n, x, t + period, period, s),
                        1e-6);
            // Small steps in time, small changes (the end runs into the start the same way).
            EXPECT_LT(
                std::abs(looping_noise(n, x, t + 0.01, period) - looping_noise(n, x, t, period)),
                0.1);
            const double v = looping_noise(n, x, t, period);
            lo = std::min(lo, v);
            hi = std::max(hi, v);
        }
        EXPECT_GT(hi - lo, 0.3);  // it does vary over a loop
    }
    // Non-finite input and a period below 1 stay in range.
    const NoiseField n(1);
    EXPECT_TRUE(std::isfinite(looping_noise(n, 0.0, INFINITY, 0.0)));
    EXPECT_LE(std::abs(looping_noise(n, 0.0, 3.0, NAN)), 1.0);
}

}  // namespace
}  // namespace sylva
