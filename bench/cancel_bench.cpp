// How soon each stage stops once the cancel flag is set (the goal: cancel always within
// 100 ms). For each heavy case one full run marks where its stages begin and end (the
// tree's stage times, then the reduction); then, for every stage longer than 30 ms, the
// flag is set from another thread every 10% into it (9 runs) and the time from setting it
// to Cancelled reaching the caller is the latency. Prints one line per
// stage: its length and the largest and mean latency of its samples.
//
// Cases: oak at generations 12 (no reduction: the studio asks before reducing it), ternary
// at generations 7 and willow, both reduced to 800 as the studio does (finish_tree with a
// LOD chain).
//
// Usage: sylva-bench-cancel [CASE...]   (oak12, ternary7, willow; default all)

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdio>
#include <functional>
#include <initializer_list>
#include <string>
#include <thread>
#include <vector>

#include "core/cancel.h"
#include "export/export_tree.h"
#include "tree/pipeline.h"
#include "tree/template_library.h"
#include "turtle/lsystem_params.h"

namespace {

using namespace sylva;
using Clock = std::chrono::steady_clock;

double ms_between(Clock::time_point a, Clock::time_point b) {
    return std::chrono::duration<double, std::milli>(b - a).count();
}

struct Case {
    std::string name;
    std::string template_name;
    int generations = 0;  // 0: the template's
    std::size_t budget = 0;
};

// Runs `work` with the flag set `after_ms` into it; the ms from setting it to the throw,
// or a negative number when the work finished first.
double latency(const std::function<void(CancelFlag)>& work, double after_ms) {
    std::atomic<bool> cancel{false};
    std::atomic<bool> finished{false};
    Clock::time_point set_at{};
    const Clock::time_point start = Clock::now();
    std::thread setter([&] {
        std::this_thread::sleep_until(
            start + std::chrono::microseconds(static_cast<long long>(after_ms * 1000.0)));
        if (finished) return;
        set_at = Clock::now();
        cancel = true;
    });
    double result = -1.0;
    try {
        work(&cancel);
    } catch (const Cancelled&) {
        result = ms_between(set_at, Clock::now());
    }
    finished = true;
    setter.join();
    return result;
}

struct Span {
    std::string stage;
    double begin_ms = 0, ms = 0;
};

void report(const std::string& name, const Span& span, const std::function<void(CancelFlag)>& work,
            std::initializer_list<double> fractions = {0.1, 0.2, 0.3, 0.4, 0.5, 0.6, 0.7, 0.8,
                                                       0.9}) {
    if (span.ms < 30.0) {
        std::printf("%-9s %-20s %9.0f ms   (too short to sample)\n", name.c_str(),
                    span.stage.c_str(), span.ms);
        return;
    }
    double worst = 0, sum = 0;
    int samples = 0;
    for (double at : fractions) {
        const double l = latency(work, span.begin_ms + at * span.ms);
        if (l < 0) continue;
        worst = std::max(worst, l);
        sum += l;
        ++samples;
    }
    std::printf("%-9s %-20s %9.0f ms   max %7.1f ms   mean %7.1f ms   (%d samples)\n", name.c_str(),
                span.stage.c_str(), span.ms, worst, samples ? sum / samples : 0.0, samples);
    std::fflush(stdout);
}

void run_case(const Case& c) {
    TreeTemplate t = load_template(c.template_name);
    if (c.generations > 0) t.params.blocks.edit<LSystemParams>().generations = c.generations;
    MeshOptions options;
    options.budget = c.budget;
    auto generate = [&](CancelFlag cancel) {
        MeshOptions o = options;
        o.cancel = cancel;
        return generate_tree(t, o);
    };
    const Clock::time_point start = Clock::now();
    const Tree tree = generate(nullptr);
    const double generate_ms = ms_between(start, Clock::now());
    // The stage times run back to back; what they leave out (checks between stages) is
    // spread over them.
    double listed = 0;
    for (const StageTime& s : tree.times) listed += s.ms;
    const double scale = listed > 0 ? generate_ms / listed : 1.0;
    double at = 0;
    std::printf("%-9s generate %.0f ms, %zu trunk + %zu crown triangles\n", c.name.c_str(),
                generate_ms, tree.trunk.triangles.size(), tree.crown.triangles.size());
    for (const StageTime& s : tree.times) {
        const Span span{s.name, at, s.ms * scale};
        report(c.name, span, [&](CancelFlag cancel) { generate(cancel); });
        at += s.ms * scale;
    }
    if (c.budget == 0) return;
    FinishSettings finish;
    finish.budget.total = c.budget;
    finish.lod = true;
    auto reduce = [&](CancelFlag cancel) {
        FinishSettings f = finish;
        f.decimate.cancel = cancel;
        finish_tree(tree, f);
    };
    const Clock::time_point reduce_start = Clock::now();
    reduce(nullptr);
    const Span span{"reduce+LOD " + std::to_string(c.budget), 0,
                    ms_between(reduce_start, Clock::now())};
    report(c.name, span, reduce);
}

}  // namespace

int main(int argc, char** argv) {
    const std::vector<Case> cases = {
        {"oak12", "oak", 12, 0}, {"ternary7", "ternary", 7, 800}, {"willow", "willow", 0, 800}};
    std::vector<std::string> wanted(argv + 1, argv + argc);
    std::printf("cancel latency: flag set at 10, 20, .. 90%% of each stage, ms to Cancelled\n");
    for (const Case& c : cases)
        if (wanted.empty() || std::find(wanted.begin(), wanted.end(), c.name) != wanted.end())
            run_case(c);
    return 0;
}
