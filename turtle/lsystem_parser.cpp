#include "turtle/lsystem_parser.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <map>
#include <set>
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

bool is_name_start(char c) {
    return std::isalpha(static_cast<unsigned char>(c)) != 0;
}
bool is_name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

// One module of a run of name characters: a single character, or a word (by name).
struct Piece {
    size_t offset = 0;  // in the run
    size_t length = 1;
};

class Parser {
  public:
    Parser(const Constants& constants, GrammarNotes* notes)
        : constants_(constants), notes_(notes) {}

    LSystem parse(std::string_view text) {
        std::vector<Line> lines = split_lines(text);
        declare_words(lines);
        LSystem result = parse_lines(lines);
        if (!words_.empty()) result.words = std::make_shared<const WordNames>(words_);
        return result;
    }

  private:
    // Rule lines: everything that is not blank, a '#' line or an axiom (the line after
    // Heuer's "#axiom" included), in the order written.
    template <class F>
    void for_each_rule_line(const std::vector<Line>& lines, F&& f) const {
        bool next_is_axiom = false;
        for (const Line& line : lines) {
            std::string_view body = trim(line.text);
            if (body.empty()) continue;
            if (body.front() == '#') {
                if (starts_with_word(body.substr(1), "axiom")) next_is_axiom = true;
                continue;
            }
            if (next_is_axiom) {
                next_is_axiom = false;
                continue;
            }
            if (starts_with_word(body, "axiom")) continue;
            f(line, static_cast<size_t>(body.data() - line.text.data()));
        }
    }

    // A grammar uses words when a rule's predecessor is a name of two or more characters
    // (docs/grammar.md, "Words"): those names are its known words, and the one-character
    // predecessors and the turtle's letters its known letters; parse_lines() reads runs of
    // name characters by them.
    void declare_words(const std::vector<Line>& lines) {
        known_letters_.fill(false);
        // The letters the turtle reads: in a grammar of words they still split off a run of
        // letters ("FF" is F F, as ABOP prints it).
        for (char c : std::string_view("FfGg"))
            known_letters_[static_cast<unsigned char>(c)] = true;
        for_each_rule_line(lines, [&](const Line& line, size_t start) {
            const size_t arrow = line.find_top_level("->", start, line.text.size());
            if (arrow == std::string_view::npos) return;
            const size_t colon = line.find_top_level(":", start, arrow);
            const size_t pattern_end = colon == std::string_view::npos ? arrow : colon;
            const size_t lt = line.find_top_level("<", start, pattern_end);
            const size_t gt = line.find_top_level(
                ">", lt == std::string_view::npos ? start : lt + 1, pattern_end);
            const size_t begin = lt == std::string_view::npos ? start : lt + 1;
            std::string_view pred =
                line.text.substr(begin, (gt == std::string_view::npos ? pattern_end : gt) - begin);
            pred = trim(pred.substr(0, pred.find('(')));
            if (pred.size() == 1) {
                known_letters_[static_cast<unsigned char>(pred[0])] = true;
                return;
            }
            const bool surface = pred.size() > 1 && pred[0] == '~';
            std::string_view name = surface ? pred.substr(1) : pred;
            if (name.empty() || !is_name_start(name[0])) return;
            for (char c : name)
                if (!is_name_char(c)) return;
            if (!surface) words_mode_ = true;
            declared_.insert(std::string(pred));
        });
    }

    LSystem parse_lines(const std::vector<Line>& lines) {
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
                if (have_axiom)
                    line.fail("a second axiom; the thesis's format (Heuer 2022) has one", start);
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

    std::optional<Expression::Name> constant_lookup(std::string_view name) {
        auto it = constants_.find(name);
        if (it == constants_.end()) return std::nullopt;
        if (auto define = define_index_.find(name); define != define_index_.end() && notes_)
            notes_->defines[define->second].read = true;
        return Expression::Name{std::nullopt, it->second};
    }

    // Compiles [begin, end) of the line; `variables` are the rule's parameters (their reads
    // go to the notes from `first_variable` on).
    Expression compile(const Line& line, size_t begin, size_t end,
                       const std::vector<std::string>& variables, size_t first_variable = 0) {
        std::string_view text = line.text.substr(begin, end - begin);
        auto lookup = [&](std::string_view name) -> std::optional<Expression::Name> {
            for (size_t i = 0; i < variables.size(); ++i)
                if (variables[i] == name) {
                    if (notes_ && first_variable + i < notes_->variables.size())
                        notes_->variables[first_variable + i].read = true;
                    return Expression::Name{static_cast<int>(i), 0.0};
                }
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
        while (name_end < line.text.size() && is_name_char(line.text[name_end])) ++name_end;
        if (name_end == at || std::isdigit(static_cast<unsigned char>(line.text[at])))
            line.fail("expected a name after #define", at);
        std::string name(line.text.substr(at, name_end - at));
        // A second definition would silently win over the first (and a slider would move
        // only one of them): refused.
        if (auto earlier = define_index_.find(name); earlier != define_index_.end())
            line.fail("'" + name + "' is defined twice (first on line " +
                          std::to_string(define_lines_[earlier->second]) +
                          "); remove one of the #define lines",
                      at);
        size_t value_begin = name_end;
        while (value_begin < line.text.size() && is_space(line.text[value_begin])) ++value_begin;
        if (value_begin < line.text.size() && line.text[value_begin] == '=') ++value_begin;
        if (trim(line.text.substr(std::min(value_begin, line.text.size()))).empty())
            line.fail("#define " + name + " needs a value", line.text.size());
        Expression value = compile(line, value_begin, line.text.size(), {});
        const bool shadows = constants_.find(name) != constants_.end();
        constants_[name] = line.evaluate_constant(value, value_begin);
        define_index_[name] = define_lines_.size();
        define_lines_.push_back(line.number);
        if (notes_)
            notes_->defines.push_back(
                {name, line.number, static_cast<int>(at) + 1, false, shadows});
    }

    void parse_ignore(const Line& line) {
        size_t at = line.text.find("ignore") + 6;
        if (at < line.text.size() && line.text[at] == ':') ++at;
        for_each_module(
            line, at, line.text.size(),
            [&](char symbol, size_t) {
                result_.ignored[static_cast<unsigned char>(symbol)] = true;
            },
            [&](size_t a, size_t) { line.fail("#ignore lists symbols, without parameters", a); });
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

    // The symbol of the word `name`, numbered in the order words are first written. Throws
    // past kMaxWords words.
    char word_symbol(const Line& line, std::string_view name, size_t column0) {
        auto found = word_index_.find(name);
        if (found == word_index_.end()) {
            if (words_.size() >= static_cast<size_t>(kMaxWords))
                line.fail("a grammar may name at most " + std::to_string(kMaxWords) +
                              " different words; '" + std::string(name) + "' is one more",
                          column0);
            found = word_index_.emplace(std::string(name), words_.size()).first;
            words_.emplace_back(name);
            if (notes_)
                notes_->word_first_written.push_back({line.number, static_cast<int>(column0) + 1});
        }
        return static_cast<char>(kFirstWordSymbol + static_cast<int>(found->second));
    }

    // A run of name characters in a grammar of words: a known word is one module; a run
    // that splits wholly into known words and known letters is those (the longest first at
    // each place, so "FF" is F F and "Fseg" F seg); any other run is a word of its own.
    std::vector<Piece> split_run(std::string_view run) const {
        if (run.size() == 1 || declared_.count(std::string(run))) return {{0, run.size()}};
        // best[i]: the length of the piece that starts a split of run[i..] (0: none).
        std::vector<size_t> best(run.size() + 1, 0);
        std::vector<bool> splits(run.size() + 1, false);
        splits[run.size()] = true;
        for (size_t i = run.size(); i-- > 0;) {
            for (size_t length = run.size() - i; length >= 1; --length) {
                if (!splits[i + length]) continue;
                const bool known = length == 1
                                       ? known_letters_[static_cast<unsigned char>(run[i])]
                                       : declared_.count(std::string(run.substr(i, length))) > 0;
                if (known) {
                    best[i] = length;
                    splits[i] = true;
                    break;
                }
            }
        }
        if (!splits[0]) return {{0, run.size()}};
        std::vector<Piece> pieces;
        for (size_t i = 0; i < run.size(); i += best[i]) pieces.push_back({i, best[i]});
        return pieces;
    }

    // Walks the modules in [begin, end): calls on_module(symbol, column0) for each, then
    // on_argument(a, b) for every parameter text [a, b) inside its parentheses (a run of
    // name characters that splits into several modules gives its parameters to the last).
    template <class OnModule, class OnArgument>
    void for_each_module(const Line& line, size_t begin, size_t end, OnModule&& on_module,
                         OnArgument&& on_argument) {
        size_t i = begin;
        while (i < end) {
            char c = line.text[i];
            if (is_space(c)) {
                ++i;
                continue;
            }
            const bool surface = c == '~' && i + 1 < end && is_name_start(line.text[i + 1]);
            if (surface || (words_mode_ && is_name_start(c))) {
                size_t run_end = i + (surface ? 1 : 0);
                while (run_end < end && is_name_char(line.text[run_end])) ++run_end;
                const std::string_view run = line.text.substr(i, run_end - i);
                const std::vector<Piece> pieces =
                    surface ? std::vector<Piece>{{0, run.size()}} : split_run(run);
                for (const Piece& piece : pieces) {
                    const size_t at = i + piece.offset;
                    on_module(piece.length == 1
                                  ? run[piece.offset]
                                  : word_symbol(line, run.substr(piece.offset, piece.length), at),
                              at);
                }
                i = run_end;
            } else {
                if (!valid_symbol(c)) line.fail("'" + std::string(1, c) + "' is not a symbol", i);
                on_module(c, i);
                ++i;
            }
            if (i < end && line.text[i] == '(') {
                size_t close = matching_paren(line, i, end);
                for_each_argument(line, i + 1, close, on_argument);
                i = close + 1;
            }
        }
    }

    // Modules with parameter expressions, e.g. "F(l*r)[+A(1,2)]", in [begin, end).
    std::vector<ModuleProduction> parse_productions(const Line& line, size_t begin, size_t end,
                                                    const std::vector<std::string>& variables,
                                                    size_t first_variable = 0) {
        std::vector<ModuleProduction> out;
        for_each_module(
            line, begin, end,
            [&](char symbol, size_t) {
                out.push_back({symbol, {}});
            },
            [&](size_t a, size_t b) {
                out.back().args.push_back(compile(line, a, b, variables, first_variable));
            });
        return out;
    }

    // Modules with parameter names, e.g. "A(l,w)", in [begin, end); appends the names (and,
    // with notes, records them for rule `rule`). `columns` gets each module's column0.
    std::vector<ModulePattern> parse_patterns(const Line& line, size_t begin, size_t end,
                                              std::vector<std::string>& variables,
                                              std::vector<size_t>* columns = nullptr) {
        std::vector<ModulePattern> out;
        for_each_module(
            line, begin, end,
            [&](char symbol, size_t at) {
                out.push_back({symbol, 0});
                if (columns) columns->push_back(at);
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
                if (notes_) {
                    const size_t column0 = static_cast<size_t>(name.data() - line.text.data());
                    notes_->variables.push_back({std::string(name),
                                                 static_cast<int>(result_.rules.size()),
                                                 line.number, static_cast<int>(column0) + 1});
                }
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
        const size_t first_variable = notes_ ? notes_->variables.size() : 0;

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
        std::vector<size_t> columns;
        std::vector<ModulePattern> pred =
            parse_patterns(line, pred_begin, pred_end, variables, &columns);
        if (pred.size() != 1)
            line.fail(pred.empty() ? "the rule has no predecessor"
                                   : "the predecessor must be a single module",
                      pred_begin);
        rule.predecessor = pred[0];
        rule.column = static_cast<int>(columns[0]) + 1;
        if (gt != std::string_view::npos)
            rule.right = parse_context(line, gt + 1, pattern_end, variables);
        if (colon != std::string_view::npos) {
            std::string_view condition = trim(line.text.substr(colon + 1, arrow - colon - 1));
            if (condition.empty()) line.fail("empty condition after ':'", colon + 1);
            if (condition != "*")  // ABOP writes "*" for "always"
                rule.condition = compile(line, colon + 1, arrow, variables, first_variable);
        }
        if (notes_)
            notes_->conditions.emplace_back(
                rule.condition ? trim(line.text.substr(colon + 1, arrow - colon - 1)) : "");

        // Right side: successor [: weight [, noise FREQUENCY]]
        size_t weight_colon = line.find_top_level(":", arrow + 2, end);
        size_t successor_end = weight_colon == std::string_view::npos ? end : weight_colon;
        rule.successor =
            parse_productions(line, arrow + 2, successor_end, variables, first_variable);
        bool bracket_rule = rule.predecessor.symbol == '[' || rule.predecessor.symbol == ']';
        if (!bracket_rule) check_brackets(line, arrow + 2, successor_end);
        if (weight_colon != std::string_view::npos) {
            size_t weight_end = line.find_top_level(",", weight_colon + 1, end);
            if (weight_end == std::string_view::npos) weight_end = end;
            Expression weight = compile(line, weight_colon + 1, weight_end, {});
            double w = line.evaluate_constant(weight, weight_colon + 1);
            if (!(w >= 0.0)) line.fail("a rule's weight must be zero or more", weight_colon + 1);
            rule.weight = w;
            size_t weight_at = weight_colon + 1;
            while (weight_at < weight_end && is_space(line.text[weight_at])) ++weight_at;
            rule.weight_column = static_cast<int>(weight_at) + 1;
            if (weight_end != end) parse_choice(line, weight_end + 1, end, rule);
        }
        result_.rules.push_back(std::move(rule));
    }

    // The option after a weight: "noise FREQUENCY" (a constant expression, cycles per meter).
    void parse_choice(const Line& line, size_t begin, size_t end, Rule& rule) {
        size_t at = begin;
        while (at < end && is_space(line.text[at])) ++at;
        if (!starts_with_word(line.text.substr(at, end - at), "noise"))
            line.fail("expected 'noise FREQUENCY' after the weight's ','", at);
        const size_t value = at + 5;
        if (trim(line.text.substr(value, end - value)).empty())
            line.fail("'noise' needs a frequency (noise cycles per meter), e.g. 'noise 0.5'",
                      value);
        const double frequency = line.evaluate_constant(compile(line, value, end, {}), value);
        if (!(frequency > 0.0) || !std::isfinite(frequency))
            line.fail("the noise frequency must be a positive number", value);
        rule.noise_choice = frequency;
    }

    Constants constants_;
    GrammarNotes* notes_ = nullptr;
    LSystem result_;
    // Words (declare_words): whether the grammar uses them, its known words and letters,
    // and the words met so far with their numbers.
    bool words_mode_ = false;
    std::set<std::string, std::less<>> declared_;
    std::array<bool, 256> known_letters_{};
    WordNames words_;
    std::map<std::string, size_t, std::less<>> word_index_;
    // #define names: their index among the defines, and each define's line.
    std::map<std::string, size_t, std::less<>> define_index_;
    std::vector<int> define_lines_;
};

}  // namespace

LSystem parse_lsystem(std::string_view text, const Constants& constants, GrammarNotes* notes) {
    // Editors on Windows save UTF-8 with a byte order mark; it is no part of the grammar,
    // and columns on the first line count from after it.
    if (text.starts_with("\xEF\xBB\xBF")) text.remove_prefix(3);
    if (notes) *notes = {};
    return Parser(constants, notes).parse(text);
}

}  // namespace sylva
