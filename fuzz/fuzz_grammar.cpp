// Fuzzes the grammar language: parse (with the template parameters as constants), lint,
// derive one step under a small module cap, read the word's text back as an axiom, and read
// the word with the turtle in both modes.
#include <string>

#include "fuzz_guard.h"
#include "turtle/derivation.h"
#include "turtle/lint.h"
#include "turtle/lsystem_growth.h"
#include "turtle/lsystem_parser.h"
#include "turtle/turtle.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    static const Constants constants = param_constants(TreeParams{});
    expect_only_input_errors([&] {
        const std::string_view text = fuzz_text(data, size);
        const LSystem system = parse_lsystem(text, constants);
        lint_grammar(text, constants, {"apple", "cone"});
        DeriveSettings settings;
        settings.steps = 1;
        settings.max_modules = 20'000;  // keeps every input fast; a bigger word is a GrammarError
        const Word word = derive(system, settings);
        // A word of word modules prints them apart from names, so its text read back as an
        // axiom (with every word declared by a rule) has as many modules.
        if (word.names() && word.size() < 2'000) {
            std::string again = "axiom: " + word.to_string() + "\n";
            for (const std::string& name : *word.names())
                if (name[0] != '~') again += name + " -> " + name + "\n";
            bool read = false;
            std::size_t modules = 0;
            try {
                modules = parse_lsystem(again).axiom.size();
                read = true;
            } catch (const InputError&) {
                // Text that only parses inside parentheses (a number printed as 1e+308 is
                // fine, but a module named like a directive is not): nothing to compare.
            }
            if (read && modules != word.size())
                fuzz_finding("a word's text reads back to other modules");
        }
        for (TurtleMode mode : {TurtleMode::Abop, TurtleMode::Lptg}) {
            TurtleSettings turtle;
            turtle.mode = mode;
            turtle.elasticity = 0.2;
            interpret(word, turtle);
        }
    });
    return 0;
}
