#include "ui/state/typing_bench.h"

#include <algorithm>
#include <cmath>
#include <cstdio>

namespace sylva::studio {

void typing_key_pressed(TypingBench& bench, TypingBench::Clock::time_point at, bool job_running) {
    bench.waiting.push_back({at, job_running});
}

void typing_frame_shown(TypingBench& bench, std::size_t length, TypingBench::Clock::time_point now,
                        double frame_ms, bool copied_view) {
    if (!bench.ready) {
        bench.shown_length = length;
        return;
    }
    bench.frame_ms.push_back(frame_ms);
    bench.copied_frames += copied_view ? 1 : 0;
    for (std::size_t n = bench.shown_length; n < length && !bench.waiting.empty(); ++n) {
        const TypingBench::Press press = bench.waiting.front();
        bench.waiting.pop_front();
        bench.samples.push_back(
            {std::chrono::duration<double, std::milli>(now - press.at).count(), press.during_job});
    }
    bench.shown_length = length;
}

bool typing_bench_done(const TypingBench& bench) {
    return bench.keys > 0 && static_cast<int>(bench.samples.size()) >= bench.keys;
}

double percentile(std::vector<double> values, double fraction) {
    if (values.empty()) return 0.0;
    std::sort(values.begin(), values.end());
    const auto rank =
        static_cast<std::size_t>(std::ceil(fraction * static_cast<double>(values.size())));
    return values[std::clamp<std::size_t>(rank, 1, values.size()) - 1];
}

std::string typing_bench_report(const TypingBench& bench) {
    std::vector<double> ms;
    int during = 0;
    for (const TypingBench::Sample& s : bench.samples) {
        ms.push_back(s.ms);
        during += s.during_job ? 1 : 0;
    }
    char text[512];
    std::snprintf(text, sizeof text,
                  "typing bench: %zu keys, %d while a growth job ran (%zu jobs finished meanwhile, "
                  "median %.0f ms); key read to its frame on screen: median %.1f ms, 90%% %.1f ms, "
                  "max %.1f ms; frames: median %.1f ms, max %.1f ms, %d of %zu copied the 3D view",
                  bench.samples.size(), during, bench.job_ms.size(), percentile(bench.job_ms, 0.5),
                  percentile(ms, 0.5), percentile(ms, 0.9), percentile(ms, 1.0),
                  percentile(bench.frame_ms, 0.5), percentile(bench.frame_ms, 1.0),
                  bench.copied_frames, bench.frame_ms.size());
    return text;
}

}  // namespace sylva::studio
