// Derivation throughput: modules written per second, for a D0L grammar (ABOP Fig. 1.24a),
// a parametric one (Honda's monopodial tree, ABOP Fig. 2.6), and two of word modules (ABOP
// Fig. 1.26's plant as the book prints it; an L-Py style parametric apex grammar), one
// thread: by the wall clock, and by the thread's CPU time (what the derivation itself costs
// when other processes share the cores).
// Usage: sylva-bench-derive [--markdown] [repetitions]
#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <ctime>
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

double thread_seconds() {
    timespec t{};
    clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
    return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
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
        {"words  ABOP plant (Fig. 1.26)", R"(axiom: plant
plant -> internode + [plant + flower] - - // [- - leaf] internode [+ + leaf] - [plant flower] + + plant flower
internode -> F seg [// & & leaf] [// ^ ^ leaf] F seg
seg -> seg F seg
leaf -> [' { + f - f f - f + | + f - f f - f } ]
flower -> [& & & pedicel ' / wedge //// wedge //// wedge //// wedge //// wedge]
pedicel -> F F
wedge -> [^ F] [{ & & & & - f + f | - f + f }]
)",
         10},
        {"words  L-Py Apex/Internode, parametric", R"(axiom: Apex(0)
Apex(t) -> Internode(1) [ + Leaf(t) ] [ - Apex(t + 1) ] Internode(1) Apex(t + 1)
Internode(l) -> Internode(l * 1.1)
)",
         18},
    };
    if (!markdown) std::printf("derivation throughput, 1 thread, best of %d runs\n", repetitions);
    bench::Table table({"grammar", "steps", "final size", "written", "M modules/s", "(CPU time)"});
    for (const Case& c : cases) {
        LSystem system = parse_lsystem(c.grammar);
        std::size_t written = modules_written(system, c.steps);
        double best = 1e30, best_cpu = 1e30;
        std::size_t size = 0;
        for (int r = 0; r < repetitions; ++r) {
            DeriveSettings s;
            s.steps = c.steps;
            s.max_modules = 100'000'000;
            auto start = std::chrono::steady_clock::now();
            const double cpu_start = thread_seconds();
            size = derive(system, s).size();
            best_cpu = std::min(best_cpu, thread_seconds() - cpu_start);
            double seconds =
                std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
            best = std::min(best, seconds);
        }
        // One derive of n steps writes the words of steps 1..n: `written` modules.
        table.row({c.name, std::to_string(c.steps), std::to_string(size), std::to_string(written),
                   bench::format("%.1f", static_cast<double>(written) / best / 1e6),
                   bench::format("%.1f", static_cast<double>(written) / best_cpu / 1e6)});
    }
    table.print(markdown);
    return 0;
}
