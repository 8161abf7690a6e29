#include "layout/grammar_json.h"

#include <cmath>
#include <limits>
#include <nlohmann/json.hpp>
#include <set>
#include <tuple>

#include "core/errors.h"

namespace sylva::layout {

namespace {

nlohmann::ordered_json graph_json(const AngleGraph& g) {
    nlohmann::ordered_json vs = nlohmann::ordered_json::array();
    for (const auto& ds : g.vertices) {
        nlohmann::ordered_json v = nlohmann::ordered_json::array();
        for (const Dart& d : ds) v.push_back({d.dir, d.left, d.to});
        vs.push_back(std::move(v));
    }
    return vs;
}

nlohmann::ordered_json ports_json(const std::vector<Port>& ports) {
    nlohmann::ordered_json out = nlohmann::ordered_json::array();
    for (const Port& p : ports) out.push_back({p.piece, p.vertex, p.dart});
    return out;
}

}  // namespace

std::string write_grammar_json(const Grammar& grammar) {
    nlohmann::ordered_json doc;
    doc["format"] = "sylva-layout-grammar";
    doc["version"] = 2;
    doc["directions"] = grammar.dirs.degrees;
    doc["opposite"] = grammar.dirs.opposite;
    doc["mean_length"] = grammar.dirs.mean_length;
    nlohmann::ordered_json label_length = nlohmann::ordered_json::array();
    for (const auto& [l, length] : grammar.dirs.label_length)
        label_length.push_back({l.dir, l.left, l.right, length});
    doc["label_length"] = std::move(label_length);
    nlohmann::ordered_json palette = nlohmann::ordered_json::array();
    for (std::uint32_t c : grammar.dirs.palette) palette.push_back(color_hex(c));
    doc["palette"] = palette;
    doc["example"] = {{"vertices", grammar.example_vertices},
                      {"polygons", grammar.example_polygons}};
    const HierarchyReport& h = grammar.hierarchy;
    doc["hierarchy"] = {{"graphs", h.graphs},
                        {"generations", h.generations},
                        {"open_graphs", h.open_graphs},
                        {"stopped_by", h.stopped_by},
                        {"vertex_limited", h.vertex_limited},
                        {"piece_limited", h.piece_limited},
                        {"decompositions_cut", h.decompositions_cut},
                        {"multi_boundary", h.multi_boundary},
                        {"dead_ends", h.dead_ends},
                        {"example_added", h.example_added}};
    doc["primitives"] = nlohmann::ordered_json::array();
    for (const AngleGraph& p : grammar.primitives) doc["primitives"].push_back(graph_json(p));
    doc["starters"] = nlohmann::ordered_json::array();
    for (const AngleGraph& s : grammar.starters) doc["starters"].push_back(graph_json(s));
    doc["rules"] = nlohmann::ordered_json::array();
    for (const Rule& r : grammar.rules) {
        nlohmann::ordered_json rule;
        rule["boundary"] = r.boundary;
        rule["left"] = graph_json(r.left);
        rule["left_ports"] = ports_json(r.left_ports);
        rule["right"] = nlohmann::ordered_json::array();
        for (const Piece& p : r.right) {
            if (p.floating)
                rule["right"].push_back({{"edge", {p.edge.dir, p.edge.left, p.edge.right}}});
            else
                rule["right"].push_back({{"graph", graph_json(p.graph)}});
        }
        rule["right_ports"] = ports_json(r.right_ports);
        doc["rules"].push_back(std::move(rule));
    }
    return doc.dump() + "\n";
}

namespace {

const nlohmann::json& member(const nlohmann::json& j, const std::string& name) {
    static const nlohmann::json kNull;
    if (!j.is_object()) return kNull;
    const auto it = j.find(name);
    return it == j.end() ? kNull : *it;
}

struct GrammarReader {
    const std::string& source;
    int directions = 0;
    int colors = 0;

    [[noreturn]] void fail(const std::string& key, const std::string& what) const {
        throw InputError(key + ": " + what, {source});
    }
    // Unsigned JSON numbers are compared as unsigned: 2^64 - 1 is not -1.
    int integer(const nlohmann::json& j, const std::string& key, int lo, int hi) const {
        bool ok = false;
        long long v = 0;
        if (j.is_number_unsigned()) {
            const std::uint64_t u = j.get<std::uint64_t>();
            ok = hi >= 0 && u <= static_cast<std::uint64_t>(hi) && static_cast<long long>(u) >= lo;
            v = ok ? static_cast<long long>(u) : 0;
        } else if (j.is_number_integer()) {
            v = j.get<std::int64_t>();
            ok = v >= lo && v <= hi;
        }
        if (!ok)
            fail(key, "expected an integer in " + std::to_string(lo) + ".." + std::to_string(hi));
        return static_cast<int>(v);
    }
    const nlohmann::json& array(const nlohmann::json& j, const std::string& key) const {
        if (!j.is_array()) fail(key, "expected an array");
        return j;
    }
    AngleGraph graph(const nlohmann::json& j, const std::string& key) const {
        AngleGraph g;
        const auto& vs = array(j, key);
        if (vs.size() > static_cast<std::size_t>(kMaxGraphVertices))
            fail(key, "more than " + std::to_string(kMaxGraphVertices) + " vertices");
        for (std::size_t v = 0; v < vs.size(); ++v) {
            const std::string vk = key + "[" + std::to_string(v) + "]";
            auto& ds = g.vertices.emplace_back();
            for (std::size_t i = 0; i < array(vs[v], vk).size(); ++i) {
                const std::string dk = vk + "[" + std::to_string(i) + "]";
                const auto& d = vs[v][i];
                if (!d.is_array() || d.size() != 3)
                    fail(dk, "expected [direction, colour, vertex]");
                ds.push_back({integer(d[0], dk, 0, directions - 1),
                              integer(d[1], dk, 0, colors - 1),
                              integer(d[2], dk, -1, static_cast<int>(vs.size()) - 1)});
            }
        }
        return g;
    }
};

}  // namespace

Grammar read_grammar_json(const std::string& text, const std::string& source) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::exception& e) {
        throw InputError("not JSON: " + std::string(e.what()), {source});
    }
    GrammarReader in{source};
    if (!doc.is_object() || member(doc, "format") != "sylva-layout-grammar")
        in.fail("format", "expected \"sylva-layout-grammar\"");
    if (member(doc, "version") != 2)
        in.fail("version", "expected 2 (derive the grammar again with this sylva)");
    Grammar g;
    const auto& dirs = in.array(member(doc, "directions"), "directions");
    if (dirs.empty() || dirs.size() > static_cast<std::size_t>(kMaxDirections))
        in.fail("directions", "expected 1 to " + std::to_string(kMaxDirections) + " angles");
    for (const auto& d : dirs) {
        if (!d.is_number() || d.get<double>() < 0 || d.get<double>() >= 360)
            in.fail("directions", "expected angles in [0, 360)");
        g.dirs.degrees.push_back(d.get<double>());
    }
    in.directions = static_cast<int>(g.dirs.degrees.size());
    for (std::size_t i = 1; i < g.dirs.degrees.size(); ++i)
        if (g.dirs.degrees[i] <= g.dirs.degrees[i - 1])
            in.fail("directions", "expected ascending angles");
    const auto& opp = in.array(member(doc, "opposite"), "opposite");
    if (opp.size() != dirs.size()) in.fail("opposite", "expected one entry per direction");
    for (const auto& o : opp)
        g.dirs.opposite.push_back(in.integer(o, "opposite", 0, in.directions - 1));
    for (int d = 0; d < in.directions; ++d)
        if (g.dirs.opposite[g.dirs.opposite[d]] != d ||
            std::abs(
                std::fmod(g.dirs.degrees[g.dirs.opposite[d]] - g.dirs.degrees[d] + 720.0, 360.0) -
                180.0) > 1e-3)
            in.fail("opposite", "direction " + std::to_string(d) +
                                    " and its opposite are not 180 degrees apart");
    const auto& lengths = in.array(member(doc, "mean_length"), "mean_length");
    if (lengths.size() != dirs.size()) in.fail("mean_length", "expected one entry per direction");
    for (const auto& l : lengths) {
        if (!l.is_number() || !(l.get<double>() > 0) || l.get<double>() > 1e8)
            in.fail("mean_length", "expected lengths > 0");
        g.dirs.mean_length.push_back(l.get<double>());
    }
    const auto& palette = in.array(member(doc, "palette"), "palette");
    if (palette.empty() || palette.size() > static_cast<std::size_t>(kMaxColors))
        in.fail("palette", "expected 1 to " + std::to_string(kMaxColors) + " colours");
    for (const auto& c : palette) {
        const std::string s = c.is_string() ? c.get<std::string>() : "";
        if (s.size() != 7 || s[0] != '#' ||
            s.find_first_not_of("0123456789abcdefABCDEF", 1) != std::string::npos)
            in.fail("palette", "expected colours \"#rrggbb\"");
        g.dirs.palette.push_back(static_cast<std::uint32_t>(std::stoul(s.substr(1), nullptr, 16)));
    }
    in.colors = g.dirs.colors();
    const auto& label_lengths = in.array(member(doc, "label_length"), "label_length");
    for (std::size_t i = 0; i < label_lengths.size(); ++i) {
        const std::string key = "label_length[" + std::to_string(i) + "]";
        const auto& e = label_lengths[i];
        if (!e.is_array() || e.size() != 4 || !e[3].is_number() || !(e[3].get<double>() > 0) ||
            e[3].get<double>() > 1e8)
            in.fail(key, "expected [direction, left, right, length > 0]");
        const Label l{in.integer(e[0], key, 0, in.directions - 1),
                      in.integer(e[1], key, 0, in.colors - 1),
                      in.integer(e[2], key, 0, in.colors - 1)};
        g.dirs.label_length[l] = e[3].get<double>();
    }
    const auto& example = member(doc, "example");
    g.example_vertices =
        in.integer(member(example, "vertices"), "example.vertices", 1, kMaxExampleVertices);
    g.example_polygons =
        in.integer(member(example, "polygons"), "example.polygons", 1, kMaxExamplePolygons);
    auto checked = [&](const nlohmann::json& j, const std::string& key, bool complete) {
        AngleGraph graph = in.graph(j, key);
        const Analysis a = analyze(graph, g.dirs);
        if (!a.planar) in.fail(key, "not a planar angle graph (" + a.why + ")");
        if (complete ? !a.complete : !a.single_boundary())
            in.fail(key,
                    complete ? "expected a complete graph" : "expected half-edges on one boundary");
        return graph;
    };
    const auto& hierarchy = member(doc, "hierarchy");
    HierarchyReport& h = g.hierarchy;
    auto count = [&](const char* name) {
        return in.integer(member(hierarchy, name), std::string("hierarchy.") + name, 0,
                          std::numeric_limits<int>::max());
    };
    h.graphs = count("graphs");
    h.generations = count("generations");
    h.open_graphs = count("open_graphs");
    h.vertex_limited = count("vertex_limited");
    h.piece_limited = count("piece_limited");
    h.decompositions_cut = count("decompositions_cut");
    h.multi_boundary = count("multi_boundary");
    h.dead_ends = count("dead_ends");
    const auto& stopped_by = member(hierarchy, "stopped_by");
    if (!stopped_by.is_string() ||
        !std::set<std::string>{"closed", "graphs", "seconds", "generations"}.count(
            stopped_by.get<std::string>()))
        in.fail("hierarchy.stopped_by",
                "expected \"closed\", \"graphs\", \"seconds\" or \"generations\"");
    h.stopped_by = stopped_by.get<std::string>();
    if (!member(hierarchy, "example_added").is_boolean())
        in.fail("hierarchy.example_added", "expected true or false");
    h.example_added = member(hierarchy, "example_added").get<bool>();
    const auto& primitives = in.array(member(doc, "primitives"), "primitives");
    for (std::size_t i = 0; i < primitives.size(); ++i)
        g.primitives.push_back(
            checked(primitives[i], "primitives[" + std::to_string(i) + "]", false));
    const auto& starters = in.array(member(doc, "starters"), "starters");
    for (std::size_t i = 0; i < starters.size(); ++i)
        g.starters.push_back(checked(starters[i], "starters[" + std::to_string(i) + "]", true));
    const auto& rules = in.array(member(doc, "rules"), "rules");
    for (std::size_t r = 0; r < rules.size(); ++r) {
        const std::string key = "rules[" + std::to_string(r) + "]";
        const auto& j = rules[r];
        if (!j.is_object()) in.fail(key, "expected an object");
        Rule rule;
        rule.left = checked(member(j, "left"), key + ".left", false);
        if (member(j, "boundary").is_string())
            rule.boundary = member(j, "boundary").get<std::string>();
        const auto& right = in.array(member(j, "right"), key + ".right");
        // Every piece has a port, so a side has at most as many pieces as ports.
        const std::size_t max_pieces = std::max<std::size_t>(1, rule.left.half_edges());
        if (right.empty() || right.size() > max_pieces)
            in.fail(key + ".right", "expected 1 to " + std::to_string(max_pieces) +
                                        " pieces (one per port at most)");
        for (std::size_t p = 0; p < right.size(); ++p) {
            const std::string pk = key + ".right[" + std::to_string(p) + "]";
            Piece piece;
            if (right[p].is_object() && right[p].contains("edge")) {
                const auto& e = right[p]["edge"];
                if (!e.is_array() || e.size() != 3)
                    in.fail(pk + ".edge", "expected [direction, left, right]");
                piece.floating = true;
                piece.edge = {in.integer(e[0], pk, 0, in.directions - 1),
                              in.integer(e[1], pk, 0, in.colors - 1),
                              in.integer(e[2], pk, 0, in.colors - 1)};
            } else if (right[p].is_object() && right[p].contains("graph")) {
                piece.graph = checked(right[p]["graph"], pk + ".graph", false);
            } else {
                in.fail(pk, "expected {\"edge\": ...} or {\"graph\": ...}");
            }
            rule.right.push_back(std::move(piece));
        }
        // Ports: both sides list the same boundary places, with equal labels.
        auto ports = [&](const char* name, const std::vector<Piece>& pieces) {
            std::vector<Port> out;
            const auto& ps = in.array(member(j, name), key + "." + name);
            for (std::size_t i = 0; i < ps.size(); ++i) {
                const std::string k = key + "." + name + "[" + std::to_string(i) + "]";
                if (!ps[i].is_array() || ps[i].size() != 3)
                    in.fail(k, "expected [piece, vertex, dart]");
                Port p;
                p.piece = in.integer(ps[i][0], k, 0, static_cast<int>(pieces.size()) - 1);
                const Piece& piece = pieces[p.piece];
                if (piece.floating) {
                    p.vertex = in.integer(ps[i][1], k, -1, -1);
                    p.dart = in.integer(ps[i][2], k, 0, 1);
                } else {
                    p.vertex = in.integer(ps[i][1], k, 0,
                                          static_cast<int>(piece.graph.vertices.size()) - 1);
                    p.dart =
                        in.integer(ps[i][2], k, 0,
                                   static_cast<int>(piece.graph.vertices[p.vertex].size()) - 1);
                    if (piece.graph.vertices[p.vertex][p.dart].to >= 0)
                        in.fail(k, "not a half-edge");
                }
                out.push_back(p);
            }
            return out;
        };
        const std::vector<Piece> left_pieces{{rule.left, false, {}}};
        rule.left_ports = ports("left_ports", left_pieces);
        rule.right_ports = ports("right_ports", rule.right);
        auto port_label = [&](const Piece& piece, const Port& p) {
            if (piece.floating) return p.dart == 0 ? piece.edge : reversed(piece.edge, g.dirs);
            return dart_label(piece.graph, p.vertex, p.dart);
        };
        std::size_t right_half_edges = 0;
        for (const Piece& p : rule.right) right_half_edges += p.floating ? 2 : p.graph.half_edges();
        if (rule.left_ports.size() != static_cast<std::size_t>(rule.left.half_edges()) ||
            rule.right_ports.size() != rule.left_ports.size() ||
            right_half_edges != rule.right_ports.size())
            in.fail(key, "the ports do not cover the boundary");
        std::set<std::tuple<int, int, int>> distinct;
        for (std::size_t i = 0; i < rule.left_ports.size(); ++i) {
            const Port& l = rule.left_ports[i];
            const Port& rp = rule.right_ports[i];
            if (port_label(left_pieces[0], l) != port_label(rule.right[rp.piece], rp))
                in.fail(key,
                        "port " + std::to_string(i) + " has different labels on the two sides");
            if (!distinct.insert({0, l.vertex, l.dart}).second ||
                !distinct.insert({1 + rp.piece, rp.vertex, rp.dart}).second)
                in.fail(key, "port " + std::to_string(i) + " repeats a half-edge");
        }
        g.rules.push_back(std::move(rule));
    }
    if (g.starters.empty()) in.fail("starters", "a grammar needs a starter rule");
    return g;
}

}  // namespace sylva::layout
