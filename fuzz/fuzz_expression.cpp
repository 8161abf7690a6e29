// Fuzzes the expression compiler: compile with two variables (x, y) and a constant (c),
// then evaluate with ordinary and extreme variable values, without a noise field and with
// the gradient and a value noise.
#include <limits>
#include <vector>

#include "fuzz_guard.h"
#include "turtle/expression.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    const Expression::NameLookup lookup =
        [](std::string_view name) -> std::optional<Expression::Name> {
        if (name == "x") return Expression::Name{0, 0.0};
        if (name == "y") return Expression::Name{1, 0.0};
        if (name == "c") return Expression::Name{std::nullopt, 2.5};
        return std::nullopt;
    };
    expect_only_input_errors([&] {
        const Expression e = Expression::compile(fuzz_text(data, size), lookup);
        (void)e.is_constant();
        const double big = std::numeric_limits<double>::max();
        const std::vector<std::vector<double>> inputs = {{0.0, 1.0}, {-1.5, 1e-300}, {big, -big}};
        for (const std::vector<double>& variables : inputs) {
            // Each evaluation may fail alone (1/x at x = 0), so each is guarded.
            static const NoiseField gradient(7), value(7, NoiseKind::value_cubic);
            for (const NoiseField* noise :
                 {static_cast<const NoiseField*>(nullptr), &gradient, &value})
                expect_only_input_errors([&] {
                    Random random(7);
                    (void)e.evaluate(variables, random, noise);
                });
        }
    });
    return 0;
}
