// Arithmetic and logical expressions inside module parameters, conditions and weights,
// compiled once to a small stack program and evaluated many times during derivation.
//
// Syntax: numbers, names, + - * / ^ (power), unary - and !, parentheses, comparisons
// < <= > >= == !=, && ||, and the functions sin cos tan (degrees), sqrt abs min max floor
// rand(a,b). Booleans are 1 and 0.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/random.h"

namespace sylva {

class Expression {
  public:
    // Resolves a name at compile time: the index of a bound variable (rule parameter) or
    // a constant's value. Returns nullopt for an unknown name.
    struct Name {
        std::optional<int> variable;
        double constant = 0.0;
    };
    using NameLookup = std::function<std::optional<Name>(std::string_view)>;

    // Compiles `text`. On error throws GrammarError whose column is `column_offset` plus
    // the 0-based position of the problem in `text` (line left 0; the caller adds it).
    static Expression compile(std::string_view text, const NameLookup& lookup,
                              int column_offset = 1);

    static Expression constant(double value);

    // Throws GrammarError (no line) on division by zero or a non-finite result.
    double evaluate(std::span<const double> variables, Random& random) const;

    // True when the value does not depend on variables or rand, so it can be folded.
    bool is_constant() const;

  private:
    enum class Op : std::uint8_t {
        Constant,
        Variable,
        Negate,
        Not,
        Add,
        Subtract,
        Multiply,
        Divide,
        Power,
        Less,
        LessEqual,
        Greater,
        GreaterEqual,
        Equal,
        NotEqual,
        And,
        Or,
        Sin,
        Cos,
        Tan,
        Sqrt,
        Abs,
        Floor,
        Min,
        Max,
        Rand,
    };
    struct Instruction {
        Op op;
        int index = 0;       // Variable
        double value = 0.0;  // Constant
    };
    std::vector<Instruction> code_;

    friend class ExpressionParser;
};

}  // namespace sylva
