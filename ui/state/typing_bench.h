// The typing latency bench (sylva-studio --bench-typing): with a growth job always running,
// the time from each key the studio reads to the frame that shows its character, and the
// jobs' and frames' times, as one report. The keys come from outside (X events typed by
// bench/typing_latency_bench.cpp, which also measures key to glyph on the screen itself);
// this part only records and reports, headless.
//
// Thread safety: UI thread only.
#pragma once

#include <chrono>
#include <cstddef>
#include <deque>
#include <string>
#include <vector>

namespace sylva::studio {

struct TypingBench {
    using Clock = std::chrono::steady_clock;
    int keys = 0;  // characters on screen before the report
    struct Press {
        Clock::time_point at;
        bool during_job = false;
    };
    std::deque<Press> waiting;  // pressed, not on screen yet, oldest first
    struct Sample {
        double ms = 0;  // key read to its frame on screen
        bool during_job = false;
    };
    std::vector<Sample> samples;
    std::vector<double> frame_ms;  // each frame's work while the bench typed
    int copied_frames = 0;         // frames that copied the 3D view (ui/view_cache.h)
    std::vector<double> job_ms;    // each growth job that finished, start to tree on screen
    std::size_t shown_length = 0;  // the rules text's length on screen
    bool ready = false;            // "ready" was printed: the keys may come
};

// A key was read at `at` (a growth job running or not).
void typing_key_pressed(TypingBench& bench, TypingBench::Clock::time_point at, bool job_running);

// A frame is on screen at `now` showing a rules text of `length` bytes: each byte more than
// the last frame showed is the character of the oldest key waiting.
void typing_frame_shown(TypingBench& bench, std::size_t length, TypingBench::Clock::time_point now,
                        double frame_ms, bool copied_view);

bool typing_bench_done(const TypingBench& bench);

// "typing bench: 40 keys, 40 while a growth job ran (jobs: median 1050 ms); key read to its
// frame on screen: median 21 ms, 90% 34 ms, max 48 ms; frames: median 17 ms, max 40 ms, 250
// of 260 copied the 3D view".
std::string typing_bench_report(const TypingBench& bench);

// The value below which `fraction` of `values` lie (nearest rank); 0 for none.
double percentile(std::vector<double> values, double fraction);

}  // namespace sylva::studio
