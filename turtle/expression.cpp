#include "turtle/expression.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <numbers>

#include "core/errors.h"

namespace sylva {

// Recursive descent over the grammar in expression.h, emitting postfix code.
class ExpressionParser {
  public:
    ExpressionParser(std::string_view text, const Expression::NameLookup& lookup, int offset)
        : text_(text), lookup_(lookup), offset_(offset) {}

    Expression parse() {
        skip_space();
        if (pos_ == text_.size()) fail("empty expression");
        parse_or();
        skip_space();
        if (pos_ != text_.size()) fail("unexpected '" + std::string(1, text_[pos_]) + "'");
        if (max_stack_depth() > kMaxStack) fail("expression is too deeply nested");
        return std::move(out_);
    }

    static constexpr int kMaxStack = 64;  // Expression::evaluate's fixed stack

  private:
    using Op = Expression::Op;

    int max_stack_depth() const {
        int depth = 0, deepest = 0;
        for (const auto& in : out_.code_) {
            bool pushes = in.op == Op::Constant || in.op == Op::Variable;
            bool binary = in.op >= Op::Add && in.op <= Op::Or;
            bool binary_call = in.op == Op::Min || in.op == Op::Max || in.op == Op::Rand;
            depth += pushes ? 1 : (binary || binary_call) ? -1 : -pops_beyond_one(in.op);
            deepest = std::max(deepest, depth);
        }
        return deepest;
    }

    // Operands beyond the first that a variable-arity function consumes.
    static int pops_beyond_one(Op op) {
        switch (op) {
            case Op::Noise2:
            case Op::Fbm1:
                return 1;
            case Op::Noise3:
            case Op::Fbm2:
            case Op::NoiseLoop3:
                return 2;
            case Op::NoiseLoop2:
                return 1;
            case Op::Fbm3:
                return 3;
            default:
                return 0;
        }
    }

    [[noreturn]] void fail(const std::string& message) const {
        throw GrammarError(message, 0, offset_ + static_cast<int>(pos_));
    }
    void skip_space() {
        while (pos_ < text_.size() && std::isspace(static_cast<unsigned char>(text_[pos_]))) ++pos_;
    }
    bool accept(std::string_view token) {
        skip_space();
        if (text_.substr(pos_, token.size()) != token) return false;
        pos_ += token.size();
        return true;
    }
    void emit(Op op) { out_.code_.push_back({op}); }

    void parse_or() {
        parse_and();
        while (accept("||")) parse_and(), emit(Op::Or);
    }
    void parse_and() {
        parse_comparison();
        while (accept("&&")) parse_comparison(), emit(Op::And);
    }
    void parse_comparison() {
        parse_sum();
        // Two-character operators first so "<=" is not read as "<".
        static constexpr std::array<std::pair<std::string_view, Op>, 6> ops{
            {{"<=", Op::LessEqual},
             {">=", Op::GreaterEqual},
             {"==", Op::Equal},
             {"!=", Op::NotEqual},
             {"<", Op::Less},
             {">", Op::Greater}}};
        for (auto [token, op] : ops) {
            if (accept(token)) {
                parse_sum();
                emit(op);
                return;
            }
        }
    }
    void parse_sum() {
        parse_product();
        for (;;) {
            if (accept("+"))
                parse_product(), emit(Op::Add);
            else if (accept("-"))
                parse_product(), emit(Op::Subtract);
            else
                return;
        }
    }
    void parse_product() {
        parse_unary();
        for (;;) {
            if (accept("*"))
                parse_unary(), emit(Op::Multiply);
            else if (accept("/"))
                parse_unary(), emit(Op::Divide);
            else
                return;
        }
    }
    void parse_unary() {
        Nest nest(*this);
        if (accept("-")) return parse_unary(), emit(Op::Negate);
        skip_space();
        if (text_.substr(pos_, 2) != "!=" && accept("!")) return parse_unary(), emit(Op::Not);
        parse_power();
    }
    void parse_power() {
        parse_primary();
        if (accept("^")) parse_unary(), emit(Op::Power);  // right-associative
    }
    // Bounds recursion so hostile input fails cleanly instead of overflowing the C++ stack.
    struct Nest {
        ExpressionParser& p;
        explicit Nest(ExpressionParser& parser) : p(parser) {
            if (++p.nesting_ > kMaxStack) p.fail("expression is too deeply nested");
        }
        ~Nest() { --p.nesting_; }
    };

    void parse_primary() {
        Nest nest(*this);
        skip_space();
        if (pos_ == text_.size()) fail("expression ends too early");
        char c = text_[pos_];
        if (accept("(")) {
            parse_or();
            if (!accept(")")) fail("missing ')'");
            return;
        }
        if (std::isdigit(static_cast<unsigned char>(c)) || c == '.') return parse_number();
        if (std::isalpha(static_cast<unsigned char>(c)) || c == '_') return parse_name();
        fail("unexpected '" + std::string(1, c) + "'");
    }
    void parse_number() {
        char* end = nullptr;
        // strtod needs a terminated string; copy the numeric run.
        std::string run;
        for (size_t i = pos_; i < text_.size(); ++i) {
            char c = text_[i];
            bool exponent_sign =
                (c == '+' || c == '-') && !run.empty() && (run.back() == 'e' || run.back() == 'E');
            if (!(std::isdigit(static_cast<unsigned char>(c)) || c == '.' || c == 'e' || c == 'E' ||
                  exponent_sign))
                break;
            run.push_back(c);
        }
        double value = std::strtod(run.c_str(), &end);
        size_t used = static_cast<size_t>(end - run.c_str());
        if (used == 0) fail("malformed number");
        pos_ += used;
        out_.code_.push_back({Op::Constant, 0, value});
    }
    void parse_name() {
        size_t start = pos_;
        while (pos_ < text_.size() &&
               (std::isalnum(static_cast<unsigned char>(text_[pos_])) || text_[pos_] == '_'))
            ++pos_;
        std::string_view name = text_.substr(start, pos_ - start);
        skip_space();
        if (pos_ < text_.size() && text_[pos_] == '(') return parse_call(name, start);
        std::optional<Expression::Name> resolved = lookup_ ? lookup_(name) : std::nullopt;
        if (!resolved) {
            pos_ = start;
            fail("unknown name '" + std::string(name) + "'");
        }
        if (resolved->variable)
            out_.code_.push_back({Op::Variable, *resolved->variable, 0.0});
        else
            out_.code_.push_back({Op::Constant, 0, resolved->constant});
    }
    void parse_call(std::string_view name, size_t start) {
        struct Function {
            std::string_view name;
            Op op;  // for min_arity; the next ops take one argument more each
            int min_arity;
            int max_arity;
            std::string_view arguments;  // for the arity error
        };
        static constexpr std::array<Function, 12> functions{
            {{"sin", Op::Sin, 1, 1, ""},
             {"cos", Op::Cos, 1, 1, ""},
             {"tan", Op::Tan, 1, 1, ""},
             {"sqrt", Op::Sqrt, 1, 1, ""},
             {"abs", Op::Abs, 1, 1, ""},
             {"floor", Op::Floor, 1, 1, ""},
             {"min", Op::Min, 2, 2, ""},
             {"max", Op::Max, 2, 2, ""},
             {"rand", Op::Rand, 2, 2, ""},
             {"noise", Op::Noise1, 1, 3, "x[, y[, z]]"},
             {"fbm", Op::Fbm1, 2, 4, "octaves, x[, y[, z]]"},
             {"noise_loop", Op::NoiseLoop2, 2, 3, "t, period[, x]"}}};
        const Function* function = nullptr;
        for (const Function& f : functions)
            if (f.name == name) function = &f;
        if (!function) {
            pos_ = start;
            fail("unknown function '" + std::string(name) + "'");
        }
        accept("(");
        int count = 0;
        if (!accept(")")) {
            do {
                skip_space();
                const size_t argument_start = pos_;
                const size_t code_start = out_.code_.size();
                parse_or();
                ++count;
                if (function->op == Op::Fbm1 && count == 1)
                    check_octaves(code_start, argument_start);
            } while (accept(","));
            if (!accept(")")) fail("missing ')' after the arguments of " + std::string(name));
        }
        if (count < function->min_arity || count > function->max_arity) {
            pos_ = start;
            if (function->min_arity == function->max_arity)
                fail(std::string(name) + " takes " + std::to_string(function->min_arity) +
                     " argument" + (function->min_arity == 1 ? "" : "s") + ", not " +
                     std::to_string(count));
            fail(std::string(name) + " takes " + std::to_string(function->min_arity) + " to " +
                 std::to_string(function->max_arity) + " arguments (" +
                 std::string(function->arguments) + "), not " + std::to_string(count));
        }
        emit(static_cast<Op>(static_cast<int>(function->op) + count - function->min_arity));
    }

    // fbm's octave count written as a number is checked here, with its column; one computed
    // at derivation time is checked by evaluate().
    void check_octaves(size_t code_start, size_t argument_start) {
        if (out_.code_.size() != code_start + 1 || out_.code_.back().op != Op::Constant) return;
        const double octaves = out_.code_.back().value;
        if (octaves >= 1 && octaves <= kMaxFbmOctaves && octaves == std::floor(octaves)) return;
        pos_ = argument_start;
        fail(octaves_message(octaves));
    }

  public:
    static std::string octaves_message(double octaves) {
        char shown[32];
        std::snprintf(shown, sizeof shown, "%g", octaves);
        return "fbm's first argument is the number of octaves, a whole number from 1 to " +
               std::to_string(kMaxFbmOctaves) + ", not " + shown;
    }

  private:
    std::string_view text_;
    const Expression::NameLookup& lookup_;
    int offset_;
    size_t pos_ = 0;
    int nesting_ = 0;
    Expression out_;
};

Expression Expression::compile(std::string_view text, const NameLookup& lookup, int column_offset) {
    return ExpressionParser(text, lookup, column_offset).parse();
}

Expression Expression::constant(double value) {
    Expression e;
    e.code_.push_back({Op::Constant, 0, value});
    return e;
}

bool Expression::is_constant() const {
    for (const Instruction& i : code_)
        if (i.op == Op::Variable || i.op == Op::Rand || i.op >= Op::Noise1) return false;
    return true;
}

namespace {

const NoiseField& need_noise(const NoiseField* noise) {
    if (!noise)
        throw GrammarError(
            "noise(), fbm() and noise_loop() depend on the tree's seed and are not available "
            "here (in #define values and rule weights); use them in rules and the axiom");
    return *noise;
}

// fbm with the expression language's fixed persistence and lacunarity.
FbmSettings fbm_settings(double octaves) {
    if (!(octaves >= 1 && octaves <= kMaxFbmOctaves && octaves == std::floor(octaves)))
        throw GrammarError(ExpressionParser::octaves_message(octaves));
    FbmSettings s;
    s.octaves = static_cast<int>(octaves);
    return s;
}

}  // namespace

double Expression::evaluate(std::span<const double> variables, Random& random,
                            const NoiseField* noise) const {
    constexpr double kDegree = std::numbers::pi / 180.0;
    double stack[64];  // compile() rejects programs deeper than this
    int top = -1;
    for (const Instruction& in : code_) {
        switch (in.op) {
            case Op::Constant:
                stack[++top] = in.value;
                continue;
            case Op::Variable:
                stack[++top] = variables[static_cast<size_t>(in.index)];
                continue;
            case Op::Negate:
                stack[top] = -stack[top];
                continue;
            case Op::Not:
                stack[top] = stack[top] == 0.0 ? 1.0 : 0.0;
                continue;
            case Op::Sin:
                stack[top] = std::sin(stack[top] * kDegree);
                continue;
            case Op::Cos:
                stack[top] = std::cos(stack[top] * kDegree);
                continue;
            case Op::Tan:
                stack[top] = std::tan(stack[top] * kDegree);
                continue;
            case Op::Sqrt:
                if (stack[top] < 0.0) throw GrammarError("square root of a negative number");
                stack[top] = std::sqrt(stack[top]);
                continue;
            case Op::Abs:
                stack[top] = std::abs(stack[top]);
                continue;
            case Op::Floor:
                stack[top] = std::floor(stack[top]);
                continue;
            case Op::Noise1:
                stack[top] = need_noise(noise)(stack[top]);
                continue;
            case Op::Noise2:
                --top;
                stack[top] = need_noise(noise)(stack[top], stack[top + 1]);
                continue;
            case Op::Noise3:
                top -= 2;
                stack[top] = need_noise(noise)(stack[top], stack[top + 1], stack[top + 2]);
                continue;
            case Op::Fbm1:
                --top;
                stack[top] = fbm(need_noise(noise), stack[top + 1], fbm_settings(stack[top]));
                continue;
            case Op::Fbm2:
                top -= 2;
                stack[top] = fbm(need_noise(noise), stack[top + 1], stack[top + 2],
                                 fbm_settings(stack[top]));
                continue;
            case Op::Fbm3:
                top -= 3;
                stack[top] = fbm(need_noise(noise), stack[top + 1], stack[top + 2], stack[top + 3],
                                 fbm_settings(stack[top]));
                continue;
            case Op::NoiseLoop2:
                --top;
                stack[top] = looping_noise(need_noise(noise), 0.0, stack[top], stack[top + 1]);
                continue;
            case Op::NoiseLoop3:
                top -= 2;
                stack[top] =
                    looping_noise(need_noise(noise), stack[top + 2], stack[top], stack[top + 1]);
                continue;
            default:
                break;
        }
        double b = stack[top--];
        double& a = stack[top];
        switch (in.op) {
            case Op::Add:
                a = a + b;
                break;
            case Op::Subtract:
                a = a - b;
                break;
            case Op::Multiply:
                a = a * b;
                break;
            case Op::Divide:
                if (b == 0.0) throw GrammarError("division by zero");
                a = a / b;
                break;
            case Op::Power:
                a = std::pow(a, b);
                break;
            case Op::Less:
                a = a < b;
                break;
            case Op::LessEqual:
                a = a <= b;
                break;
            case Op::Greater:
                a = a > b;
                break;
            case Op::GreaterEqual:
                a = a >= b;
                break;
            case Op::Equal:
                a = a == b;
                break;
            case Op::NotEqual:
                a = a != b;
                break;
            case Op::And:
                a = (a != 0.0) && (b != 0.0);
                break;
            case Op::Or:
                a = (a != 0.0) || (b != 0.0);
                break;
            case Op::Min:
                a = std::min(a, b);
                break;
            case Op::Max:
                a = std::max(a, b);
                break;
            case Op::Rand:
                a = a + (b - a) * random.uniform();
                break;
            default:
                break;
        }
    }
    if (!std::isfinite(stack[0])) throw GrammarError("expression gives a non-finite number");
    return stack[0];
}

}  // namespace sylva
