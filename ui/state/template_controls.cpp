#include "ui/state/template_controls.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>
#include <utility>

#include "tree/grammar_constants.h"
#include "tree/parameters.h"
#include "tree/pipeline.h"
#include "tree/unread_params.h"

namespace sylva::studio {
namespace {

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

// Where the comment after a #define's value starts in its line (the '#' after the one of
// "#define"); npos without one.
std::size_t comment_column(std::string_view line) {
    const std::size_t define = line.find('#');
    return define == std::string_view::npos ? define : line.find('#', define + 1);
}

// Offsets of the 1-based `line`'s first character and its end in `text`.
std::pair<std::size_t, std::size_t> line_span(std::string_view text, int line) {
    std::size_t start = 0;
    for (int i = 1; i < line && start <= text.size(); ++i) {
        const std::size_t newline = text.find('\n', start);
        start = newline == std::string_view::npos ? text.size() + 1 : newline + 1;
    }
    if (start > text.size()) return {text.size(), text.size()};
    const std::size_t end = text.find('\n', start);
    return {start, end == std::string_view::npos ? text.size() : end};
}

}  // namespace

std::string shortest_number(double value) {
    if (value == 0.0) return "0";  // and not "-0"
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : std::to_string(value);
}

double round_for_range(double value, double min, double max) {
    const double span = max - min;
    if (!(span > 0)) return value;
    const double step = std::pow(10.0, std::floor(std::log10(span)) - 2.0);
    const double rounded = std::round(value / step) * step;
    // Through text, so 0.82 is the double "0.82" reads as (not 0.8200000000000001).
    char buffer[32];
    const int decimals = std::max(0, static_cast<int>(-std::floor(std::log10(step))));
    std::snprintf(buffer, sizeof buffer, "%.*f", decimals, rounded);
    return std::clamp(std::strtod(buffer, nullptr), min, max);
}

std::vector<GrammarConstant> grammar_constants(std::string_view grammar) {
    std::vector<GrammarConstant> constants;
    for (const GrammarDefine& d : grammar_defines(grammar)) {
        if (!d.value || !d.min || !d.max) continue;  // an expression, or no range: text only
        constants.push_back({d.name, *d.value, *d.min, *d.max, d.help, d.integer, d.line});
    }
    return constants;
}

bool set_grammar_constant(std::string& grammar, std::string_view name, double value) {
    // The comments' columns before the value is rewritten (tree/grammar_constants.h), so they
    // stay aligned: a shorter value is padded, a longer one takes the spaces after it (one
    // stays).
    std::vector<std::pair<int, std::size_t>> columns;  // line, comment column
    for (const GrammarDefine& d : grammar_defines(grammar)) {
        if (d.name != name) continue;
        const auto [begin, end] = line_span(grammar, d.line);
        columns.emplace_back(d.line,
                             comment_column(std::string_view(grammar).substr(begin, end - begin)));
    }
    if (!set_grammar_define(grammar, name, value)) return false;
    for (const auto& [line, column] : columns) {
        if (column == std::string_view::npos) continue;
        const auto [begin, end] = line_span(grammar, line);
        const std::size_t now =
            comment_column(std::string_view(grammar).substr(begin, end - begin));
        if (now == std::string_view::npos) continue;
        if (now < column) {
            grammar.insert(begin + now, column - now, ' ');
        } else {
            std::size_t spaces = 0;
            while (spaces < now && grammar[begin + now - 1 - spaces] == ' ') ++spaces;
            const std::size_t drop = std::min(now - column, spaces > 0 ? spaces - 1 : 0);
            grammar.erase(begin + now - drop, drop);
        }
    }
    return true;
}

std::map<std::string, std::string, std::less<>> inert_params(const TreeTemplate& tree) {
    // Asked every frame, and a growth method may grow the tree to answer (colonization's
    // max_no_grow): answers are kept per template and parameters.
    std::string key = tree.growth + "|" + std::to_string(static_cast<int>(tree.mode)) + "|" +
                      std::to_string(static_cast<int>(tree.width_model)) + "|" + tree.grammar;
    for (const ParamInfo& info : param_infos()) {
        char buffer[40];
        std::snprintf(buffer, sizeof buffer, "|%.17g", *get_param(tree.params, info.key));
        key += buffer;
    }
    using Unread = std::map<std::string, std::string, std::less<>>;
    static std::mutex mutex;
    static std::map<std::string, Unread> known;
    {
        const std::lock_guard lock(mutex);
        if (auto found = known.find(key); found != known.end()) return found->second;
    }
    Unread unread = unread_params(tree);
    const std::lock_guard lock(mutex);
    if (known.size() > 256) known.clear();
    known.emplace(std::move(key), unread);
    return unread;
}

std::vector<ParameterRow> parameter_rows(const TreeTemplate& tree) {
    const auto inert = inert_params(tree);
    std::vector<ParameterRow> rows;
    for (ParamGroup group : param_groups())
        for (const ParamInfo& info : param_infos()) {
            if (info.group != group) continue;
            ParameterRow row{&info, {}};
            if (auto found = inert.find(info.key); found != inert.end()) row.unread = found->second;
            rows.push_back(std::move(row));
        }
    return rows;
}

SliderRange slider_range(std::string_view key, double value) {
    const ParamInfo* info = find_param(key);
    if (!info) return {0, 1};
    // Useful drags for parameters whose valid range is far wider; typed values (Ctrl+click)
    // may go to the whole range.
    double min = info->min, max = info->max;
    if (key == "trunk_resolution" || key == "crown_resolution") max = 300;
    if (key == "triangle_budget") max = 5000;
    if (key == "leaf_density") max = 500;
    if (key == "branch_length" || key == "branch_width" || key == "sphere_diameter") max = 3;
    if (key == "crown_offset") min = -2, max = 2;
    // The template's own value sits inside, with room to go past it.
    if (value > max)
        max = std::min(info->max, info->integer ? std::ceil(value * 1.5) : value * 1.5);
    if (value < min) min = std::max(info->min, value < 0 ? value * 1.5 : info->min);
    return {min, max};
}

std::string budget_resolution_note(const TreeParams& params, std::string_view key) {
    const auto budget = static_cast<std::size_t>(std::max(params.triangle_budget, 0));
    int used = 0, set = 0;
    std::string why = "what it can show";
    if (key == "trunk_resolution" && budget > 0 && branch_style(params) == BranchStyle::Prisms)
        return "\nthe game mesh draws its branches as prisms: this meshes the full-detail "
               "trunk and sets the thinnest branch drawn";
    if (key == "trunk_resolution") {
        used = trunk_resolution_for_budget(params, budget);
        set = params.trunk_resolution;
        TreeParams shown = params;  // every branch meshed
        shown.drop_hidden = false;
        why += used < trunk_resolution_for_budget(shown, budget)
                   ? ", since drop_hidden is on"
                   : ", below " + std::to_string(kTrunkDetailBudget) + " triangles";
    } else if (key == "crown_resolution") {
        used = crown_resolution_for_budget(params.crown_resolution, budget);
        set = params.crown_resolution;
    }
    if (used >= set) return "";
    return "\nmeshed at " + std::to_string(used) + " for the budget of " + std::to_string(budget) +
           " triangles (" + why + ")";
}

std::string constant_label(const GrammarConstant& constant) {
    const std::string_view help = constant.help;
    const std::string_view label = trim(help.substr(0, help.find_first_of(",(;")));
    return label.empty() ? constant.name : std::string(label);
}

bool search_finds(std::string_view query, std::string_view text) {
    auto lower = [](unsigned char c) { return static_cast<char>(std::tolower(c)); };
    std::string haystack(text.size(), ' ');
    std::transform(text.begin(), text.end(), haystack.begin(), lower);
    std::size_t start = 0;
    while (start < query.size()) {
        std::size_t end = query.find(' ', start);
        if (end == std::string_view::npos) end = query.size();
        std::string word(end - start, ' ');
        std::transform(query.begin() + static_cast<std::ptrdiff_t>(start),
                       query.begin() + static_cast<std::ptrdiff_t>(end), word.begin(), lower);
        if (!word.empty() && haystack.find(word) == std::string::npos) return false;
        start = end + 1;
    }
    return true;
}

std::string parameter_search_text(const ParamInfo& info) {
    std::string words(info.key);
    std::replace(words.begin(), words.end(), '_', ' ');
    return std::string(info.key) + " " + words + " " + std::string(info.help) + " " +
           std::string(group_title(info.group));
}

}  // namespace sylva::studio
