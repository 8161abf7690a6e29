// The project's one seeded random source: splitmix64, so the same seed gives the same numbers
// on every machine and standard library (std:: distributions do not). Behind rand(a,b),
// stochastic rules, leaf scattering and surface sampling.
#pragma once

#include <cstdint>

namespace sylva {

class Random {
  public:
    explicit Random(std::uint64_t seed) : state_(seed) {}

    std::uint64_t next() {
        std::uint64_t z = (state_ += kGamma);
        z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
        z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
        return z ^ (z >> 31);
    }

    // Skips n numbers: the same state as n calls of next() (splitmix64's state only counts).
    void discard(std::uint64_t n) { state_ += n * kGamma; }

    // Uniform in [0, 1).
    double uniform() { return static_cast<double>(next() >> 11) * 0x1.0p-53; }

  private:
    static constexpr std::uint64_t kGamma = 0x9e3779b97f4a7c15ULL;
    std::uint64_t state_;
};

}  // namespace sylva
