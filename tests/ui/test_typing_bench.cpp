// The typing bench's bookkeeping (ui/state/typing_bench.h) without a window: each character
// a frame shows more than the last is the oldest key waiting, keys before "ready" do not
// count, and the report names the figures. Times are the test's own.
#include <gtest/gtest.h>

#include <chrono>
#include <string>

#include "ui/state/typing_bench.h"

namespace sylva::studio {
namespace {

using std::chrono::milliseconds;

TEST(TypingBench, EachNewCharacterOnScreenIsTheOldestKeyWaiting) {
    TypingBench bench;
    bench.keys = 3;
    const auto t = TypingBench::Clock::now();
    typing_frame_shown(bench, 10, t, 5.0, false);  // before ready: only the length is taken
    EXPECT_TRUE(bench.samples.empty());
    bench.ready = true;
    typing_key_pressed(bench, t + milliseconds(100), true);
    typing_key_pressed(bench, t + milliseconds(110), false);
    typing_frame_shown(bench, 10, t + milliseconds(115), 5.0, true);  // nothing new yet
    EXPECT_TRUE(bench.samples.empty());
    typing_frame_shown(bench, 12, t + milliseconds(130), 15.0, true);  // both show at once
    ASSERT_EQ(bench.samples.size(), 2u);
    EXPECT_DOUBLE_EQ(bench.samples[0].ms, 30.0);
    EXPECT_TRUE(bench.samples[0].during_job);
    EXPECT_DOUBLE_EQ(bench.samples[1].ms, 20.0);
    EXPECT_FALSE(bench.samples[1].during_job);
    EXPECT_FALSE(typing_bench_done(bench));
    typing_key_pressed(bench, t + milliseconds(200), true);
    typing_frame_shown(bench, 13, t + milliseconds(240), 10.0, false);
    EXPECT_TRUE(typing_bench_done(bench));
    EXPECT_EQ(bench.copied_frames, 2);
    const std::string report = typing_bench_report(bench);
    EXPECT_NE(report.find("3 keys, 2 while a growth job ran"), std::string::npos) << report;
    EXPECT_NE(report.find("max 40.0 ms"), std::string::npos) << report;
}

TEST(TypingBench, PercentilesAreNearestRank) {
    EXPECT_EQ(percentile({}, 0.5), 0.0);
    EXPECT_EQ(percentile({3, 1, 2}, 0.5), 2.0);
    EXPECT_EQ(percentile({1, 2, 3, 4, 5, 6, 7, 8, 9, 10}, 0.9), 9.0);
    EXPECT_EQ(percentile({5, 7}, 1.0), 7.0);
}

}  // namespace
}  // namespace sylva::studio
