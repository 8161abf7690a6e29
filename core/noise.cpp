#include "core/noise.h"

#include <algorithm>
#include <cmath>
#include <numbers>
#include <string>

#include "core/errors.h"
#include "core/random.h"

namespace sylva {

namespace {

// Scales that map the extremes of each gradient noise to +-1. 1D: 0.5 at x = 1/2 between
// slopes +1 and -1. 2D: 1.0 at a cell centre where four diagonals point in. 3D: 1.0203,
// found by hill-climbing |noise| from 400,000 random starts over 20 seeds (slightly off the
// cell centre). The result is clamped, so a higher unseen peak would only flatten a little.
constexpr double kScale1 = 2.0;
constexpr double kScale2 = 1.0;
constexpr double kScale3 = 1.0 / 1.0203;

// Beyond this the lattice index no longer fits comfortably and fractions are meaningless.
constexpr double kWrapLimit = 0x1p50;

// Brings a coordinate into [-2^50, 2^50]; false for NaN or infinity. Gradient noise repeats
// every 256 units, so wrapping by a multiple of 256 changes nothing there.
inline bool tame(double& x) {
    if (std::abs(x) < kWrapLimit) {
        return true;
    }
    if (!std::isfinite(x)) {
        return false;
    }
    x = std::fmod(x, 65536.0);
    return true;
}

inline std::int64_t floor_int(double x) {
    const auto i = static_cast<std::int64_t>(x);
    return i - static_cast<std::int64_t>(x < static_cast<double>(i));
}

inline double fade(double t) {
    return t * t * t * (t * (t * 6.0 - 15.0) + 10.0);
}
inline double lerp(double t, double a, double b) {
    return a + t * (b - a);
}

// 1D: 16 evenly spaced slopes in [-1, 1].
inline double grad1(std::uint8_t h, double x) {
    return (static_cast<double>(h & 15) * (2.0 / 15.0) - 1.0) * x;
}

// 2D: the four axis and four diagonal directions.
inline double grad2(std::uint8_t h, double x, double y) {
    switch (h & 7) {
        case 0:
            return x + y;
        case 1:
            return -x + y;
        case 2:
            return x - y;
        case 3:
            return -x - y;
        case 4:
            return x;
        case 5:
            return -x;
        case 6:
            return y;
        default:
            return -y;
    }
}

// 3D: Perlin's 12 cube-edge directions (4 of them twice, to fill 16), as a table: a branchy
// switch mispredicts on random hashes and costs a third of the time.
struct Gradient3 {
    double x, y, z;
};
constexpr Gradient3 kGradients3[16] = {
    {1, 1, 0}, {-1, 1, 0}, {1, -1, 0}, {-1, -1, 0}, {1, 0, 1}, {-1, 0, 1}, {1, 0, -1}, {-1, 0, -1},
    {0, 1, 1}, {0, -1, 1}, {0, 1, -1}, {0, -1, -1}, {1, 1, 0}, {0, -1, 1}, {-1, 1, 0}, {0, -1, -1},
};

inline double grad3(std::uint8_t h, double x, double y, double z) {
    const Gradient3& g = kGradients3[h & 15];
    return g.x * x + g.y * y + g.z * z;
}

inline double clamp_unit(double v) {
    return std::clamp(v, -1.0, 1.0);
}

// splitmix64's finaliser: a good 64-bit mix for lattice hashing.
inline std::uint64_t mix(std::uint64_t z) {
    z = (z ^ (z >> 30)) * 0xbf58476d1ce4e5b9ULL;
    z = (z ^ (z >> 27)) * 0x94d049bb133111ebULL;
    return z ^ (z >> 31);
}

inline double unit_from_hash(std::uint64_t h) {
    return static_cast<double>(h >> 11) * 0x1.0p-52 - 1.0;  // [-1, 1)
}

inline double cosine_t(double t) {
    return (1.0 - std::cos(t * std::numbers::pi)) * 0.5;
}

// Limbach's (2004) cubic through v1 (t = 0) and v2 (t = 1) using the outer neighbours v0 and v3.
inline double cubic(double v0, double v1, double v2, double v3, double t) {
    const double p = (v3 - v2) - (v0 - v1);
    const double q = (v0 - v1) - p;
    const double r = v2 - v0;
    return ((p * t + q) * t + r) * t + v1;
}

// Per-octave domain shifts: irrational-looking offsets so octaves do not share a lattice origin.
constexpr double kOctaveShift[3] = {19.19, 33.71, 47.63};

struct OctaveWalk {
    int octaves;
    double frequency, persistence, lacunarity;
};

inline OctaveWalk clamp_settings(const FbmSettings& s) {
    return {std::clamp(s.octaves, 1, kMaxFbmOctaves), s.frequency,
            std::clamp(s.persistence, 0.0, 1.0), std::max(s.lacunarity, 1.0)};
}

template <class Sample>
double fractal_sum(const FbmSettings& settings, Sample&& sample) {
    const OctaveWalk w = clamp_settings(settings);
    double frequency = w.frequency;
    double amplitude = 1.0;
    double sum = 0.0;
    double norm = 0.0;
    for (int k = 0; k < w.octaves; ++k) {
        sum += amplitude * sample(frequency, static_cast<double>(k));
        norm += amplitude;
        frequency *= w.lacunarity;
        amplitude *= w.persistence;
    }
    return clamp_unit(sum / norm);
}

}  // namespace

void validate(const FbmSettings& s, const char* what) {
    const std::string prefix = std::string(what) + ".";
    if (s.octaves < 1 || s.octaves > kMaxFbmOctaves) {
        throw InputError(prefix + "octaves must be in 1.." + std::to_string(kMaxFbmOctaves) +
                         ", got " + std::to_string(s.octaves));
    }
    if (!(s.frequency > 0.0) || !std::isfinite(s.frequency)) {
        throw InputError(prefix + "frequency must be a positive number, got " +
                         std::to_string(s.frequency));
    }
    if (!(s.persistence >= 0.0 && s.persistence <= 1.0)) {
        throw InputError(prefix + "persistence must be in [0, 1], got " +
                         std::to_string(s.persistence));
    }
    if (!(s.lacunarity >= 1.0) || !std::isfinite(s.lacunarity)) {
        throw InputError(prefix + "lacunarity must be >= 1, got " + std::to_string(s.lacunarity));
    }
}

std::uint64_t derive_seed(std::uint64_t base, std::uint64_t stream) {
    Random random(base ^ mix(stream + 0x632be59bd9b4e019ULL));
    return random.next();
}

// ---- gradient noise ----

GradientNoise::GradientNoise(std::uint64_t seed) : seed_(seed) {
    std::array<std::uint8_t, 256> p{};
    for (int i = 0; i < 256; ++i) {
        p[static_cast<std::size_t>(i)] = static_cast<std::uint8_t>(i);
    }
    Random random(seed);
    for (std::size_t i = 255; i > 0; --i) {  // Fisher-Yates, with our own uniform draw
        const auto j = static_cast<std::size_t>(random.next() % (i + 1));
        std::swap(p[i], p[j]);
    }
    for (std::size_t i = 0; i < 512; ++i) {
        perm_[i] = p[i & 255];
    }
}

double GradientNoise::operator()(double x) const {
    if (!tame(x)) {
        return 0.0;
    }
    const std::int64_t xi = floor_int(x);
    const double fx = x - static_cast<double>(xi);
    const int X = static_cast<int>(xi & 255);
    const double n0 = grad1(perm_[X], fx);
    const double n1 = grad1(perm_[X + 1], fx - 1.0);
    return clamp_unit(kScale1 * lerp(fade(fx), n0, n1));
}

double GradientNoise::operator()(double x, double y) const {
    if (!tame(x) || !tame(y)) {
        return 0.0;
    }
    const std::int64_t xi = floor_int(x);
    const std::int64_t yi = floor_int(y);
    const double fx = x - static_cast<double>(xi);
    const double fy = y - static_cast<double>(yi);
    const int X = static_cast<int>(xi & 255);
    const int Y = static_cast<int>(yi & 255);
    const std::uint8_t* p = perm_.data();
    const int A = p[X] + Y;
    const int B = p[X + 1] + Y;
    const double u = fade(fx);
    const double v = fade(fy);
    const double x0 = lerp(u, grad2(p[A], fx, fy), grad2(p[B], fx - 1.0, fy));
    const double x1 = lerp(u, grad2(p[A + 1], fx, fy - 1.0), grad2(p[B + 1], fx - 1.0, fy - 1.0));
    return clamp_unit(kScale2 * lerp(v, x0, x1));
}

double GradientNoise::operator()(double x, double y, double z) const {
    // One well-predicted test for the common case; the slow path wraps or rejects.
    if (!(std::abs(x) < kWrapLimit && std::abs(y) < kWrapLimit && std::abs(z) < kWrapLimit) &&
        (!tame(x) || !tame(y) || !tame(z))) {
        return 0.0;
    }
    const std::int64_t xi = floor_int(x);
    const std::int64_t yi = floor_int(y);
    const std::int64_t zi = floor_int(z);
    const double fx = x - static_cast<double>(xi);
    const double fy = y - static_cast<double>(yi);
    const double fz = z - static_cast<double>(zi);
    const int X = static_cast<int>(xi & 255);
    const int Y = static_cast<int>(yi & 255);
    const int Z = static_cast<int>(zi & 255);
    const std::uint8_t* p = perm_.data();
    const int A = p[X] + Y;
    const int AA = p[A] + Z;
    const int AB = p[A + 1] + Z;
    const int B = p[X + 1] + Y;
    const int BA = p[B] + Z;
    const int BB = p[B + 1] + Z;
    const double u = fade(fx);
    const double v = fade(fy);
    const double w = fade(fz);
    const double gx = fx - 1.0;
    const double gy = fy - 1.0;
    const double gz = fz - 1.0;
    const double y00 = lerp(u, grad3(p[AA], fx, fy, fz), grad3(p[BA], gx, fy, fz));
    const double y10 = lerp(u, grad3(p[AB], fx, gy, fz), grad3(p[BB], gx, gy, fz));
    const double y01 = lerp(u, grad3(p[AA + 1], fx, fy, gz), grad3(p[BA + 1], gx, fy, gz));
    const double y11 = lerp(u, grad3(p[AB + 1], fx, gy, gz), grad3(p[BB + 1], gx, gy, gz));
    return clamp_unit(kScale3 * lerp(w, lerp(v, y00, y10), lerp(v, y01, y11)));
}

// ---- value noise ----

ValueNoise::ValueNoise(std::uint64_t seed, Interpolation interpolation)
    : seed_(Random(seed).next()), interpolation_(interpolation) {}

double ValueNoise::lattice(std::int64_t i) const {
    return unit_from_hash(mix(seed_ ^ (static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ULL)));
}

double ValueNoise::lattice(std::int64_t i, std::int64_t j) const {
    return unit_from_hash(mix(seed_ ^ (static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ULL) ^
                              mix(static_cast<std::uint64_t>(j) * 0xc2b2ae3d27d4eb4fULL + 1)));
}

double ValueNoise::lattice(std::int64_t i, std::int64_t j, std::int64_t k) const {
    return unit_from_hash(mix(seed_ ^ (static_cast<std::uint64_t>(i) * 0x9e3779b97f4a7c15ULL) ^
                              mix(static_cast<std::uint64_t>(j) * 0xc2b2ae3d27d4eb4fULL + 1) ^
                              mix(static_cast<std::uint64_t>(k) * 0x165667b19e3779f9ULL + 2)));
}

double ValueNoise::operator()(double x) const {
    if (!tame(x)) {
        return 0.0;
    }
    const std::int64_t i = floor_int(x);
    const double t = x - static_cast<double>(i);
    switch (interpolation_) {
        case Interpolation::linear:
            return lerp(t, lattice(i), lattice(i + 1));
        case Interpolation::cosine:
            return lerp(cosine_t(t), lattice(i), lattice(i + 1));
        case Interpolation::cubic:
            return clamp_unit(cubic(lattice(i - 1), lattice(i), lattice(i + 1), lattice(i + 2), t));
    }
    return 0.0;
}

double ValueNoise::operator()(double x, double y) const {
    if (!tame(x) || !tame(y)) {
        return 0.0;
    }
    const std::int64_t i = floor_int(x);
    const std::int64_t j = floor_int(y);
    const double tx = x - static_cast<double>(i);
    const double ty = y - static_cast<double>(j);
    if (interpolation_ == Interpolation::cubic) {
        double rows[4];
        for (int b = 0; b < 4; ++b) {
            const std::int64_t jj = j - 1 + b;
            rows[b] = cubic(lattice(i - 1, jj), lattice(i, jj), lattice(i + 1, jj),
                            lattice(i + 2, jj), tx);
        }
        return clamp_unit(cubic(rows[0], rows[1], rows[2], rows[3], ty));
    }
    const double u = interpolation_ == Interpolation::cosine ? cosine_t(tx) : tx;
    const double v = interpolation_ == Interpolation::cosine ? cosine_t(ty) : ty;
    return lerp(v, lerp(u, lattice(i, j), lattice(i + 1, j)),
                lerp(u, lattice(i, j + 1), lattice(i + 1, j + 1)));
}

double ValueNoise::operator()(double x, double y, double z) const {
    if (!tame(x) || !tame(y) || !tame(z)) {
        return 0.0;
    }
    const std::int64_t i = floor_int(x);
    const std::int64_t j = floor_int(y);
    const std::int64_t k = floor_int(z);
    const double tx = x - static_cast<double>(i);
    const double ty = y - static_cast<double>(j);
    const double tz = z - static_cast<double>(k);
    if (interpolation_ == Interpolation::cubic) {
        double planes[4];
        for (int c = 0; c < 4; ++c) {
            const std::int64_t kk = k - 1 + c;
            double rows[4];
            for (int b = 0; b < 4; ++b) {
                const std::int64_t jj = j - 1 + b;
                rows[b] = cubic(lattice(i - 1, jj, kk), lattice(i, jj, kk), lattice(i + 1, jj, kk),
                                lattice(i + 2, jj, kk), tx);
            }
            planes[c] = cubic(rows[0], rows[1], rows[2], rows[3], ty);
        }
        return clamp_unit(cubic(planes[0], planes[1], planes[2], planes[3], tz));
    }
    const bool cos = interpolation_ == Interpolation::cosine;
    const double u = cos ? cosine_t(tx) : tx;
    const double v = cos ? cosine_t(ty) : ty;
    const double w = cos ? cosine_t(tz) : tz;
    const double z0 = lerp(v, lerp(u, lattice(i, j, k), lattice(i + 1, j, k)),
                           lerp(u, lattice(i, j + 1, k), lattice(i + 1, j + 1, k)));
    const double z1 = lerp(v, lerp(u, lattice(i, j, k + 1), lattice(i + 1, j, k + 1)),
                           lerp(u, lattice(i, j + 1, k + 1), lattice(i + 1, j + 1, k + 1)));
    return lerp(w, z0, z1);
}

// ---- fractal sums ----

namespace {

// The octaves of any noise: each at f times the frequency, shifted by k octave offsets.
template <class Noise>
double noise_fbm(const Noise& noise, double x, const FbmSettings& s) {
    return fractal_sum(s, [&](double f, double k) { return noise(x * f + k * kOctaveShift[0]); });
}

template <class Noise>
double noise_fbm(const Noise& noise, double x, double y, const FbmSettings& s) {
    return fractal_sum(s, [&](double f, double k) {
        return noise(x * f + k * kOctaveShift[0], y * f + k * kOctaveShift[1]);
    });
}

template <class Noise>
double noise_fbm(const Noise& noise, double x, double y, double z, const FbmSettings& s) {
    return fractal_sum(s, [&](double f, double k) {
        return noise(x * f + k * kOctaveShift[0], y * f + k * kOctaveShift[1],
                     z * f + k * kOctaveShift[2]);
    });
}

}  // namespace

double fbm(const GradientNoise& noise, double x, const FbmSettings& s) {
    return noise_fbm(noise, x, s);
}
double fbm(const GradientNoise& noise, double x, double y, const FbmSettings& s) {
    return noise_fbm(noise, x, y, s);
}
double fbm(const GradientNoise& noise, double x, double y, double z, const FbmSettings& s) {
    return noise_fbm(noise, x, y, z, s);
}
double fbm(const ValueNoise& noise, double x, const FbmSettings& s) {
    return noise_fbm(noise, x, s);
}
double fbm(const ValueNoise& noise, double x, double y, const FbmSettings& s) {
    return noise_fbm(noise, x, y, s);
}
double fbm(const ValueNoise& noise, double x, double y, double z, const FbmSettings& s) {
    return noise_fbm(noise, x, y, z, s);
}

// ---- one field of a chosen kind ----

namespace {

Interpolation interpolation_of(NoiseKind kind) {
    switch (kind) {
        case NoiseKind::value_linear:
            return Interpolation::linear;
        case NoiseKind::value_cosine:
            return Interpolation::cosine;
        default:
            return Interpolation::cubic;
    }
}

}  // namespace

NoiseField::NoiseField(std::uint64_t seed, NoiseKind kind)
    : kind_(kind), gradient_(seed), value_(seed, interpolation_of(kind)) {}

double NoiseField::operator()(double x) const {
    return kind_ == NoiseKind::gradient ? gradient_(x) : value_(x);
}
double NoiseField::operator()(double x, double y) const {
    return kind_ == NoiseKind::gradient ? gradient_(x, y) : value_(x, y);
}
double NoiseField::operator()(double x, double y, double z) const {
    return kind_ == NoiseKind::gradient ? gradient_(x, y, z) : value_(x, y, z);
}

double fbm(const NoiseField& noise, double x, const FbmSettings& s) {
    return noise_fbm(noise, x, s);
}
double fbm(const NoiseField& noise, double x, double y, const FbmSettings& s) {
    return noise_fbm(noise, x, y, s);
}
double fbm(const NoiseField& noise, double x, double y, double z, const FbmSettings& s) {
    return noise_fbm(noise, x, y, z, s);
}

// ---- looping in time ----

namespace {

// The circle's point for time t: radius period / (2 pi), so one unit of t is one unit of
// arc; the centre is off the lattice's origin, where gradient noise is zero.
struct TimeCircle {
    double c, s;
};
TimeCircle time_circle(double t, double period) {
    const double p = std::max(std::isfinite(period) ? period : 1.0, 1.0);
    if (!std::isfinite(t)) t = 0.0;
    const double turn = std::fmod(t, p) / p;
    const double r = p / (2.0 * std::numbers::pi);
    const double a = 2.0 * std::numbers::pi * turn;
    return {r * std::cos(a) + 0.5 * kOctaveShift[1], r * std::sin(a) + 0.5 * kOctaveShift[2]};
}

}  // namespace

double looping_noise(const NoiseField& noise, double x, double t, double period) {
    const TimeCircle c = time_circle(t, period);
    return noise(x, c.c, c.s);
}

double looping_fbm(const NoiseField& noise, double x, double t, double period,
                   const FbmSettings& s) {
    const TimeCircle c = time_circle(t, period);
    // Octave k samples the circle scaled by its frequency: a circle of circumference
    // period * f, walked once per period.
    return fractal_sum(s, [&](double f, double k) {
        return noise(x * f + k * kOctaveShift[0], c.c * f + k * kOctaveShift[1],
                     c.s * f + k * kOctaveShift[2]);
    });
}

}  // namespace sylva
