#include "tree/template_setting.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <vector>

#include "core/errors.h"
#include "tree/grammar_constants.h"
#include "tree/parameters.h"

namespace sylva {
namespace {

std::string number_text(double v) {
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, v);
    return error == std::errc() ? std::string(buffer, end) : std::to_string(v);
}

// The #define `key` set to `value` after the checks of its comment; false when the grammar
// has no such #define.
bool set_define(TreeTemplate& tree, std::string_view key, double value, std::string_view text) {
    const std::optional<GrammarDefine> define = find_grammar_define(tree.grammar, key);
    if (!define) return false;
    const std::string name = "#define " + std::string(key);
    if (!std::isfinite(value))
        throw InputError(name + " expects a finite number, not '" + std::string(text) + "'");
    if (define->min && !(value >= *define->min && value <= *define->max))
        throw InputError(name + " must be from " + number_text(*define->min) + " to " +
                         number_text(*define->max) + " (the range of its comment), not " +
                         std::string(text));
    if (define->integer && std::floor(value) != value)
        throw InputError(name + " takes whole numbers from " + number_text(*define->min) + " to " +
                         number_text(*define->max) + ", not " + std::string(text));
    set_grammar_define(tree.grammar, key, value);
    return true;
}

[[noreturn]] void unknown(const TreeTemplate& tree, const InputError& e) {
    const std::string names = grammar_define_names(tree);
    if (names.empty()) throw e;
    throw InputError(e.reason() + "; " + (tree.name.empty() ? "the" : tree.name + "'s") +
                     " rules' #define constants: " + names);
}

}  // namespace

std::string grammar_define_names(const TreeTemplate& tree) {
    std::vector<std::string> seen;
    std::string names;
    for (const GrammarDefine& d : grammar_defines(tree.grammar)) {
        if (std::find(seen.begin(), seen.end(), d.name) != seen.end()) continue;
        seen.push_back(d.name);
        names += (names.empty() ? "" : ", ") + d.name;
    }
    return names;
}

void set_template_value(TreeTemplate& tree, std::string_view key, std::string_view value) {
    if (find_param(key)) {
        set_param(tree.params, key, value);
        // A #define of the same name shadows the parameter in the rules: it follows.
        if (find_grammar_define(tree.grammar, key))
            set_define(tree, key, *get_param(tree.params, key), value);
        return;
    }
    if (find_grammar_define(tree.grammar, key)) {
        std::string_view digits = value;
        if (!digits.empty() && digits.front() == '+') digits.remove_prefix(1);
        double number = 0;
        const auto [end, error] =
            std::from_chars(digits.data(), digits.data() + digits.size(), number);
        if (digits.empty() || error != std::errc() || end != digits.data() + digits.size())
            throw InputError("#define " + std::string(key) + " expects a number, not '" +
                             std::string(value) + "'");
        set_define(tree, key, number, value);
        return;
    }
    try {
        set_param(tree.params, key, value);
    } catch (const InputError& e) {
        unknown(tree, e);
    }
}

void set_template_value(TreeTemplate& tree, std::string_view key, double value) {
    if (find_param(key)) {
        set_param(tree.params, key, value);
        if (find_grammar_define(tree.grammar, key))
            set_define(tree, key, *get_param(tree.params, key), number_text(value));
        return;
    }
    if (set_define(tree, key, value, number_text(value))) return;
    try {
        set_param(tree.params, key, value);
    } catch (const InputError& e) {
        unknown(tree, e);
    }
}

}  // namespace sylva
