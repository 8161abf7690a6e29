// Noise throughput (the target: >= 50 M 3D samples/s per core): Sylva's improved gradient
// noise and Limbach's (2004) value noise (linear, cosine, cubic) in 1, 2 and 3 dimensions,
// 4-octave fbm, and GLM's unseeded glm::perlin beside them for reference. One thread.
//   build/bench/sylva-bench-noise [--markdown] [million samples per row, default 20]
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <glm/gtc/noise.hpp>
#include <string>
#include <vector>

#include "bench/common.h"
#include "core/noise.h"
#include "core/stopwatch.h"

using namespace sylva;

namespace {

volatile double g_sink = 0.0;  // keeps the sums alive

// Samples along a slanted line through the volume, so every call lands in a new spot of the
// lattice as in real use (a branch walking through space), and the table stays in cache.
template <class F>
void row(bench::Table& table, const char* name, long count, F&& f) {
    Stopwatch clock;
    const std::clock_t cpu_start = std::clock();
    double sum = 0.0;
    for (long i = 0; i < count; ++i) {
        const double t = static_cast<double>(i) * 0.0137;
        sum += f(t, t * 0.71 + 3.1, t * 0.37 - 5.3);
    }
    const double ms = clock.lap_ms();
    const double cpu_ms = 1e3 * static_cast<double>(std::clock() - cpu_start) / CLOCKS_PER_SEC;
    g_sink = g_sink + sum;
    // CPU time as well as wall time: on a shared machine the wall figure undercounts a core.
    table.row({name, bench::format("%.1f", static_cast<double>(count) / (ms * 1e3)),
               bench::format("%.1f", static_cast<double>(count) / (cpu_ms * 1e3)),
               bench::format("%.1f", cpu_ms * 1e6 / static_cast<double>(count))});
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    const bool markdown = bench::take_flag(args, "--markdown");
    const long count = static_cast<long>((args.empty() ? 20.0 : std::atof(args[0].c_str())) * 1e6);
    bench::Table table({"noise", "M/s wall", "M/s cpu", "ns cpu/sample"});
    const GradientNoise g(1);
    const ValueNoise linear(1, Interpolation::linear), cosine(1, Interpolation::cosine),
        cubic(1, Interpolation::cubic);
    const FbmSettings four{};
    if (!markdown) std::printf("%ld samples per row, one thread\n", count);
    row(table, "gradient 1D", count, [&](double x, double, double) { return g(x); });
    row(table, "gradient 2D", count, [&](double x, double y, double) { return g(x, y); });
    row(table, "gradient 3D", count, [&](double x, double y, double z) { return g(x, y, z); });
    row(table, "gradient fbm 3D (4 octaves)", count / 4,
        [&](double x, double y, double z) { return fbm(g, x, y, z, four); });
    row(table, "value linear 1D", count, [&](double x, double, double) { return linear(x); });
    row(table, "value linear 2D", count, [&](double x, double y, double) { return linear(x, y); });
    row(table, "value linear 3D", count,
        [&](double x, double y, double z) { return linear(x, y, z); });
    row(table, "value cosine 1D", count, [&](double x, double, double) { return cosine(x); });
    row(table, "value cosine 2D", count, [&](double x, double y, double) { return cosine(x, y); });
    row(table, "value cosine 3D", count,
        [&](double x, double y, double z) { return cosine(x, y, z); });
    row(table, "value cubic 1D", count, [&](double x, double, double) { return cubic(x); });
    row(table, "value cubic 2D", count / 4,
        [&](double x, double y, double) { return cubic(x, y); });
    row(table, "value cubic 3D", count / 16,
        [&](double x, double y, double z) { return cubic(x, y, z); });
    row(table, "glm::perlin 2D (float, unseeded)", count, [&](double x, double y, double) {
        return static_cast<double>(glm::perlin(glm::vec2(x, y)));
    });
    row(table, "glm::perlin 3D (float, unseeded)", count, [&](double x, double y, double z) {
        return static_cast<double>(glm::perlin(glm::vec3(x, y, z)));
    });
    row(table, "glm::perlin 3D (double, unseeded)", count,
        [&](double x, double y, double z) { return glm::perlin(glm::dvec3(x, y, z)); });
    table.print(markdown);
    return 0;
}
