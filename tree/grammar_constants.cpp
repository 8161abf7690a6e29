#include "tree/grammar_constants.h"

#include <cctype>
#include <charconv>
#include <cmath>

#include "turtle/grammar_reads.h"

namespace sylva {
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

// A plain finite number, all of `text` (a leading '+' allowed).
std::optional<double> plain_number(std::string_view text) {
    text = trim(text);
    if (!text.empty() && text.front() == '+') text.remove_prefix(1);
    double value = 0;
    const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (text.empty() || error != std::errc() || end != text.data() + text.size() ||
        !std::isfinite(value))
        return std::nullopt;
    return value;
}

// One #define line taken apart: its name, where its value stands (offsets into the line)
// and its comment (after the '#' that starts it; empty without one).
struct DefineLine {
    std::string name;
    std::size_t value_begin = 0, value_end = 0;
    std::string_view comment;
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

// "[10, 60] fork angle" -> 10, 60, "fork angle"; false for any other comment.
bool parse_range_comment(std::string_view comment, GrammarDefine& out) {
    comment = trim(comment);
    if (comment.empty() || comment.front() != '[') return false;
    const auto close = comment.find(']');
    const auto comma = comment.find(',');
    if (close == std::string_view::npos || comma == std::string_view::npos || comma > close)
        return false;
    const std::optional<double> min = plain_number(comment.substr(1, comma - 1));
    const std::optional<double> max = plain_number(comment.substr(comma + 1, close - comma - 1));
    if (!min || !max || !(*min < *max)) return false;
    out.min = min;
    out.max = max;
    out.help = std::string(trim(comment.substr(close + 1)));
    return true;
}

bool whole(double v) {
    return std::floor(v) == v && std::abs(v) < 1e9;
}

std::string shortest(double value) {
    if (value == 0.0) return "0";  // and not "-0"
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    return error == std::errc() ? std::string(buffer, end) : std::to_string(value);
}

}  // namespace

std::vector<GrammarDefine> grammar_defines(std::string_view grammar) {
    std::vector<GrammarDefine> defines;
    int number = 0;
    for (std::string_view line : grammar_lines(grammar)) {
        ++number;
        DefineLine define;
        if (!parse_define_line(line, define)) continue;
        GrammarDefine d;
        d.name = define.name;
        d.value =
            plain_number(line.substr(define.value_begin, define.value_end - define.value_begin));
        parse_range_comment(define.comment, d);
        d.integer = d.value && d.min && whole(*d.value) && whole(*d.min) && whole(*d.max);
        d.line = number;
        defines.push_back(std::move(d));
    }
    return defines;
}

std::optional<GrammarDefine> find_grammar_define(std::string_view grammar, std::string_view name) {
    for (GrammarDefine& d : grammar_defines(grammar))
        if (d.name == name) return std::move(d);
    return std::nullopt;
}

bool set_grammar_define(std::string& grammar, std::string_view name, double value) {
    const std::string text = shortest(value);
    bool found = false;
    std::size_t start = 0;
    while (start <= grammar.size()) {
        std::size_t end = grammar.find('\n', start);
        if (end == std::string::npos) end = grammar.size();
        DefineLine define;
        if (parse_define_line(std::string_view(grammar).substr(start, end - start), define) &&
            define.name == name) {
            grammar.replace(start + define.value_begin, define.value_end - define.value_begin,
                            text);
            found = true;
            end = grammar.find('\n', start);
            if (end == std::string::npos) end = grammar.size();
        }
        start = end + 1;
    }
    return found;
}

}  // namespace sylva
