#include "turtle/lsystem_parser.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/errors.h"

namespace sylva {
namespace {

bool is_space(char c) {
    return std::isspace(static_cast<unsigned char>(c)) != 0;
}

std::string_view trim(std::string_view s) {
    while (!s.empty() && is_space(s.front())) s.remove_prefix(1);
    while (!s.empty() && is_space(s.back())) s.remove_suffix(1);
    return s;
}

bool starts_with_word(std::string_view s, std::string_view word) {
    if (s.size() < word.size()) return false;
    for (size_t i = 0; i < word.size(); ++i)
        if (std::tolower(static_cast<unsigned char>(s[i])) != word[i]) return false;
    return s.size() == word.size() || !std::isalnum(static_cast<unsigned char>(s[word.size()]));
}

// One line of the grammar text, with helpers that report errors at a column of it.
struct Line {
    std::string_view text;  // without the comment
    std::string_view full;  // as written, for error display
    int number = 0;

    [[noreturn]] void fail(const std::string& message, size_t column0) const {
        throw GrammarError(message, number, static_cast<int>(column0) + 1, std::string(full));
    }

    // A constant expression's value; an evaluation error (division by zero, ...) names
    // this line and `column0`.
    double evaluate_constant(const Expression& e, size_t column0) const {
        Random unused(0);
        try {
            return e.evaluate({}, unused);
        } catch (const GrammarError& error) {
            fail(error.reason(), column0);
        }
    }

    // Position of `token` at parenthesis depth 0 in [begin, end), or npos.
    size_t find_top_level(std::string_view token, size_t begin, size_t end) const {
        int depth = 0;
        for (size_t i = begin; i < end; ++i) {
            char c = text[i];
            if (c == '(')
                ++depth;
            else if (c == ')')
                --depth;
            else if (depth == 0 && text.substr(i, token.size()) == token && i + token.size() <= end)
                return i;
        }
        return std::string_view::npos;
    }
};

bool valid_symbol(char c) {
    auto u = static_cast<unsigned char>(c);
    return u > 32 && u < 127 && c != '(' && c != ')' && c != ',';
}

class Parser {
  public:
    explicit Parser(const Constants& constants) : constants_(constants) {}

    LSystem parse(std::string_view text) {
        std::vector<Line> lines = split_lines(text);
        enum class Section { Free, SeedAxiom, SeedRules } section = Section::Free;
        bool have_axiom = false;
        for (const Line& line : lines) {
            std::string_view body = trim(line.text);
            if (body.empty()) continue;
            if (body.front() == '#') {
                std::string_view directive = body.substr(1);
                if (starts_with_word(directive, "define")) {
                    parse_define(line);
                } else if (starts_with_word(directive, "ignore")) {
                    parse_ignore(line);
                } else if (starts_with_word(directive, "axiom")) {
                    section = Section::SeedAxiom;
                } else if (starts_with_word(directive, "rules")) {
                    section = Section::SeedRules;
                }
                // Any other '#' line is a comment.
                continue;
            }
            size_t start = static_cast<size_t>(body.data() - line.text.data());
            if (section == Section::SeedAxiom) {
                if (have_axiom) line.fail("a second axiom; seed 001's format has one", start);
                result_.axiom = parse_productions(line, start, line.text.size(), {});
                if (result_.axiom.empty()) line.fail("the axiom is empty", start);
                result_.axiom_line = line.number;
                result_.axiom_text = std::string(line.full);
                check_brackets(line, start, line.text.size());
                have_axiom = true;
                section = Section::Free;
                continue;
            }
            if (starts_with_word(body, "axiom")) {
                size_t colon = line.text.find(':', start);
                if (colon == std::string_view::npos)
                    line.fail("expected ':' after 'axiom'", start + 5);
                if (have_axiom) line.fail("a second axiom", start);
                result_.axiom = parse_productions(line, colon + 1, line.text.size(), {});
                if (result_.axiom.empty()) line.fail("the axiom is empty", colon + 1);
                result_.axiom_line = line.number;
                result_.axiom_text = std::string(line.full);
                check_brackets(line, colon + 1, line.text.size());
                have_axiom = true;
                continue;
            }
            parse_rule(line, start);
        }
        if (!have_axiom)
            throw GrammarError(
                "the grammar has no axiom (write 'axiom: ...' or '#axiom' "
                "followed by the axiom on the next line)");
        return std::move(result_);
    }

  private:
    std::vector<Line> split_lines(std::string_view text) {
        std::vector<Line> lines;
        int number = 0;
        size_t pos = 0;
        while (pos <= text.size()) {
            size_t end = text.find('\n', pos);
            if (end == std::string_view::npos) end = text.size();
            std::string_view full = text.substr(pos, end - pos);
            if (!full.empty() && full.back() == '\r') full.remove_suffix(1);
            Line line{full, full, ++number};
            // A '#' starts a comment; on a directive line ("#define ...") the next one does.
            std::string_view body = trim(full);
            bool directive = body.size() > 1 && body.front() == '#' &&
                             std::isalpha(static_cast<unsigned char>(body[1]));
            size_t first = full.find('#');
            size_t hash = directive ? full.find('#', first + 1) : first;
            if (hash != std::string_view::npos) line.text = full.substr(0, hash);
            lines.push_back(line);
            if (end == text.size()) break;
            pos = end + 1;
        }
        return lines;
    }

    std::optional<Expression::Name> constant_lookup(std::string_view name) const {
        auto it = constants_.find(name);
        if (it == constants_.end()) return std::nullopt;
        return Expression::Name{std::nullopt, it->second};
    }

    Expression compile(const Line& line, size_t begin, size_t end,
                       const std::vector<std::string>& variables) const {
        std::string_view text = line.text.substr(begin, end - begin);
        auto lookup = [&](std::string_view name) -> std::optional<Expression::Name> {
            for (size_t i = 0; i < variables.size(); ++i)
                if (variables[i] == name) return Expression::Name{static_cast<int>(i), 0.0};
            return constant_lookup(name);
        };
        try {
            return Expression::compile(text, lookup, 0);
        } catch (const GrammarError& e) {
            line.fail(e.reason(), begin + static_cast<size_t>(e.column()));
        }
    }

    void parse_define(const Line& line) {
        size_t at = line.text.find("define") + 6;
        while (at < line.text.size() && is_space(line.text[at])) ++at;
        size_t name_end = at;
        while (name_end < line.text.size() &&
               (std::isalnum(static_cast<unsigned char>(line.text[name_end])) ||
                line.text[name_end] == '_'))
            ++name_end;
        if (name_end == at || std::isdigit(static_cast<unsigned char>(line.text[at])))
            line.fail("expected a name after #define", at);
        std::string name(line.text.substr(at, name_end - at));
        size_t value_begin = name_end;
        while (value_begin < line.text.size() && is_space(line.text[value_begin])) ++value_begin;
        if (value_begin < line.text.size() && line.text[value_begin] == '=') ++value_begin;
        if (trim(line.text.substr(std::min(value_begin, line.text.size()))).empty())
            line.fail("#define " + name + " needs a value", line.text.size());
        Expression value = compile(line, value_begin, line.text.size(), {});
        Random unused(0);
        constants_[name] = line.evaluate_constant(value, value_begin);
    }

    void parse_ignore(const Line& line) {
        size_t at = line.text.find("ignore") + 6;
        if (at < line.text.size() && line.text[at] == ':') ++at;
        for (; at < line.text.size(); ++at) {
            char c = line.text[at];
            if (is_space(c)) continue;
            if (!valid_symbol(c)) line.fail("not a symbol", at);
            result_.ignored[static_cast<unsigned char>(c)] = true;
        }
    }

    // Checks '[' / ']' balance in [begin, end) of a line (outside parameter lists).
    void check_brackets(const Line& line, size_t begin, size_t end) const {
        std::vector<size_t> open;
        int depth = 0;
        for (size_t i = begin; i < end; ++i) {
            char c = line.text[i];
            if (c == '(') ++depth;
            if (c == ')') --depth;
            if (depth != 0) continue;
            if (c == '[') open.push_back(i);
            if (c == ']') {
                if (open.empty()) line.fail("']' without a matching '['", i);
                open.pop_back();
            }
        }
        if (!open.empty()) line.fail("'[' is never closed", open.back());
    }

    // Walks the modules in [begin, end): calls on_module(symbol) for each, then
    // on_argument(a, b) for every parameter text [a, b) inside its parentheses.
    template <class OnModule, class OnArgument>
    void for_each_module(const Line& line, size_t begin, size_t end, OnModule&& on_module,
                         OnArgument&& on_argument) const {
        size_t i = begin;
        while (i < end) {
            char c = line.text[i];
            if (is_space(c)) {
                ++i;
                continue;
            }
            if (!valid_symbol(c)) line.fail("'" + std::string(1, c) + "' is not a symbol", i);
            on_module(c);
            ++i;
            if (i < end && line.text[i] == '(') {
                size_t close = matching_paren(line, i, end);
                for_each_argument(line, i + 1, close, on_argument);
                i = close + 1;
            }
        }
    }

    // Modules with parameter expressions, e.g. "F(l*r)[+A(1,2)]", in [begin, end).
    std::vector<ModuleProduction> parse_productions(const Line& line, size_t begin, size_t end,
                                                    const std::vector<std::string>& variables) {
        std::vector<ModuleProduction> out;
        for_each_module(
            line, begin, end,
            [&](char symbol) {
                out.push_back({symbol, {}});
            },
            [&](size_t a, size_t b) { out.back().args.push_back(compile(line, a, b, variables)); });
        return out;
    }

    // Modules with parameter names, e.g. "A(l,w)", in [begin, end); appends the names.
    std::vector<ModulePattern> parse_patterns(const Line& line, size_t begin, size_t end,
                                              std::vector<std::string>& variables) {
        std::vector<ModulePattern> out;
        for_each_module(
            line, begin, end,
            [&](char symbol) {
                out.push_back({symbol, 0});
            },
            [&](size_t a, size_t b) {
                std::string_view name = trim(line.text.substr(a, b - a));
                bool ok = !name.empty() &&
                          (std::isalpha(static_cast<unsigned char>(name[0])) || name[0] == '_');
                for (char n : name)
                    ok = ok && (std::isalnum(static_cast<unsigned char>(n)) || n == '_');
                if (!ok) line.fail("a parameter of a rule's left side must be a name", a);
                if (std::find(variables.begin(), variables.end(), name) != variables.end())
                    line.fail("parameter '" + std::string(name) + "' is named twice", a);
                variables.emplace_back(name);
                ++out.back().arity;
            });
        return out;
    }

    size_t matching_paren(const Line& line, size_t open, size_t end) const {
        int depth = 0;
        for (size_t i = open; i < end; ++i) {
            if (line.text[i] == '(') ++depth;
            if (line.text[i] == ')' && --depth == 0) return i;
        }
        line.fail("'(' is never closed", open);
    }

    template <class F>
    void for_each_argument(const Line& line, size_t begin, size_t end, F&& f) const {
        if (trim(line.text.substr(begin, end - begin)).empty())
            line.fail("empty parameter list", begin);
        size_t a = begin;
        for (int count = 1;; ++count) {
            if (count > kMaxModuleParameters)
                line.fail("a module has more than " + std::to_string(kMaxModuleParameters) +
                              " parameters",
                          a);
            size_t comma = line.find_top_level(",", a, end);
            size_t b = comma == std::string_view::npos ? end : comma;
            if (trim(line.text.substr(a, b - a)).empty()) line.fail("missing parameter", a);
            f(a, b);
            if (comma == std::string_view::npos) break;
            a = comma + 1;
        }
    }

    // A context written as "*" means "any", the same as no context.
    std::vector<ModulePattern> parse_context(const Line& line, size_t begin, size_t end,
                                             std::vector<std::string>& variables) {
        if (trim(line.text.substr(begin, end - begin)) == "*") return {};
        auto context = parse_patterns(line, begin, end, variables);
        if (context.empty()) line.fail("empty context", begin);
        for (const ModulePattern& p : context)
            if (p.symbol == '[' || p.symbol == ']')
                line.fail("brackets inside a context are not supported", begin);
        return context;
    }

    void parse_rule(const Line& line, size_t start) {
        size_t end = line.text.size();
        size_t arrow = line.find_top_level("->", start, end);
        if (arrow == std::string_view::npos)
            line.fail("expected a rule 'predecessor -> successor', but there is no '->'", start);
        Rule rule;
        rule.line = line.number;
        rule.text = std::string(trim(line.full));

        // Left side: [left <] pred [> right] [: condition]
        size_t colon = line.find_top_level(":", start, arrow);
        size_t pattern_end = colon == std::string_view::npos ? arrow : colon;
        size_t lt = line.find_top_level("<", start, pattern_end);
        size_t gt =
            line.find_top_level(">", lt == std::string_view::npos ? start : lt + 1, pattern_end);
        size_t pred_begin = lt == std::string_view::npos ? start : lt + 1;
        size_t pred_end = gt == std::string_view::npos ? pattern_end : gt;
        std::vector<std::string> variables;
        if (lt != std::string_view::npos) rule.left = parse_context(line, start, lt, variables);
        std::vector<ModulePattern> pred = parse_patterns(line, pred_begin, pred_end, variables);
        if (pred.size() != 1)
            line.fail(pred.empty() ? "the rule has no predecessor"
                                   : "the predecessor must be a single module",
                      pred_begin);
        rule.predecessor = pred[0];
        if (gt != std::string_view::npos)
            rule.right = parse_context(line, gt + 1, pattern_end, variables);
        if (colon != std::string_view::npos) {
            std::string_view condition = trim(line.text.substr(colon + 1, arrow - colon - 1));
            if (condition.empty()) line.fail("empty condition after ':'", colon + 1);
            if (condition != "*")  // ABOP writes "*" for "always"
                rule.condition = compile(line, colon + 1, arrow, variables);
        }

        // Right side: successor [: weight]
        size_t weight_colon = line.find_top_level(":", arrow + 2, end);
        size_t successor_end = weight_colon == std::string_view::npos ? end : weight_colon;
        rule.successor = parse_productions(line, arrow + 2, successor_end, variables);
        bool bracket_rule = rule.predecessor.symbol == '[' || rule.predecessor.symbol == ']';
        if (!bracket_rule) check_brackets(line, arrow + 2, successor_end);
        if (weight_colon != std::string_view::npos) {
            Expression weight = compile(line, weight_colon + 1, end, {});
            Random unused(0);
            double w = line.evaluate_constant(weight, weight_colon + 1);
            if (!(w >= 0.0)) line.fail("a rule's weight must be zero or more", weight_colon + 1);
            rule.weight = w;
        }
        result_.rules.push_back(std::move(rule));
    }

    Constants constants_;
    LSystem result_;
};

}  // namespace

LSystem parse_lsystem(std::string_view text, const Constants& constants) {
    // Editors on Windows save UTF-8 with a byte order mark; it is no part of the grammar,
    // and columns on the first line count from after it.
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    return Parser(constants).parse(text);
}

}  // namespace sylva
