// The layout grammar reader (layout/grammar_json.h). Bad input must raise InputError; a grammar
// it accepts must write back to the same bytes it reads again, and growing a small layout from
// it must give a complete planar graph (or stop, never crash): the reader's checks are what
// generation relies on.
#include <cstdint>

#include "fuzz_guard.h"
#include "layout/generate.h"
#include "layout/grammar_json.h"

namespace {

using namespace sylva;

void check(const std::string& text) {
    const layout::Grammar g = layout::read_grammar_json(text, "fuzz.json");
    const std::string written = layout::write_grammar_json(g);
    if (layout::write_grammar_json(layout::read_grammar_json(written, "again.json")) != written)
        fuzz_finding("an accepted grammar does not read back to the same bytes");
    // Growing is bounded here (a few moves on small graphs): the fuzzer looks for crashes.
    std::size_t largest = 0;
    for (const layout::AngleGraph& s : g.starters) largest = std::max(largest, s.vertices.size());
    if (largest > 64 || g.rules.size() > 64) return;
    const layout::GrowthTable table(g);
    layout::GrowSettings grow;
    grow.target = 4;
    grow.max_steps = 8;
    grow.tries = 8;
    const layout::AngleGraph out = layout::grow_graph(table, 1, grow);
    const layout::Analysis a = layout::analyze(out, g.dirs);
    if (!a.planar || !a.complete) fuzz_finding("a grown graph is not complete and planar");
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 256 * 1024) return 0;
    const std::string text(fuzz_text(data, size));
    expect_only_input_errors([&] { check(text); });
    return 0;
}
