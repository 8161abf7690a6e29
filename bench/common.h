// What the benchmark executables share: the studio's heap, the built-in templates as the
// default list, medians, flags, best-of-N wall and CPU timing, and a Table that prints aligned text
// for a terminal or, with
// --markdown, a Markdown table (scripts/bench-tables splices those into docs/benchmarks.md).
// Single-threaded helpers for main(); not for the code under measurement.
#pragma once

#include <algorithm>
#include <chrono>
#include <cstdarg>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <limits>
#include <string>
#include <string_view>
#include <vector>

#include "platform/large_pages.h"

namespace sylva::bench {

// The studio's heap (platform/large_pages.h): benchmarks whose exports follow each other in
// one process, as the studio's do, measure with it. SYLVA_NO_LARGE_PAGES=1 measures without.
inline void use_studio_heap() {
    if (!std::getenv("SYLVA_NO_LARGE_PAGES")) keep_freed_memory();
}

// Removes every `flag` from `args`; true when there was one.
inline bool take_flag(std::vector<std::string>& args, std::string_view flag) {
    return std::erase(args, std::string(flag)) > 0;
}

// The middle value (the upper one of an even count); 0 for none.
inline double median(std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
}

// CPU time used so far by the calling thread, and by all threads of the process, in ms.
inline double thread_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}
inline double process_cpu_ms() {
    timespec t{};
    clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
    return 1e3 * static_cast<double>(t.tv_sec) + 1e-6 * static_cast<double>(t.tv_nsec);
}

// The best (smallest) wall time and the best CPU time of all threads of some runs, in ms;
// on a shared machine the CPU time is the steadier figure (work on two threads: cpu / 2).
struct Times {
    double wall_ms = std::numeric_limits<double>::max();
    double cpu_ms = std::numeric_limits<double>::max();
};

// The best of `runs` calls of f() (at least one).
template <class F>
Times best_of(int runs, F&& f) {
    Times best;
    for (int r = 0; r < std::max(runs, 1); ++r) {
        const auto start = std::chrono::steady_clock::now();
        const double cpu = process_cpu_ms();
        f();
        best.cpu_ms = std::min(best.cpu_ms, process_cpu_ms() - cpu);
        best.wall_ms = std::min(best.wall_ms, std::chrono::duration<double, std::milli>(
                                                  std::chrono::steady_clock::now() - start)
                                                  .count());
    }
    return best;
}

// printf into a std::string, for a table's cells.
inline std::string format(const char* pattern, ...) {
    va_list args;
    va_start(args, pattern);
    char text[256];
    std::vsnprintf(text, sizeof text, pattern, args);
    va_end(args);
    return text;
}

// Rows of cells under a header; the first column is left-aligned, the others right-aligned.
class Table {
  public:
    explicit Table(std::vector<std::string> header) : rows_{std::move(header)} {}

    void row(std::vector<std::string> cells) {
        cells.resize(rows_.front().size());
        rows_.push_back(std::move(cells));
    }

    // Aligned columns, or a Markdown table.
    void print(bool markdown, std::FILE* to = stdout) const {
        std::vector<std::size_t> width(rows_.front().size(), 3);
        for (const auto& r : rows_)
            for (std::size_t c = 0; c < r.size(); ++c) width[c] = std::max(width[c], r[c].size());
        for (std::size_t i = 0; i < rows_.size(); ++i) {
            const auto& r = rows_[i];
            for (std::size_t c = 0; c < r.size(); ++c) {
                const int w = static_cast<int>(width[c]);
                if (markdown)
                    std::fprintf(to, "| %s ", r[c].c_str());
                else
                    std::fprintf(to, c == 0 ? "%-*s" : "  %*s", w, r[c].c_str());
            }
            std::fprintf(to, markdown ? "|\n" : "\n");
            if (markdown && i == 0) {
                for (std::size_t c = 0; c < r.size(); ++c)
                    std::fprintf(to, c == 0 ? "|---" : "|---:");
                std::fprintf(to, "|\n");
            }
        }
        std::fflush(to);
    }

  private:
    std::vector<std::vector<std::string>> rows_;
};

}  // namespace sylva::bench
