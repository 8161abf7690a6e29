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

#include "tree/parameters.h"
#include "tree/pipeline.h"
#include "tree/unread_params.h"
#include "turtle/grammar_reads.h"

namespace sylva::studio {
namespace {

std::string_view trim(std::string_view s) {
    const auto first = s.find_first_not_of(" \t\r");
    if (first == std::string_view::npos) return {};
    const auto last = s.find_last_not_of(" \t\r");
    return s.substr(first, last - first + 1);
}

bool is_name_char(char c) {
    return std::isalnum(static_cast<unsigned char>(c)) || c == '_';
}

// A plain number, all of `text`.
bool parse_number(std::string_view text, double& value) {
    text = trim(text);
    if (text.empty()) return false;
    if (text.front() == '+') text.remove_prefix(1);
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    return error == std::errc() && end == text.data() + text.size() && std::isfinite(value);
}

// One #define line taken apart: where its value stands (offsets into the line) and its
// comment. False for any other line.
struct DefineLine {
    std::string name;
    std::size_t value_begin = 0, value_end = 0;
    std::string_view comment;  // after the '#' that starts it; empty without one
};
bool parse_define_line(std::string_view line, DefineLine& out) {
    std::size_t i = line.find_first_not_of(" \t");
    if (i == std::string_view::npos || line[i] != '#') return false;
    i = line.find_first_not_of(" \t", i + 1);
    if (i == std::string_view::npos || line.substr(i, 6) != "define") return false;
    i += 6;
    if (i >= line.size() || (line[i] != ' ' && line[i] != '\t')) return false;
    i = line.find_first_not_of(" \t", i);
    if (i == std::string_view::npos) return false;
    const std::size_t name_begin = i;
    while (i < line.size() && is_name_char(line[i])) ++i;
    if (i == name_begin) return false;
    out.name = std::string(line.substr(name_begin, i - name_begin));
    const std::size_t hash = line.find('#', i);
    const std::string_view rest =
        line.substr(i, hash == std::string_view::npos ? line.npos : hash - i);
    const auto value_first = rest.find_first_not_of(" \t");
    if (value_first == std::string_view::npos) return false;
    const auto value_last = rest.find_last_not_of(" \t\r");
    out.value_begin = i + value_first;
    out.value_end = i + value_last + 1;
    out.comment = hash == std::string_view::npos ? std::string_view{} : line.substr(hash + 1);
    return true;
}

// "[10, 60] fork angle" -> 10, 60, "fork angle".
bool parse_range_comment(std::string_view comment, double& min, double& max, std::string& help) {
    comment = trim(comment);
    if (comment.empty() || comment.front() != '[') return false;
    const auto close = comment.find(']');
    const auto comma = comment.find(',');
    if (close == std::string_view::npos || comma == std::string_view::npos || comma > close)
        return false;
    if (!parse_number(comment.substr(1, comma - 1), min) ||
        !parse_number(comment.substr(comma + 1, close - comma - 1), max) || !(min < max))
        return false;
    help = std::string(trim(comment.substr(close + 1)));
    return true;
}

bool whole(double v) {
    return std::floor(v) == v && std::abs(v) < 1e9;
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
    int number = 0;
    for (std::string_view line : grammar_lines(grammar)) {
        ++number;
        DefineLine define;
        if (!parse_define_line(line, define)) continue;
        GrammarConstant c;
        if (!parse_number(line.substr(define.value_begin, define.value_end - define.value_begin),
                          c.value) ||
            !parse_range_comment(define.comment, c.min, c.max, c.help))
            continue;
        c.name = define.name;
        c.integer = whole(c.value) && whole(c.min) && whole(c.max);
        c.line = number;
        constants.push_back(std::move(c));
    }
    return constants;
}

bool set_grammar_constant(std::string& grammar, std::string_view name, double value) {
    std::size_t start = 0;
    while (start <= grammar.size()) {
        std::size_t end = grammar.find('\n', start);
        if (end == std::string::npos) end = grammar.size();
        const std::string_view line(grammar.data() + start, end - start);
        DefineLine define;
        if (parse_define_line(line, define) && define.name == name) {
            const std::string text = shortest_number(value);
            std::size_t old_width = define.value_end - define.value_begin;
            std::string replacement = text;
            // Keep the comment's column: pad a shorter value, and let a longer one take the
            // spaces after it (one stays).
            if (define.value_end < line.size()) {
                if (text.size() < old_width) {
                    replacement.append(old_width - text.size(), ' ');
                } else {
                    std::size_t spaces = 0;
                    while (define.value_end + spaces < line.size() &&
                           line[define.value_end + spaces] == ' ')
                        ++spaces;
                    old_width += std::min(text.size() - old_width, spaces > 0 ? spaces - 1 : 0);
                }
            }
            grammar.replace(start + define.value_begin, old_width, replacement);
            return true;
        }
        start = end + 1;
    }
    return false;
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
