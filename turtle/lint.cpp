#include "turtle/lint.h"

#include <algorithm>
#include <set>
#include <tuple>
#include <utility>

namespace sylva {
namespace {

using Kind = std::pair<char, int>;  // a module as rules match it: symbol and arity

std::string quoted(const LSystem& system, char symbol) {
    Word names;
    names.set_names(system.words);
    return "'" + std::string(names.symbol_name(symbol)) + "'";
}

std::string parameters(int arity) {
    if (arity == 0) return "no parameters";
    return std::to_string(arity) + (arity == 1 ? " parameter" : " parameters");
}

// Every (symbol, arity) some word of the grammar can hold: the axiom's, and what every rule
// whose predecessor can occur makes. Conditions and contexts are not evaluated, so this is
// what can occur at most: a kind not in it never occurs.
std::set<Kind> reachable_kinds(const LSystem& system) {
    std::set<Kind> reached;
    std::vector<Kind> work;
    auto reach = [&](char symbol, int arity) {
        if (reached.insert({symbol, arity}).second) work.push_back({symbol, arity});
    };
    for (const ModuleProduction& m : system.axiom) reach(m.symbol, static_cast<int>(m.args.size()));
    while (!work.empty()) {
        const Kind kind = work.back();
        work.pop_back();
        for (const Rule& rule : system.rules)
            if (rule.predecessor.symbol == kind.first && rule.predecessor.arity == kind.second)
                for (const ModuleProduction& m : rule.successor)
                    reach(m.symbol, static_cast<int>(m.args.size()));
    }
    return reached;
}

bool same_patterns(const std::vector<ModulePattern>& a, const std::vector<ModulePattern>& b) {
    return a.size() == b.size() && std::equal(a.begin(), a.end(), b.begin(),
                                              [](const ModulePattern& x, const ModulePattern& y) {
                                                  return x.symbol == y.symbol && x.arity == y.arity;
                                              });
}

// Rule `earlier` always applies where `later` would: the same predecessor, no weight, and
// no context or condition of its own that `later` does not share.
bool shadows(const Rule& earlier, const std::string& earlier_condition, const Rule& later,
             const std::string& later_condition) {
    if (earlier.predecessor.symbol != later.predecessor.symbol ||
        earlier.predecessor.arity != later.predecessor.arity || earlier.weight)
        return false;
    if (!earlier.left.empty() && !same_patterns(earlier.left, later.left)) return false;
    if (!earlier.right.empty() && !same_patterns(earlier.right, later.right)) return false;
    return earlier_condition.empty() || earlier_condition == later_condition;
}

}  // namespace

std::vector<LintWarning> lint_grammar(std::string_view text, const Constants& constants,
                                      const std::vector<std::string>& surfaces) {
    GrammarNotes notes;
    const LSystem system = parse_lsystem(text, constants, &notes);
    std::vector<LintWarning> out;
    const std::set<Kind> reached = reachable_kinds(system);

    for (std::size_t r = 0; r < system.rules.size(); ++r) {
        const Rule& rule = system.rules[r];
        const ModulePattern& p = rule.predecessor;
        if (!reached.count({p.symbol, p.arity})) {
            std::vector<int> arities;
            for (const auto& [symbol, arity] : reached)
                if (symbol == p.symbol) arities.push_back(arity);
            std::string message = "this rule never applies: no word the grammar derives has " +
                                  quoted(system, p.symbol);
            if (arities.empty()) {
                message += " at all";
            } else {
                message += " with " + parameters(p.arity) + " (it has " + quoted(system, p.symbol) +
                           " with ";
                for (std::size_t k = 0; k < arities.size(); ++k)
                    message += (k ? " or " : "") + parameters(arities[k]);
                message += ")";
            }
            out.push_back({rule.line, rule.column, message});
            continue;
        }
        for (std::size_t e = 0; e < r; ++e) {
            const Rule& earlier = system.rules[e];
            if (!shadows(earlier, notes.conditions[e], rule, notes.conditions[r])) continue;
            out.push_back(
                {rule.line, rule.column,
                 "this rule never applies: the rule on line " + std::to_string(earlier.line) +
                     " has the same predecessor, " +
                     (notes.conditions[e].empty() ? "no condition" : "the same condition") +
                     " and no weight, and always applies first"});
            break;
        }
        if (rule.weight && *rule.weight == 0.0)
            out.push_back({rule.line, rule.weight_column, "weight 0: this rule is never chosen"});
    }

    for (const GrammarNotes::Define& d : notes.defines) {
        if (d.shadows_constant)
            out.push_back({d.line, d.column,
                           "#define " + d.name + " hides the parameter '" + d.name +
                               "': the rules read this value, the rest of the tree the "
                               "parameter's; give the constant another name"});
        else if (!d.read)
            out.push_back({d.line, d.column, "#define " + d.name + " is never read"});
    }
    for (const GrammarNotes::Variable& v : notes.variables)
        if (!v.read && !v.name.starts_with('_'))
            out.push_back({v.line, v.column,
                           "parameter '" + v.name +
                               "' is never read by the rule's condition or successor (name it "
                               "_" +
                               v.name + " if that is meant)"});

    if (system.words) {
        for (std::size_t w = 0; w < system.words->size(); ++w) {
            const std::string& name = (*system.words)[w];
            const char symbol = static_cast<char>(kFirstWordSymbol + static_cast<int>(w));
            const GrammarNotes::Place at = notes.word_first_written[w];
            if (name.starts_with('~')) {
                if (!surfaces.empty() &&
                    std::find(surfaces.begin(), surfaces.end(), name.substr(1)) == surfaces.end()) {
                    std::string known;
                    for (const std::string& s : surfaces) known += (known.empty() ? "" : ", ") + s;
                    out.push_back({at.line, at.column,
                                   "unknown organ '" + name + "' (known: " + known + ")"});
                }
                continue;
            }
            const bool has_rule =
                std::any_of(system.rules.begin(), system.rules.end(),
                            [&](const Rule& rule) { return rule.predecessor.symbol == symbol; });
            if (!has_rule && !system.ignored[static_cast<unsigned char>(symbol)])
                out.push_back({at.line, at.column,
                               "'" + name +
                                   "' is a word module that has no rule and draws nothing; if "
                                   "it means single-character modules, write them apart "
                                   "(docs/grammar.md, \"Words\")"});
        }
    }
    std::stable_sort(out.begin(), out.end(), [](const LintWarning& a, const LintWarning& b) {
        return std::tie(a.line, a.column) < std::tie(b.line, b.column);
    });
    return out;
}

}  // namespace sylva
