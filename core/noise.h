// Seeded, deterministic coherent noise for variation (Limbach 2004, Perlin noise and
// L-systems): Ken Perlin's improved gradient noise (2002) in 1, 2 and 3 dimensions, the value
// noise of Limbach 2004 with linear, cosine and cubic interpolation, and fractal sums of
// octaves (fbm) with frequency, persistence and lacunarity. Nearby inputs give nearby values,
// so the noise bends a branch smoothly along its length or makes neighbouring trees alike.
//
// Every generator is seeded through core/random.h (splitmix64), so the same seed gives the
// same values on every machine. Objects are immutable after construction: one generator may
// be read by many threads at once. Non-finite inputs give 0; inputs beyond +-2^50 are wrapped
// into range first (the noise there has no meaningful precision anyway).
//
// GLM's glm::perlin is not used: it hashes lattice points with a fixed permutation polynomial
// (mod 289) that takes no seed, and it has no 1D form (see third_party_notes.md).
#pragma once

#include <array>
#include <cstdint>

namespace sylva {

// A fractal sum of `octaves` noise layers: layer k samples at frequency * lacunarity^k with
// amplitude persistence^k. fbm() divides by the sum of the amplitudes, so it stays in [-1, 1].
struct FbmSettings {
    int octaves = 4;           // 1..kMaxFbmOctaves
    double frequency = 1.0;    // of the first octave, > 0
    double persistence = 0.5;  // amplitude factor per octave, in [0, 1]
    double lacunarity = 2.0;   // frequency factor per octave, >= 1
};

inline constexpr int kMaxFbmOctaves = 16;

// Throws InputError naming the field ("octaves", "frequency", ...) when a setting is out of
// range; `what` prefixes the key (e.g. "fbm" -> "fbm.octaves").
void validate(const FbmSettings& settings, const char* what = "fbm");

// Improved Perlin gradient noise: a seeded permutation of 0..255 hashes the lattice corners to
// gradients; the quintic fade 6t^5 - 15t^4 + 10t^3 makes it C2. Zero at every integer point.
class GradientNoise {
  public:
    explicit GradientNoise(std::uint64_t seed);

    // Each is in [-1, 1] (scaled from the measured extremes, then clamped).
    double operator()(double x) const;
    double operator()(double x, double y) const;
    double operator()(double x, double y, double z) const;

    std::uint64_t seed() const { return seed_; }

  private:
    std::uint64_t seed_;
    std::array<std::uint8_t, 512> perm_{};  // the permutation twice, so p[p[x] + y] needs no mask
};

// Limbach's (2004) value noise: a random value in [-1, 1] at every lattice point, interpolated.
enum class Interpolation {
    linear,  // (1 - t) a + t b: continuous, kinks at lattice points
    cosine,  // t' = (1 - cos(pi t)) / 2: smooth, flat at lattice points
    cubic,   // through four neighbours (p t^3 + q t^2 + r t + s): smooth, may overshoot (clamped)
};

class ValueNoise {
  public:
    explicit ValueNoise(std::uint64_t seed, Interpolation interpolation = Interpolation::cubic);

    // Each is in [-1, 1].
    double operator()(double x) const;
    double operator()(double x, double y) const;
    double operator()(double x, double y, double z) const;

    std::uint64_t seed() const { return seed_; }
    Interpolation interpolation() const { return interpolation_; }

  private:
    double lattice(std::int64_t i) const;
    double lattice(std::int64_t i, std::int64_t j) const;
    double lattice(std::int64_t i, std::int64_t j, std::int64_t k) const;

    std::uint64_t seed_;
    Interpolation interpolation_;
};

// Fractal sums, in [-1, 1]. Each octave samples a shifted domain so octaves are not aligned at
// the origin (Limbach 2004: "each octave needs its own noise function"). Settings are clamped to
// the ranges of FbmSettings (validate() them where they come from user input).
double fbm(const GradientNoise& noise, double x, const FbmSettings& s);
double fbm(const GradientNoise& noise, double x, double y, const FbmSettings& s);
double fbm(const GradientNoise& noise, double x, double y, double z, const FbmSettings& s);
double fbm(const ValueNoise& noise, double x, const FbmSettings& s);
double fbm(const ValueNoise& noise, double x, double y, const FbmSettings& s);
double fbm(const ValueNoise& noise, double x, double y, double z, const FbmSettings& s);

// Which noise a field samples: Perlin's gradient noise, or Limbach's (2004) value noise with
// one of its three interpolations (the `noise_kind` parameter, docs/noise.md).
enum class NoiseKind { gradient = 0, value_linear = 1, value_cosine = 2, value_cubic = 3 };

// One seeded noise field of a chosen kind, so callers (expressions, the turtle's variation)
// pick the kind without a template per kind. With NoiseKind::gradient it gives exactly the
// values of GradientNoise(seed). Immutable after construction; any number of threads may
// read it at once.
class NoiseField {
  public:
    explicit NoiseField(std::uint64_t seed, NoiseKind kind = NoiseKind::gradient);

    // Each is in [-1, 1].
    double operator()(double x) const;
    double operator()(double x, double y) const;
    double operator()(double x, double y, double z) const;

    NoiseKind kind() const { return kind_; }
    std::uint64_t seed() const { return gradient_.seed(); }

  private:
    NoiseKind kind_;
    GradientNoise gradient_;
    ValueNoise value_;
};

double fbm(const NoiseField& noise, double x, const FbmSettings& s);
double fbm(const NoiseField& noise, double x, double y, const FbmSettings& s);
double fbm(const NoiseField& noise, double x, double y, double z, const FbmSettings& s);

// Noise that loops in time (Limbach 2004: for animation the time coordinate wraps, so the
// end of a loop runs into its start, as wind must): the value at (x, t) equals the value at
// (x, t + period) for every t, and is as smooth and as fine (one lattice cell per unit of
// t) as noise(x, t). Time walks around a circle of circumference `period` in a plane of its
// own (the 3D field at (x, r cos a, r sin a), a = 2 pi t / period) rather than wrapping the
// lattice, so every kind of noise loops alike. A period below 1 is taken as 1. In [-1, 1].
double looping_noise(const NoiseField& noise, double x, double t, double period);
// Its fractal sum: octave k walks a circle k-fold larger, so each octave loops with the
// same period.
double looping_fbm(const NoiseField& noise, double x, double t, double period,
                   const FbmSettings& s);

// A seed derived from a base seed and a stream number (splitmix64 of both), for the many
// independent noise fields one tree needs (bend, jitter, colour, ...).
std::uint64_t derive_seed(std::uint64_t base, std::uint64_t stream);

// The streams of one tree's seed, so each use of noise has its own field and adding a use
// does not change the others.
namespace noise_stream {
inline constexpr std::uint64_t expressions = 1;  // noise() and fbm() in rules
inline constexpr std::uint64_t bend = 2;         // turtle: coherent bending along branches
inline constexpr std::uint64_t jitter = 3;       // turtle: per-branch angle and length factors
inline constexpr std::uint64_t width = 4;        // turtle: width along branches
inline constexpr std::uint64_t tropism = 5;      // tropism vector per branch / per node
inline constexpr std::uint64_t color = 6;        // part colours per tree
}  // namespace noise_stream

}  // namespace sylva
