// Wall-clock time of a stage, in milliseconds.
#pragma once

#include <chrono>

namespace sylva {

class Stopwatch {
  public:
    // Milliseconds since construction or the previous lap.
    double lap_ms() {
        auto now = std::chrono::steady_clock::now();
        double ms = std::chrono::duration<double, std::milli>(now - start_).count();
        start_ = now;
        return ms;
    }

  private:
    std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

}  // namespace sylva
