#include "turtle/grammar_reads.h"

#include <algorithm>
#include <cctype>

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

// The text a turtle draws from: the axiom and every production's successor, comments and
// directives left out (the predecessor and condition of a rule are matched, not drawn).
std::vector<std::string_view> drawn_texts(std::string_view grammar) {
    std::vector<std::string_view> texts;
    for (std::string_view line : grammar_lines(grammar)) {
        line = trim(line);
        if (line.empty() || line.front() == '#') continue;  // comments, #define, #axiom, #rules
        if (const auto hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        if (const auto arrow = line.rfind("->"); arrow != std::string_view::npos) {
            line = line.substr(arrow + 2);
            // A stochastic rule's weight (": w") is not drawn: cut at the first ':' outside
            // parentheses.
            int depth = 0;
            for (std::size_t i = 0; i < line.size(); ++i) {
                depth += line[i] == '(' ? 1 : line[i] == ')' ? -1 : 0;
                if (depth == 0 && line[i] == ':') {
                    line = line.substr(0, i);
                    break;
                }
            }
        } else if (line.starts_with("axiom:")) {
            line = line.substr(6);
        }
        texts.push_back(line);
    }
    return texts;
}

// The successors of the rules for module `symbol` (the text after "->" of each line whose
// predecessor starts with it).
std::vector<std::string_view> successors_of(std::string_view grammar, char symbol) {
    std::vector<std::string_view> out;
    for (std::string_view line : grammar_lines(grammar)) {
        line = trim(line);
        if (line.empty() || line.front() != symbol) continue;
        if (const auto hash = line.find('#'); hash != std::string_view::npos)
            line = line.substr(0, hash);
        if (const auto arrow = line.rfind("->"); arrow != std::string_view::npos)
            out.push_back(line.substr(arrow + 2));
    }
    return out;
}

// True when `text` sets a width ('!(w)') before it draws: through the rules of the modules
// it starts with, `depth` levels deep.
bool sets_width_first(std::string_view grammar, std::string_view text, int depth) {
    int parens = 0;
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c == '(') ++parens;
        if (c == ')') --parens;
        if (parens != 0) continue;
        if (c == '!') {
            const auto next = text.find_first_not_of(" \t", i + 1);
            if (next != std::string_view::npos && text[next] == '(') return true;
            return false;  // '!' alone scales the starting width
        }
        if (c == 'F' || c == 'f') return false;
        if (std::isalpha(static_cast<unsigned char>(c))) {
            if (depth == 0) return false;
            const std::vector<std::string_view> rules = successors_of(grammar, c);
            if (rules.empty()) continue;  // a module without rules draws nothing
            return std::all_of(rules.begin(), rules.end(), [&](std::string_view successor) {
                return sets_width_first(grammar, successor, depth - 1);
            });
        }
    }
    return false;
}

}  // namespace

std::vector<std::string_view> grammar_lines(std::string_view text) {
    std::vector<std::string_view> lines;
    std::size_t start = 0;
    while (start <= text.size()) {
        const std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) {
            if (start < text.size()) lines.push_back(text.substr(start));
            break;
        }
        lines.push_back(text.substr(start, end - start));
        start = end + 1;
    }
    return lines;
}

bool grammar_uses_default(std::string_view grammar, std::string_view symbols) {
    for (std::string_view text : drawn_texts(grammar)) {
        int depth = 0;
        for (std::size_t i = 0; i < text.size(); ++i) {
            const char c = text[i];
            if (c == '(') ++depth;
            if (c == ')') --depth;
            if (depth != 0 || symbols.find(c) == std::string_view::npos) continue;
            const auto next = text.find_first_not_of(" \t", i + 1);
            if (next == std::string_view::npos || text[next] != '(') return true;
        }
    }
    return false;
}

bool grammar_names(std::string_view grammar, std::string_view key) {
    for (std::string_view line : grammar_lines(grammar)) {
        std::string_view code = line;
        const auto first = code.find_first_not_of(" \t");
        if (first != std::string_view::npos && code[first] == '#') {
            // A #define's value may name it; its comment does not count.
            const auto second = code.find('#', first + 1);
            code = code.substr(0, second);
        } else if (const auto hash = code.find('#'); hash != std::string_view::npos) {
            code = code.substr(0, hash);
        }
        for (auto at = code.find(key); at != std::string_view::npos; at = code.find(key, at + 1)) {
            const bool before = at > 0 && is_name_char(code[at - 1]);
            const bool after = at + key.size() < code.size() && is_name_char(code[at + key.size()]);
            if (!before && !after) return true;
        }
    }
    return false;
}

bool axiom_sets_width(std::string_view grammar) {
    const std::vector<std::string_view> texts = drawn_texts(grammar);
    return !texts.empty() && sets_width_first(grammar, texts.front(), 2);
}

}  // namespace sylva
