#include "turtle/derivation.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <map>
#include <string>
#include <vector>

#include "core/errors.h"
#include "turtle/turtle.h"

namespace sylva {
namespace {

// Samples of the noise field that rank a noise value (noise_choice): the choice draws the
// value's rank among them, uniform in [0, 1), so weights keep their shares although noise
// values crowd around 0.
constexpr int kRankSamples = 4096;

class Deriver {
  public:
    Deriver(const LSystem& system, const DeriveSettings& settings)
        : system_(system),
          settings_(settings),
          random_(settings.seed),
          noise_(expression_noise(settings.seed, settings.noise_kind)) {
        for (size_t r = 0; r < system.rules.size(); ++r) {
            const Rule& rule = system.rules[r];
            by_symbol_[static_cast<unsigned char>(rule.predecessor.symbol)].push_back(r);
            has_context_ = has_context_ || !rule.left.empty() || !rule.right.empty();
            has_noise_choice_ = has_noise_choice_ || rule.noise_choice > 0.0;
        }
        if (has_noise_choice_) rank_noise_values();
    }

    Word run() {
        Word word = axiom_word(system_, random_, &noise_);
        Word next;
        next.set_names(system_.words);
        const std::vector<double> ends = step_ends();
        for (int step = 1; step <= settings_.steps; ++step) {
            throw_if_cancelled(settings_.cancel);
            if (has_context_) match_brackets(word);
            if (has_noise_choice_) find_positions(word);
            next.clear();
            next.reserve(word.size() * 2, word.param_count() * 2);
            const double begin = ends[static_cast<size_t>(step - 1)];
            const double share = ends[static_cast<size_t>(step)] - begin;
            for (size_t i = 0; i < word.size(); ++i) {
                // A long step answers a cancel too (the studio's cancel within 100 ms).
                if ((i & 4095) == 4095) {
                    throw_if_cancelled(settings_.cancel);
                    report(begin +
                           share * static_cast<double>(i) / static_cast<double>(word.size()));
                }
                rewrite(word, i, next);
                if (next.size() > settings_.max_modules)
                    throw GrammarError("derivation step " + std::to_string(step) +
                                       ": the word grew past " + std::to_string(next.size()) +
                                       " modules (limit " + std::to_string(settings_.max_modules) +
                                       "); lower the number of steps or raise the limit");
            }
            std::swap(word, next);
            report(ends[static_cast<size_t>(step)]);
        }
        report(1.0);
        return word;
    }

  private:
    // The fraction of the derivation done after each step (ends[0] = 0, ends[steps] = 1):
    // step k's share is the word it makes as word_growth() estimates it (the geometric mean
    // of its bounds), since rewriting costs about one pass over the words.
    std::vector<double> step_ends() const {
        const int steps = std::max(settings_.steps, 0);
        std::vector<double> ends(static_cast<size_t>(steps) + 1, 0.0);
        if (!settings_.progress || steps == 0) return ends;
        std::vector<double> work(static_cast<size_t>(steps) + 1, 1.0);
        for (int k = 1; k <= steps; ++k) {
            const WordGrowth g = word_growth(system_, k);
            const double size =
                std::sqrt(std::max(g.low_modules, 1.0)) * std::sqrt(std::max(g.high_modules, 1.0));
            work[static_cast<size_t>(k)] = std::isfinite(size) ? std::min(size, 1e200) : 1e200;
        }
        double total = 0.0;
        for (int k = 1; k <= steps; ++k) total += work[static_cast<size_t>(k)];
        double done = 0.0;
        for (int k = 1; k <= steps; ++k) {
            done += work[static_cast<size_t>(k)];
            ends[static_cast<size_t>(k)] = done / total;
        }
        ends[static_cast<size_t>(steps)] = 1.0;
        return ends;
    }

    // Reports a fraction, never less than the last one reported.
    void report(double fraction) {
        if (!settings_.progress) return;
        reported_ = std::max(reported_, static_cast<float>(std::clamp(fraction, 0.0, 1.0)));
        settings_.progress(reported_);
    }

    void rewrite(const Word& word, size_t i, Word& out) {
        const char symbol = word.symbol(i);
        const auto& candidates = by_symbol_[static_cast<unsigned char>(symbol)];
        const Rule* chosen = nullptr;
        double total_weight = 0.0;
        weighted_.clear();
        for (size_t r : candidates) {
            const Rule& rule = system_.rules[r];
            if (!bind(word, i, rule)) continue;
            if (rule.condition && evaluate(*rule.condition, rule) == 0.0) continue;
            if (!rule.weight) {
                if (weighted_.empty()) chosen = &rule;
                break;  // an unweighted rule ends the search; weighted ones before it compete
            }
            weighted_.push_back({&rule, bindings_});
            total_weight += *rule.weight;
        }
        if (!weighted_.empty()) {
            chosen = pick_weighted(total_weight, word, i);
        }
        if (!chosen) {  // identity production
            out.push(symbol, word.args(i));
            return;
        }
        for (const ModuleProduction& m : chosen->successor) {
            args_.clear();
            for (const Expression& e : m.args) args_.push_back(evaluate(e, *chosen));
            out.push(m.symbol, args_);
        }
    }

    // One of the competing weighted rules, each with the chance of its share of `total`.
    // Weights near the largest double sum to infinity: then every weight is taken relative
    // to the largest, which keeps the shares. All weights zero is an error, not the last
    // rule.
    // Out of line: rewrite() stays small for the common, unweighted rules.
    [[gnu::noinline]] const Rule* pick_weighted(double total, const Word& word, size_t i) {
        const Rule& first = *weighted_.front().first;
        if (total == 0.0)
            throw GrammarError(
                "the weights of the rules for '" + std::string(word.symbol_name(word.symbol(i))) +
                    "' that apply here are all zero, so none can be chosen (give one a weight "
                    "above zero)",
                first.line, first.weight_column, first.text);
        double scale = 1.0;
        if (!std::isfinite(total)) {
            double largest = 0.0;
            for (const auto& [rule, bindings] : weighted_)
                largest = std::max(largest, *rule->weight);
            scale = 1.0 / largest;
            total = 0.0;
            for (const auto& [rule, bindings] : weighted_) total += *rule->weight * scale;
        }
        double target = choice_draw(i) * total;
        for (auto& [rule, bindings] : weighted_) {
            target -= *rule->weight * scale;
            if (target < 0.0 || &rule == &weighted_.back().first) {
                bindings_ = bindings;
                return rule;
            }
        }
        return nullptr;
    }

    // The draw in [0, 1) that picks among weighted rules: the seeded random number, or with
    // the first competing rule's noise_choice, the rank of the noise at the module's place.
    double choice_draw(size_t i) {
        double frequency = 0.0;
        for (const auto& [rule, bindings] : weighted_)
            if (rule->noise_choice > 0.0) {
                frequency = rule->noise_choice;
                break;
            }
        if (frequency == 0.0 || i >= positions_.size()) return random_.uniform();
        const glm::vec3& p = positions_[i];
        // Off the lattice's integer points, where gradient noise is zero everywhere.
        const double n =
            noise_(p.x * frequency + 0.31, p.y * frequency + 0.57, p.z * frequency + 0.73);
        const auto rank = std::lower_bound(ranks_.begin(), ranks_.end(), n) - ranks_.begin();
        return std::min(static_cast<double>(rank) / kRankSamples, 1.0 - 1e-12);
    }

    void rank_noise_values() {
        Random points(derive_seed(settings_.seed, 0x6e6f697365ULL));
        ranks_.resize(kRankSamples);
        for (double& v : ranks_)
            v = noise_(points.uniform() * 256.0, points.uniform() * 256.0,
                       points.uniform() * 256.0);
        std::sort(ranks_.begin(), ranks_.end());
    }

    void find_positions(const Word& word) {
        positions_.clear();
        if (settings_.positions)
            settings_.positions(word, positions_);
        else
            turtle_positions(word, TurtleSettings{}, positions_);
    }

    double evaluate(const Expression& e, const Rule& rule) {
        try {
            return e.evaluate(bindings_, random_, &noise_);
        } catch (const GrammarError& error) {
            throw GrammarError(error.reason() + " in rule '" + rule.text + "'", rule.line);
        }
    }

    // Binds the rule's parameters (left context, predecessor, right context) if it matches.
    bool bind(const Word& word, size_t i, const Rule& rule) {
        if (word.args(i).size() != static_cast<size_t>(rule.predecessor.arity)) return false;
        bindings_.clear();
        if (!rule.left.empty() && !match_left(word, i, rule.left)) return false;
        auto a = word.args(i);
        bindings_.insert(bindings_.end(), a.begin(), a.end());
        if (!rule.right.empty() && !match_right(word, i, rule.right)) return false;
        return true;
    }

    bool ignored(char c) const { return system_.ignored[static_cast<unsigned char>(c)]; }

    // ABOP left context: walk left, skip ignored symbols and whole [...] branches, climb out
    // of the enclosing '['. Patterns are matched from the last one backwards.
    bool match_left(const Word& word, size_t i, const std::vector<ModulePattern>& left) {
        std::vector<size_t> found(left.size());
        long pos = static_cast<long>(i) - 1;
        for (size_t k = left.size(); k-- > 0;) {
            for (;;) {
                if (pos < 0) return false;
                char c = word.symbol(static_cast<size_t>(pos));
                if (c == ']')
                    pos = static_cast<long>(bracket_match_[static_cast<size_t>(pos)]) - 1;
                else if (c == '[' || ignored(c))
                    --pos;
                else
                    break;
            }
            auto p = static_cast<size_t>(pos);
            if (word.symbol(p) != left[k].symbol ||
                word.args(p).size() != static_cast<size_t>(left[k].arity))
                return false;
            found[k] = p;
            --pos;
        }
        for (size_t p : found) {
            auto a = word.args(p);
            bindings_.insert(bindings_.end(), a.begin(), a.end());
        }
        return true;
    }

    // ABOP right context: walk right, skip ignored symbols and side branches, stop at ']'.
    bool match_right(const Word& word, size_t i, const std::vector<ModulePattern>& right) {
        size_t pos = i + 1;
        for (const ModulePattern& pattern : right) {
            for (;;) {
                if (pos >= word.size()) return false;
                char c = word.symbol(pos);
                if (c == '[')
                    pos = bracket_match_[pos] + 1;
                else if (c == ']')
                    return false;
                else if (ignored(c))
                    ++pos;
                else
                    break;
            }
            if (word.symbol(pos) != pattern.symbol ||
                word.args(pos).size() != static_cast<size_t>(pattern.arity))
                return false;
            auto a = word.args(pos);
            bindings_.insert(bindings_.end(), a.begin(), a.end());
            ++pos;
        }
        return true;
    }

    // For every bracket, the index of its partner; an unmatched bracket points past the word
    // (for ']' walking left: to index 0, so the walk ends).
    void match_brackets(const Word& word) {
        bracket_match_.assign(word.size(), 0);
        std::vector<size_t> open;
        for (size_t i = 0; i < word.size(); ++i) {
            char c = word.symbol(i);
            if (c == '[') {
                open.push_back(i);
                bracket_match_[i] = word.size() - 1;  // unmatched: skip to the end
            } else if (c == ']' && !open.empty()) {
                bracket_match_[i] = open.back();
                bracket_match_[open.back()] = i;
                open.pop_back();
            }
        }
    }

    const LSystem& system_;
    const DeriveSettings& settings_;
    Random random_;
    NoiseField noise_;
    std::array<std::vector<size_t>, 256> by_symbol_;
    bool has_context_ = false;
    bool has_noise_choice_ = false;
    std::vector<double> ranks_;         // sorted noise samples (rank_noise_values)
    std::vector<glm::vec3> positions_;  // the turtle's place at each module of this step's word
    float reported_ = 0.0f;
    std::vector<size_t> bracket_match_;
    std::vector<double> bindings_;
    std::vector<double> args_;
    std::vector<std::pair<const Rule*, std::vector<double>>> weighted_;
};

// 1234567 as "1234567", 3.2e+40 as "3.2e+40".
std::string format_count(double n) {
    if (n < 1e15) return std::to_string(static_cast<long long>(n));
    char text[32];
    std::snprintf(text, sizeof text, "%.3g", n);
    return text;
}

}  // namespace

GradientNoise expression_noise(std::uint64_t seed) {
    return GradientNoise(derive_seed(seed, noise_stream::expressions));
}

NoiseField expression_noise(std::uint64_t seed, NoiseKind kind) {
    return NoiseField(derive_seed(seed, noise_stream::expressions), kind);
}

Word axiom_word(const LSystem& system, Random& random, const NoiseField* noise) {
    Word word;
    word.set_names(system.words);
    std::vector<double> args;
    for (const ModuleProduction& m : system.axiom) {
        args.clear();
        for (const Expression& e : m.args) {
            try {
                args.push_back(e.evaluate({}, random, noise));
            } catch (const GrammarError& error) {
                throw GrammarError(error.reason() + " in the axiom", system.axiom_line, 0,
                                   system.axiom_text);
            }
        }
        word.push(m.symbol, args);
    }
    return word;
}

WordGrowth word_growth(const LSystem& system, int steps, double module_limit) {
    // A module is (symbol, arity): a rule matches only its own arity.
    using Kind = std::pair<char, int>;
    using Counts = std::map<Kind, double>;
    static constexpr double kSaturate = 1e300;
    // Each kind's alternatives: the successor counts of every rule that could rewrite it.
    std::map<Kind, std::vector<Counts>> alternatives;
    auto alternatives_of = [&](const Kind& kind) -> const std::vector<Counts>& {
        auto found = alternatives.find(kind);
        if (found != alternatives.end()) return found->second;
        std::vector<Counts> options;
        bool certain = false;  // some rule always applies, so the module never stays
        for (const Rule& rule : system.rules) {
            if (rule.predecessor.symbol != kind.first || rule.predecessor.arity != kind.second)
                continue;
            Counts made;
            for (const ModuleProduction& m : rule.successor)
                made[{m.symbol, static_cast<int>(m.args.size())}] += 1.0;
            options.push_back(std::move(made));
            const bool always = !rule.condition && rule.left.empty() && rule.right.empty();
            if (always) certain = true;
            if (always && !rule.weight) break;  // ends the search (derive's rewrite)
        }
        if (!certain) options.push_back({{kind, 1.0}});
        return alternatives.emplace(kind, std::move(options)).first->second;
    };
    Counts low, high;
    for (const ModuleProduction& m : system.axiom) {
        low[{m.symbol, static_cast<int>(m.args.size())}] += 1.0;
        high[{m.symbol, static_cast<int>(m.args.size())}] += 1.0;
    }
    auto total = [](const Counts& c) {
        double sum = 0;
        for (const auto& [kind, n] : c) sum += n;
        return std::min(sum, kSaturate);
    };
    WordGrowth growth;
    // Pushes `counts` one step: per kind, the componentwise min (or max) over its options.
    auto step = [&](const Counts& counts, bool take_max) {
        Counts next;
        for (const auto& [kind, n] : counts) {
            const std::vector<Counts>& options = alternatives_of(kind);
            Counts pick = options.front();
            for (const Counts& o : options) {
                for (auto& [k, v] : pick) {
                    auto it = o.find(k);
                    const double w = it == o.end() ? 0.0 : it->second;
                    v = take_max ? std::max(v, w) : std::min(v, w);
                }
                if (take_max)
                    for (const auto& [k, w] : o) pick[k] = std::max(pick[k], w);
            }
            for (const auto& [k, v] : pick)
                if (v > 0) next[k] = std::min(next[k] + n * v, kSaturate);
        }
        return next;
    };
    for (int s = 1; s <= steps; ++s) {
        low = step(low, false);
        high = step(high, true);
        if (growth.first_step_over < 0 && total(low) > module_limit) growth.first_step_over = s;
        if (total(low) >= kSaturate && total(high) >= kSaturate) break;
    }
    growth.low_modules = total(low);
    growth.high_modules = total(high);
    for (const auto& [kind, n] : low)
        if (kind.first == 'F') growth.low_segments += n;
    for (const auto& [kind, n] : high)
        if (kind.first == 'F') growth.high_segments += n;
    return growth;
}

Word derive(const LSystem& system, const DeriveSettings& settings) {
    if (settings.steps < 0) throw GrammarError("the number of derivation steps is negative");
    const WordGrowth growth =
        word_growth(system, settings.steps, static_cast<double>(settings.max_modules));
    if (growth.first_step_over > 0)
        throw GrammarError("derivation step " + std::to_string(growth.first_step_over) +
                           ": the word would grow past " + std::to_string(settings.max_modules) +
                           " modules (estimated " + format_count(growth.low_modules) + " after " +
                           std::to_string(settings.steps) +
                           " steps); lower the number of steps or raise the limit");
    return Deriver(system, settings).run();
}

}  // namespace sylva
