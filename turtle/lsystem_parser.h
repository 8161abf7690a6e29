// Reads the grammar syntax of docs/grammar.md (ABOP/cpfg style, with L-Py style word
// modules) and Heuer's (2022) "#axiom / #rules" format into an LSystem.
#pragma once

#include <map>
#include <string>
#include <string_view>
#include <vector>

#include "turtle/lsystem.h"

namespace sylva {

// Constants visible to every expression, e.g. template parameters; #define overrides them.
using Constants = std::map<std::string, double, std::less<>>;

// Parameters one module may carry: far more than any grammar needs (ABOP's use up to six),
// few enough that a module cannot exhaust memory.
constexpr int kMaxModuleParameters = 64;

// What the parser saw beyond the LSystem itself, for warnings (turtle/lint.h): where names
// were defined and written, and whether an expression ever read them. Lines and columns are
// 1-based, in the grammar's own lines.
struct GrammarNotes {
    struct Define {
        std::string name;
        int line = 0, column = 0;
        bool read = false;              // some expression after it names it
        bool shadows_constant = false;  // a constant given to the parser has this name
    };
    std::vector<Define> defines;
    struct Variable {
        std::string name;
        int rule = 0;  // index into LSystem::rules
        int line = 0, column = 0;
        bool read = false;  // the rule's condition or successor names it
    };
    std::vector<Variable> variables;
    struct Place {
        int line = 0, column = 0;
    };
    std::vector<Place> word_first_written;  // per word of LSystem::words
    // Per rule, its condition as written (trimmed; empty without one or for "*").
    std::vector<std::string> conditions;
};

// Throws GrammarError naming line and column (with the line and a caret) on bad input,
// among it a #define given twice. `notes`, when given, receives what turtle/lint.h needs.
LSystem parse_lsystem(std::string_view text, const Constants& constants = {},
                      GrammarNotes* notes = nullptr);

}  // namespace sylva
