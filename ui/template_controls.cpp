#include "ui/template_controls.h"

#include <algorithm>
#include <array>
#include <cctype>
#include <charconv>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>
#include <mutex>

#include "colonization/colonization_growth.h"
#include "core/tree_params.h"
#include "tree/pipeline.h"
#include "tree/template_crown.h"

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

// The lines of `text`, without their newlines.
std::vector<std::string_view> lines_of(std::string_view text) {
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

// The text a turtle draws from: the axiom and every production's successor, comments and
// directives left out (the predecessor and condition of a rule are matched, not drawn).
std::vector<std::string_view> drawn_texts(std::string_view grammar) {
    std::vector<std::string_view> texts;
    for (std::string_view line : lines_of(grammar)) {
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

// True when one of `symbols` is drawn without an argument anywhere, so the turtle uses the
// global default for it.
bool uses_default(const std::vector<std::string_view>& texts, std::string_view symbols) {
    for (std::string_view text : texts) {
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

// True when an expression of the grammar names the parameter (template parameters are
// constants every expression sees).
bool names_param(std::string_view grammar, std::string_view key) {
    for (std::string_view line : lines_of(grammar)) {
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

// The successors of the rules for module `symbol` (the text after "->" of each line whose
// predecessor starts with it).
std::vector<std::string_view> successors_of(std::string_view grammar, char symbol) {
    std::vector<std::string_view> out;
    for (std::string_view line : lines_of(grammar)) {
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

// The axiom (or the rules it starts with) sets its own starting width before the first F:
// branch_width is never drawn.
bool axiom_sets_width(std::string_view grammar) {
    const std::vector<std::string_view> texts = drawn_texts(grammar);
    return !texts.empty() && sets_width_first(grammar, texts.front(), 2);
}

bool colonization_key(std::string_view key) {
    static constexpr std::array<std::string_view, 31> keys = {
        "attraction_points", "influence_radius",
        "kill_distance",     "step_size",
        "max_iterations",    "envelope",
        "envelope_size_x",   "envelope_size_y",
        "envelope_size_z",   "envelope_base",
        "envelope_offset_x", "envelope_offset_z",
        "envelope_template", "envelope_tilt",
        "obstacle",          "obstacle_x",
        "obstacle_y",        "obstacle_z",
        "obstacle_size_x",   "obstacle_size_y",
        "obstacle_size_z",   "roots",
        "root_spread",       "point_distribution",
        "trunk_height",      "max_degree",
        "max_depth",         "max_no_grow",
        "weighted_growth",   "curve_reduction",
        "angle_smoothing"};
    return std::find(keys.begin(), keys.end(), key) != keys.end();
}

// colonization_growth.h's why_max_no_grow_is_unused, which grows the tree: kept per set of
// parameters, since the panel asks every frame. Empty when it cannot tell (a bad template).
std::string max_no_grow_unused(const TreeTemplate& tree) {
    std::string key = tree.growth;
    for (const ParamInfo& info : param_infos()) {
        char buffer[40];
        std::snprintf(buffer, sizeof buffer, "|%.17g", *get_param(tree.params, info.key));
        key += buffer;
    }
    static std::mutex mutex;
    static std::map<std::string, std::string> known;
    {
        const std::lock_guard lock(mutex);
        if (auto found = known.find(key); found != known.end()) return found->second;
    }
    std::string why;
    try {
        GrowthContext context;
        context.template_crown = [](std::string_view name) { return template_crown(name); };
        why = why_max_no_grow_is_unused(tree, context);
    } catch (const std::exception&) {
        // The growth reports the error itself; the slider stays enabled.
    }
    const std::lock_guard lock(mutex);
    if (known.size() > 256) known.clear();
    known.emplace(std::move(key), why);
    return why;
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
    for (std::string_view line : lines_of(grammar)) {
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
    std::map<std::string, std::string, std::less<>> inert;
    const TreeParams& p = tree.params;
    const bool colonization = tree.growth == "colonization";
    auto mark = [&](std::string_view key, std::string reason) {
        inert.emplace(std::string(key), std::move(reason));
    };
    if (colonization) {
        for (std::string_view key : {"generations", "branch_length", "pitch_angle", "yaw_angle",
                                     "branch_width", "trunk_taper", "branch_taper", "tropism"})
            mark(key,
                 "an L-system parameter: space colonization does not read it (its branches "
                 "follow the attraction points; widths come from tip_width and pipe_exponent)");
        if (p.envelope == kEnvelopeTemplate) {
            for (std::string_view key :
                 {"envelope_size_x", "envelope_size_y", "envelope_size_z", "envelope_base",
                  "envelope_offset_x", "envelope_offset_z", "envelope_tilt"})
                mark(key,
                     "the envelope is another template's crown (envelope = template): "
                     "its own size and place are not used");
        } else {
            mark("envelope_template", "only used with envelope = template");
        }
        if (p.obstacle == 0)
            for (std::string_view key : {"obstacle_x", "obstacle_y", "obstacle_z",
                                         "obstacle_size_x", "obstacle_size_y", "obstacle_size_z"})
                mark(key, "no obstacle: set obstacle to sphere or box first");
        if (p.roots <= 1)
            mark("root_spread", "one root: the spread of a circle of roots is unused");
        for (std::string_view key : {"bend", "bend_frequency", "jitter", "width_variation"})
            mark(key,
                 "a turtle parameter: space colonization does not read it (tropism_variation "
                 "varies its growth directions)");
        mark("noise_kind",
             "the L-system's noise: space colonization's variation keeps the gradient noise");
        if (std::string why = max_no_grow_unused(tree); !why.empty())
            mark("max_no_grow", std::move(why));
    } else {
        for (const ParamInfo& info : param_infos())
            if (colonization_key(info.key))
                mark(info.key,
                     "a space colonization parameter: the L-system does not read it "
                     "(switch growth to colonization)");
        const std::vector<std::string_view> texts = drawn_texts(tree.grammar);
        auto unread = [&](std::string_view key, std::string_view symbols) {
            return !uses_default(texts, symbols) && !names_param(tree.grammar, key);
        };
        // The noise kind matters where something reads the noise: the rules (noise, fbm,
        // noise_loop, and the ", noise F" choice all name it) or the turtle's variation.
        if (!names_param(tree.grammar, "noise") && !names_param(tree.grammar, "fbm") &&
            !names_param(tree.grammar, "noise_loop") && p.bend == 0.0 && p.width_variation == 0.0 &&
            (p.tropism_variation == 0.0 || p.tropism == 0.0))
            mark("noise_kind",
                 "nothing reads the noise: the rules call no noise(), fbm() or noise_loop() and "
                 "bend, width_variation and tropism_variation are 0");
        if (unread("branch_length", "Ff"))
            mark("branch_length", "every F and f in the rules gives its own length");
        if (unread("pitch_angle", "&^"))
            mark("pitch_angle", "every & and ^ in the rules gives its own angle");
        if (unread("yaw_angle", "+-\\/"))
            mark("yaw_angle", "every +, -, \\ and / in the rules gives its own angle");
        if (tree.mode == TurtleMode::Lptg && !names_param(tree.grammar, "tropism"))
            mark("tropism", "the lptg turtle (seed 001) does not bend towards gravity");
        if ((inert.contains("tropism") || p.tropism == 0.0) &&
            !names_param(tree.grammar, "tropism")) {
            mark("tropism_variation", "no tropism to vary: set tropism first");
            // The L-system's tropism vector is where `tropism` bends towards.
            for (std::string_view key :
                 {"tropism_vector_x", "tropism_vector_y", "tropism_vector_z"})
                if (!names_param(tree.grammar, key))
                    mark(key, "no tropism to point: set tropism first");
        }
        const auto width_reason = [&](WidthModel model) -> std::string {
            switch (model) {
                case WidthModel::Explicit:
                    return "widths = explicit: only ! in the rules sets widths";
                case WidthModel::Pipe:
                    return "widths = pipe: the pipe model sets every width from tip_width";
                default:
                    return "widths = taper: per-segment factors set the widths";
            }
        };
        for (std::string_view key :
             {"trunk_taper", "branch_taper", "tip_width", "pipe_exponent", "branch_width"}) {
            if (names_param(tree.grammar, key)) continue;
            const bool taper_key = key == "trunk_taper" || key == "branch_taper";
            const bool pipe_key = key == "tip_width" || key == "pipe_exponent";
            bool read = true;
            switch (tree.width_model) {
                case WidthModel::Explicit:
                    read = key == "branch_width" && !axiom_sets_width(tree.grammar);
                    break;
                case WidthModel::Taper:
                    read = taper_key || (key == "branch_width" && !axiom_sets_width(tree.grammar));
                    break;
                case WidthModel::Pipe:
                    read = pipe_key;
                    break;
            }
            if (!read) {
                std::string reason = width_reason(tree.width_model);
                if (key == "branch_width" && tree.width_model != WidthModel::Pipe)
                    reason = "the axiom sets its own starting width with !(...)";
                mark(key, reason);
            }
        }
    }
    if (p.bend == 0.0) mark("bend_frequency", "bend is 0: there is no bending to shape");
    if (p.leaf_density <= 0.0)
        for (std::string_view key : {"leaf_size", "leaf_shape"})
            mark(key, "leaf_density is 0: the crown carries no leaves");
    if (p.crown_mesh == 0)
        for (std::string_view key : {"crown_resolution", "crown_blend", "crown_fusion",
                                     "crown_shape", "crown_lump_triangles"})
            mark(key, "crown_mesh is off: the crown is not meshed (its leaves stay)");
    if (p.triangle_budget == 0) {
        mark("crown_shape", "triangle_budget is 0: the game mesh keeps the crown as meshed");
        mark("branch_style", "triangle_budget is 0: the game mesh keeps the trunk as meshed");
    }
    if (p.triangle_budget == 0 || static_cast<CrownShape>(p.crown_shape) == CrownShape::Blobs)
        mark("crown_lump_triangles", "the game mesh draws the crown as blobs, not as lumps");
    if (p.sphere_diameter <= 0.0)
        for (std::string_view key :
             {"crown_resolution", "crown_blend", "crown_fusion", "crown_offset", "leaf_density",
              "leaf_size", "leaf_shape", "crown_mesh", "crown_merge", "crown_shape",
              "crown_lump_triangles"})
            mark(key, "sphere_diameter is 0: the tree has no crown");
    return inert;
}

SliderRange slider_range(std::string_view key, double value) {
    const ParamInfo* info = nullptr;
    for (const ParamInfo& i : param_infos())
        if (i.key == key) info = &i;
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
        shown.drop_hidden = 0;
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

}  // namespace sylva::studio
