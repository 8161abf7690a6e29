// Fuzzes the grammar language: parse (with the template parameters as constants), derive
// one step under a small module cap, and read the word with the turtle in both modes.
#include "fuzz_guard.h"
#include "turtle/derivation.h"
#include "turtle/lsystem_growth.h"
#include "turtle/lsystem_parser.h"
#include "turtle/turtle.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    static const Constants constants = param_constants(TreeParams{});
    expect_only_input_errors([&] {
        const LSystem system = parse_lsystem(fuzz_text(data, size), constants);
        DeriveSettings settings;
        settings.steps = 1;
        settings.max_modules = 20'000;  // keeps every input fast; a bigger word is a GrammarError
        const Word word = derive(system, settings);
        for (TurtleMode mode : {TurtleMode::Abop, TurtleMode::Lptg}) {
            TurtleSettings turtle;
            turtle.mode = mode;
            turtle.elasticity = 0.2;
            interpret(word, turtle);
        }
    });
    return 0;
}
