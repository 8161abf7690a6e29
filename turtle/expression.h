// Arithmetic and logical expressions inside module parameters, conditions and weights,
// compiled once to a small stack program and evaluated many times during derivation.
//
// Syntax: numbers, names, + - * / ^ (power), unary - and !, parentheses, comparisons
// < <= > >= == !=, && ||, and the functions sin cos tan (degrees), sqrt abs min max floor
// rand(a,b), noise(x), noise(x,y), noise(x,y,z) (the tree's noise field in [-1, 1]: Perlin's
// gradient noise or a value noise, as `noise_kind` says, seeded by the tree's seed),
// fbm(octaves,x), fbm(octaves,x,y), fbm(octaves,x,y,z) (that many octaves, 1 to 16,
// persistence 1/2, lacunarity 2; in [-1, 1]) and noise_loop(t, period), noise_loop(t,
// period, x) (noise that repeats in t with that period: looping animation, such as wind).
// Booleans are 1 and 0.
#pragma once

#include <cstdint>
#include <functional>
#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/noise.h"
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

    // Throws GrammarError (no line) on division by zero or a non-finite result, and when the
    // expression calls noise(), fbm() or noise_loop() but `noise` is null (constants and
    // weights are evaluated before a tree's seed is known).
    double evaluate(std::span<const double> variables, Random& random,
                    const NoiseField* noise = nullptr) const;

    // True when the value does not depend on variables, rand or noise, so it can be folded.
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
        Noise1,  // noise(x), noise(x, y), noise(x, y, z)
        Noise2,
        Noise3,
        Fbm1,  // fbm(octaves, x), ... (octaves first, so the count of arguments gives the
               // dimension)
        Fbm2,
        Fbm3,
        NoiseLoop2,  // noise_loop(t, period), noise_loop(t, period, x)
        NoiseLoop3,
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
