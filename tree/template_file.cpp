#include "tree/template_file.h"

#include <toml++/toml.h>

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdio>
#include <sstream>

#include "core/atomic_file.h"
#include "core/errors.h"
#include "core/seed.h"
#include "tree/growth.h"
#include "tree/parameters.h"

namespace sylva {
namespace {

struct Named {
    std::string_view name;
    int value;
};
constexpr Named kModes[] = {{"abop", int(TurtleMode::Abop)}, {"lptg", int(TurtleMode::Lptg)}};
constexpr Named kWidths[] = {{"explicit", int(WidthModel::Explicit)},
                             {"taper", int(WidthModel::Taper)},
                             {"pipe", int(WidthModel::Pipe)}};

class Reader {
  public:
    explicit Reader(const std::string& source) : source_(source) {}

    [[noreturn]] void fail(const toml::node* node, const std::string& message) const {
        SourceLocation where{source_};
        if (node && node->source().begin.line > 0) where.line = int(node->source().begin.line);
        throw InputError(message, where);
    }

    std::string string(const toml::table& table, std::string_view key, bool required) const {
        const toml::node* node = table.get(key);
        if (!node) {
            if (required) fail(&table, "missing key '" + std::string(key) + "'");
            return {};
        }
        if (!node->is_string()) fail(node, "'" + std::string(key) + "' must be a string");
        return std::string(*node->value<std::string_view>());
    }

    template <size_t N>
    int named(const toml::table& table, std::string_view key, const Named (&names)[N],
              int fallback) const {
        std::string text = string(table, key, false);
        if (text.empty()) return fallback;
        std::string known;
        for (const Named& n : names) {
            if (n.name == text) return n.value;
            known += (known.empty() ? "" : ", ") + std::string(n.name);
        }
        fail(table.get(key),
             "'" + std::string(key) + "' must be one of " + known + ", not '" + text + "'");
    }

    void params(const toml::node* node, TreeParams& params) const {
        if (!node) return;
        const toml::table* table = node->as_table();
        if (!table) fail(node, "'params' must be a table");
        for (const auto& [key, value] : *table) {
            if (key.str() == "seed") {
                // An integer node (value<int64_t>() would cast a float, seed = 1e308, to an
                // integer first, which is undefined) within the seed range (core/seed.h).
                const toml::value<int64_t>* seed = value.as_integer();
                if (!seed || seed->get() < 0 || !is_seed(static_cast<std::uint64_t>(seed->get())))
                    fail(&value, "[params] seed must be a whole number from " + seed_range_text());
                params.seed = static_cast<std::uint64_t>(seed->get());
                continue;
            }
            try {
                const ParamInfo* info = find_param(key.str());
                if (value.is_string())
                    set_param(params, key.str(), *value.value<std::string_view>());
                else if (value.is_boolean() && info && info->flag)
                    set_param(params, key.str(), *value.value<bool>() ? 1.0 : 0.0);
                else if (value.is_number()) {
                    // An integer beyond 2^53 has no exact double: say so instead of rounding.
                    const std::optional<double> number = value.value<double>();
                    if (!number)
                        throw InputError("parameter " + std::string(key.str()) +
                                         " is not a number a double can hold exactly");
                    set_param(params, key.str(), *number);
                } else
                    throw InputError("parameter " + std::string(key.str()) + " must be a number");
            } catch (const InputError& e) {
                fail(&value, std::string("[params] ") + e.reason());
            }
        }
    }

    // [colors]: the parts' colours and, optionally, `palette`; or `colors = [...]`, the
    // palette alone (the parts keep their defaults).
    void colors(const toml::node* node, PartColors& colors) const {
        if (!node) return;
        if (node->as_array()) return palette(node, "colors", colors.palette);
        const toml::table* table = node->as_table();
        if (!table) fail(node, "'colors' must be a table of part colours or a list of [r, g, b]");
        for (const auto& [key, value] : *table) {
            if (key.str() == "palette") {
                palette(&value, "[colors] palette", colors.palette);
                continue;
            }
            glm::vec3* target = key.str() == "trunk"    ? &colors.trunk
                                : key.str() == "crown"  ? &colors.crown
                                : key.str() == "leaves" ? &colors.leaves
                                                        : nullptr;
            if (!target)
                fail(&value, "[colors] unknown part '" + std::string(key.str()) +
                                 "' (trunk, crown, leaves, palette)");
            *target = rgb(&value, "[colors] " + std::string(key.str()));
        }
    }

  private:
    glm::vec3 rgb(const toml::node* value, const std::string& what) const {
        const toml::array* rgb = value->as_array();
        if (!rgb || rgb->size() != 3) fail(value, what + " must be [r, g, b]");
        glm::vec3 out;
        for (size_t i = 0; i < 3; ++i) {
            std::optional<double> c = (*rgb)[i].value<double>();
            if (!c || !(*c >= 0.0 && *c <= 1.0))
                fail(value, what + ": each component must be a number from 0 to 1");
            out[static_cast<int>(i)] = static_cast<float>(*c);
        }
        return out;
    }

    void palette(const toml::node* node, const std::string& what,
                 std::vector<glm::vec3>& out) const {
        const toml::array* list = node->as_array();
        if (!list) fail(node, what + " must be a list of [r, g, b]");
        if (list->size() > kMaxPaletteColors)
            fail(node, what + " has " + std::to_string(list->size()) + " colours; at most " +
                           std::to_string(kMaxPaletteColors));
        out.clear();
        for (size_t i = 0; i < list->size(); ++i)
            out.push_back(rgb(list->get(i), what + "[" + std::to_string(i) + "]"));
    }

  private:
    const std::string& source_;
};

// The file's line of the grammar's first line: a multi-line string drops a newline right
// after its opening quotes, so its text then starts on the next line.
int grammar_first_line(std::string_view text, const toml::node* grammar) {
    const toml::source_region& where = grammar->source();
    std::size_t start = 0;
    for (std::size_t line = 1; line < where.begin.line && start != std::string_view::npos; ++line) {
        start = text.find('\n', start);
        if (start != std::string_view::npos) ++start;
    }
    if (start == std::string_view::npos) return int(where.begin.line);
    std::string_view rest = text.substr(start + where.begin.column - 1);
    const bool multi_line = rest.starts_with("'''") || rest.starts_with("\"\"\"");
    const bool newline_after =
        multi_line && (rest.substr(3).starts_with('\n') || rest.substr(3).starts_with("\r\n"));
    return int(where.begin.line) + (newline_after ? 1 : 0);
}

// The shortest text that reads back to `value`, always a TOML float ("0.8", "34.0", "1e-07"):
// 0.8 is written as 0.8, not 0.80000000000000004.
template <class Real>
std::string toml_float(Real value) {
    if (value == 0) return "0.0";
    char buffer[32];
    const auto [end, error] = std::to_chars(buffer, buffer + sizeof buffer, value);
    std::string text = error == std::errc() ? std::string(buffer, end) : std::to_string(value);
    if (text.find_first_of(".eEn") == std::string::npos) text += ".0";
    return text;
}

// A value's end on its line: past a quoted string (which may hold '#'), else the first '#'.
std::size_t comment_start(std::string_view line, std::size_t value_begin) {
    char quote = 0;
    for (std::size_t i = value_begin; i < line.size(); ++i) {
        const char c = line[i];
        if (quote) {
            if (c == '\\' && quote == '"')
                ++i;
            else if (c == quote)
                quote = 0;
        } else if (c == '"' || c == '\'') {
            quote = c;
        } else if (c == '#') {
            return i;
        }
    }
    return std::string_view::npos;
}

}  // namespace

TemplateComments template_comments(std::string_view text) {
    TemplateComments comments;
    std::string section, pending;
    bool seen_key = false;
    std::string_view multiline_end;  // inside a multi-line string: its closing quotes
    std::size_t start = 0;
    while (start < text.size()) {
        std::size_t end = text.find('\n', start);
        if (end == std::string_view::npos) end = text.size();
        const std::string_view line = text.substr(start, end - start);
        start = end + 1;
        if (!multiline_end.empty()) {
            if (line.find(multiline_end) != std::string_view::npos) multiline_end = {};
            continue;
        }
        const auto first = line.find_first_not_of(" \t\r");
        if (first == std::string_view::npos) {
            if (!seen_key && !pending.empty()) pending += "\n";
            continue;
        }
        if (line[first] == '#') {
            pending += std::string(line.substr(first)) + "\n";
            continue;
        }
        if (line[first] == '[') {
            const auto close = line.find(']', first);
            section = std::string(line.substr(first + 1, close - first - 1));
            if (!pending.empty()) comments.above["[" + section + "]"] = pending;
            pending.clear();
            seen_key = true;
            continue;
        }
        const auto equals = line.find('=', first);
        if (equals == std::string_view::npos) continue;
        std::string_view key = line.substr(first, equals - first);
        key = key.substr(0, key.find_last_not_of(" \t") + 1);
        const std::string id = section + "." + std::string(key);
        if (!seen_key) {
            comments.header = pending;
            seen_key = true;
        } else if (!pending.empty()) {
            comments.above[id] = pending;
        }
        pending.clear();
        const auto value = line.find_first_not_of(" \t", equals + 1);
        if (value == std::string_view::npos) continue;
        for (std::string_view quotes : {"'''", "\"\"\""}) {
            if (line.substr(value, 3) == quotes &&
                line.find(quotes, value + 3) == std::string_view::npos) {
                multiline_end = quotes;
                break;
            }
        }
        if (!multiline_end.empty()) continue;
        const auto hash = comment_start(line, value);
        if (hash != std::string_view::npos) {
            std::string_view comment = line.substr(hash);
            comment = comment.substr(0, comment.find_last_not_of(" \t\r") + 1);
            comments.after[id] = std::string(comment);
        }
    }
    return comments;
}

TreeTemplate parse_template_file(std::string_view text, const std::string& source) {
    toml::table doc;
    try {
        doc = toml::parse(text, source);
    } catch (const toml::parse_error& e) {
        throw InputError(std::string(e.description()),
                         {source, int(e.source().begin.line), int(e.source().begin.column)});
    }
    Reader read(source);
    for (const auto& [key, value] : doc) {
        static constexpr std::string_view known[] = {"name",   "description", "growth", "turtle",
                                                     "widths", "grammar",     "params", "colors"};
        if (std::find(std::begin(known), std::end(known), key.str()) == std::end(known))
            read.fail(&value,
                      "unknown key '" + std::string(key.str()) +
                          "' (name, description, growth, turtle, widths, grammar, params, colors)");
    }
    TreeTemplate tree;
    tree.name = read.string(doc, "name", true);
    tree.description = read.string(doc, "description", false);
    tree.source = source;
    if (std::string growth = read.string(doc, "growth", false); !growth.empty()) {
        if (!find_growth_method(growth))
            read.fail(doc.get("growth"), "'growth' must be one of " + growth_method_names() +
                                             ", not '" + growth + "'");
        tree.growth = growth;
    }
    // Only a method that reads a grammar (the L-system) needs one; others ignore one.
    const GrowthMethod* method = find_growth_method(tree.growth);
    tree.grammar = read.string(doc, "grammar", method && method->uses_grammar);
    if (doc.get("grammar")) tree.grammar_line = grammar_first_line(text, doc.get("grammar"));
    tree.mode = static_cast<TurtleMode>(read.named(doc, "turtle", kModes, int(TurtleMode::Abop)));
    tree.width_model =
        static_cast<WidthModel>(read.named(doc, "widths", kWidths, int(WidthModel::Taper)));
    read.params(doc.get("params"), tree.params);
    read.colors(doc.get("colors"), tree.colors);
    return tree;
}

std::string template_file_text(const TreeTemplate& tree, std::string_view original) {
    auto name_of = [](const auto& names, int value) {
        for (const Named& n : names)
            if (n.value == value) return n.name;
        return std::string_view{};
    };
    const TemplateComments comments = template_comments(original);
    std::ostringstream out;
    // A key's comment lines above it, then the key, then its comment at the line's end.
    auto put = [&](std::string_view section, std::string_view key, const std::string& value) {
        const std::string id = std::string(section) + "." + std::string(key);
        if (auto above = comments.above.find(id); above != comments.above.end())
            out << above->second;
        out << key << " = " << value;
        if (auto after = comments.after.find(id); after != comments.after.end())
            out << "  " << after->second;
        out << "\n";
    };
    auto quoted = [](const std::string& text) {
        std::ostringstream q;
        q << toml::value<std::string>(text);
        return q.str();
    };
    out << (comments.header.empty() ? std::string("# Sylva tree template\n") : comments.header);
    put("", "name", quoted(tree.name));
    put("", "description", quoted(tree.description));
    if (tree.growth != TreeTemplate{}.growth) put("", "growth", quoted(tree.growth));
    put("", "turtle", "\"" + std::string(name_of(kModes, int(tree.mode))) + "\"");
    put("", "widths", "\"" + std::string(name_of(kWidths, int(tree.width_model))) + "\"");
    // Written so it reads back byte for byte: the closing quotes follow the grammar's last
    // character (a newline there would be read as part of it), and a grammar a literal
    // string cannot hold (three quotes, a control character) goes into an escaped string.
    const std::string& grammar = tree.grammar;
    const bool literal =
        grammar.find("'''") == std::string::npos &&
        std::none_of(grammar.begin(), grammar.end(), [](char c) {
            return (static_cast<unsigned char>(c) < 0x20 && c != '\n' && c != '\t') || c == '\x7f';
        });
    const GrowthMethod* method = find_growth_method(tree.growth);
    if (grammar.empty() && method && !method->uses_grammar) {
        // A growth method without a grammar (colonization) writes none.
    } else if (literal) {
        put("", "grammar", "'''\n" + grammar + "'''");
    } else {
        std::string escaped;
        for (char c : grammar) {
            const auto byte = static_cast<unsigned char>(c);
            if (c == '\\' || c == '"') {
                escaped += '\\';
                escaped += c;
            } else if ((byte < 0x20 && c != '\n' && c != '\t') || byte == 0x7f) {
                char code[8];
                std::snprintf(code, sizeof code, "\\u%04X", unsigned(byte));
                escaped += code;
            } else {
                escaped += c;
            }
        }
        put("", "grammar", "\"\"\"\n" + escaped + "\"\"\"");
    }
    out << "\n";
    if (auto above = comments.above.find("[params]"); above != comments.above.end())
        out << above->second;
    out << "[params]\n";
    // The shared parameters and the growth method's own; another method's only where they
    // differ from the default (set before the growth was switched), so none is lost.
    for (const ParamInfo& info : param_infos()) {
        const double value = *get_param(tree.params, info.key);
        if (!info.owner.empty() && info.owner != tree.growth && value == info.default_value)
            continue;
        if (!info.choices.empty())
            put("params", info.key, quoted(param_text(tree.params, info)));
        else if (info.integer)
            put("params", info.key, std::to_string(static_cast<int64_t>(value)));
        else
            put("params", info.key, toml_float(value));
    }
    // A seed outside core/seed.h's range would write a file no reader takes back.
    if (!is_seed(tree.params.seed))
        throw InputError("seed " + std::to_string(tree.params.seed) + " is not a seed from " +
                         seed_range_text() + ", so the file could not be read back");
    put("params", "seed", std::to_string(tree.params.seed));
    out << "\n";
    if (auto above = comments.above.find("[colors]"); above != comments.above.end())
        out << above->second;
    out << "[colors]\n";
    auto rgb = [](const glm::vec3& c) {
        // Shortest as floats, which is what they are: 0.33, not 0.33000001311302185.
        return "[" + toml_float(c.r) + ", " + toml_float(c.g) + ", " + toml_float(c.b) + "]";
    };
    put("colors", "trunk", rgb(tree.colors.trunk));
    put("colors", "crown", rgb(tree.colors.crown));
    put("colors", "leaves", rgb(tree.colors.leaves));
    if (!tree.colors.palette.empty()) {
        std::string list = "[";
        for (std::size_t i = 0; i < tree.colors.palette.size(); ++i)
            list += (i ? ", " : "") + rgb(tree.colors.palette[i]);
        put("colors", "palette", list + "]");
    }
    return out.str();
}

void save_template_file(const std::filesystem::path& path, const TreeTemplate& tree,
                        std::string_view original) {
    std::string text = template_file_text(tree, original);
    write_file_atomically(path, [&](std::ostream& out) { out << text; });
}

}  // namespace sylva
