// Derivation throughput: modules written per second, for a D0L grammar (ABOP Fig. 1.24a)
// and a parametric one (Honda's monopodial tree, ABOP Fig. 2.6), one thread.
// Usage: sylva-bench-derive [--markdown] [repetitions]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "bench/common.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_parser.h"

namespace {

using namespace sylva;

struct Case {
    const char* name;
    std::string grammar;
    int steps;
};

// Every module written by every step (what the engine actually produced).
std::size_t modules_written(const LSystem& system, int steps) {
    std::size_t total = 0;
    for (int n = 1; n <= steps; ++n) {
        DeriveSettings s;
        s.steps = n;
        s.max_modules = 100'000'000;
        total += derive(system, s).size();
    }
    return total;
}

}  // namespace

int main(int argc, char** argv) {
    std::vector<std::string> args(argv + 1, argv + argc);
    const bool markdown = bench::take_flag(args, "--markdown");
    const int repetitions = args.empty() ? 5 : std::max(1, std::atoi(args[0].c_str()));
    const Case cases[] = {
        {"D0L  F -> F[+F]F[-F]F (ABOP 1.24a)", "axiom: F\nF -> F[+F]F[-F]F\n", 9},
        {"parametric Honda (ABOP 2.6)", R"(#define r1 0.9
#define r2 0.6
#define d 137.5
#define wr 0.707
axiom: A(1,10)
A(l,w) : * -> !(w)F(l)[&(45)B(l*r2,w*wr)]/(d)A(l*r1,w*wr)
B(l,w) : * -> !(w)F(l)[-(45)$C(l*r2,w*wr)]C(l*r1,w*wr)
C(l,w) : * -> !(w)F(l)[+(45)$B(l*r2,w*wr)]B(l*r1,w*wr)
)",
         19},
    };
    if (!markdown) std::printf("derivation throughput, 1 thread, best of %d runs\n", repetitions);
    bench::Table table({"grammar", "steps", "final size", "written", "M modules/s"});
    for (const Case& c : cases) {
        LSystem system = parse_lsystem(c.grammar);
        std::size_t written = modules_written(system, c.steps);
        double best = 1e30;
        std::size_t size = 0;
        for (int r = 0; r < repetitions; ++r) {
            DeriveSettings s;
            s.steps = c.steps;
            s.max_modules = 100'000'000;
            auto start = std::chrono::steady_clock::now();
            size = derive(system, s).size();
            double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            best = std::min(best, seconds);
        }
        // One derive of n steps writes the words of steps 1..n: `written` modules.
        table.row({c.name, std::to_string(c.steps), std::to_string(size), std::to_string(written),
                   bench::format("%.1f", static_cast<double>(written) / best / 1e6)});
    }
    table.print(markdown);
    return 0;
}
