// How one meshing call runs: on how many threads, how it reports progress, when it stops
// for a cancel request and what it counts. Shared by every mesher (dense, sparse, OpenVDB)
// so they honour MeshSettings the same way.
#pragma once

#include <tbb/blocked_range.h>
#include <tbb/parallel_for.h>
#include <tbb/partitioner.h>
#include <tbb/task_arena.h>

#include <atomic>
#include <cstddef>
#include <mutex>

#include "marching/mesher.h"

namespace sylva::detail {

class MeshingRun {
  public:
    // `serial` runs every loop on the calling thread, whatever settings.threads says (the
    // ScalarField overload promises that to fields that are not thread-safe).
    MeshingRun(const MeshSettings& settings, bool serial) : settings_(settings), serial_(serial) {}

    // Runs `work` in an arena of settings.threads workers (0: the caller's arena).
    template <class Work>
    auto execute(Work&& work) {
        if (serial_ || settings_.threads <= 0) return work();
        tbb::task_arena arena(settings_.threads);
        return arena.execute(work);
    }

    // Calls item(i) for every i in [0, n), in parallel unless serial. The cancel flag is
    // polled before each item, so items should be a few tens of microseconds or more;
    // throws Cancelled once it is seen, after the running items have finished.
    template <class Item>
    void for_each(std::size_t n, Item&& item) {
        if (serial_) {
            for (std::size_t i = 0; i < n; ++i) {
                throw_if_cancelled();
                item(i);
            }
            return;
        }
        // One item per task: items are already coarse, and the simple partitioner keeps
        // the cancel latency to one item.
        tbb::parallel_for(
            tbb::blocked_range<std::size_t>(0, n, 1),
            [&](const tbb::blocked_range<std::size_t>& r) {
                for (std::size_t i = r.begin(); i != r.end(); ++i) {
                    if (cancelled()) return;
                    item(i);
                }
            },
            tbb::simple_partitioner());
        throw_if_cancelled();
    }

    // Calls the field on one batch and counts it. Isolated: a field that runs its own TBB
    // loops must not let this thread, while it waits for them, pick up another of our
    // items, which would reuse the thread's scratch buffers under the batch being filled.
    void evaluate(const BatchField& field, std::span<const glm::vec3> points,
                  std::span<float> values) {
        if (points.empty()) return;
        tbb::this_task_arena::isolate([&] { field(points, values); });
        evaluations_.fetch_add(points.size(), std::memory_order_relaxed);
    }

    bool cancelled() const { return is_cancelled(settings_.cancel); }

    // Also between phases, and around work that cannot poll (a library call).
    void throw_if_cancelled() const { sylva::throw_if_cancelled(settings_.cancel); }

    // Progress runs through phases: phase fraction done/units maps to [start, start + weight].
    // Called from the calling thread between parallel loops.
    void begin_phase(float start, float weight, std::size_t units) {
        phase_start_ = start;
        phase_weight_ = weight;
        phase_units_ = units;
        phase_done_.store(0, std::memory_order_relaxed);
        report(start);
    }

    // Thread-safe: `units` more of the current phase are done.
    void advance(std::size_t units = 1) {
        if (!settings_.progress || phase_units_ == 0) return;
        const std::size_t done = phase_done_.fetch_add(units, std::memory_order_relaxed) + units;
        report(phase_start_ + phase_weight_ * float(double(done) / double(phase_units_)));
    }

    // The last progress report, exactly 1.
    void finish() { report(1.0f); }

    std::size_t evaluations() const { return evaluations_.load(std::memory_order_relaxed); }

  private:
    // Serialised and filtered so the callback sees a non-decreasing sequence even when
    // workers finish out of order, and not thousands of calls for tiny steps.
    void report(float fraction) {
        if (!settings_.progress) return;
        std::lock_guard lock(progress_mutex_);
        const bool last = fraction >= 1.0f;
        if (last ? reported_ >= 1.0f : fraction < reported_ + 0.005f) return;
        reported_ = last ? 1.0f : fraction;
        settings_.progress(reported_);
    }

    const MeshSettings& settings_;
    const bool serial_;
    std::atomic<std::size_t> evaluations_{0};
    float phase_start_ = 0.0f;
    float phase_weight_ = 0.0f;
    std::size_t phase_units_ = 0;
    std::atomic<std::size_t> phase_done_{0};
    std::mutex progress_mutex_;
    float reported_ = -1.0f;
};

}  // namespace sylva::detail
