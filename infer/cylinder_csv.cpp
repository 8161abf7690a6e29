#include "infer/cylinder_csv.h"

#include <algorithm>
#include <array>
#include <charconv>
#include <cmath>
#include <glm/geometric.hpp>
#include <map>
#include <optional>
#include <unordered_map>
#include <vector>

#include "core/errors.h"

namespace sylva {
namespace {

enum Column {
    kRadius,
    kLength,
    kStartX,
    kStartY,
    kStartZ,
    kAxisX,
    kAxisY,
    kAxisZ,
    kEndX,
    kEndY,
    kEndZ,
    kParent,
    kId,
    kExtension,
    kOrder,
    kColumns
};

// Column names as tools spell them, after lower-casing, dropping a unit in parentheses
// and every ' ', '_', '-' and '.'.
const std::map<std::string, Column>& column_names() {
    static const std::map<std::string, Column> names = {
        {"radius", kRadius},
        {"rad", kRadius},
        {"r", kRadius},
        {"unmodradius", kRadius},
        {"length", kLength},
        {"len", kLength},
        {"startx", kStartX},
        {"starty", kStartY},
        {"startz", kStartZ},
        {"startpointx", kStartX},
        {"startpointy", kStartY},
        {"startpointz", kStartZ},
        {"x1", kStartX},
        {"y1", kStartY},
        {"z1", kStartZ},
        {"axisx", kAxisX},
        {"axisy", kAxisY},
        {"axisz", kAxisZ},
        {"axisdirectionx", kAxisX},
        {"axisdirectiony", kAxisY},
        {"axisdirectionz", kAxisZ},
        {"directionx", kAxisX},
        {"directiony", kAxisY},
        {"directionz", kAxisZ},
        {"dx", kAxisX},
        {"dy", kAxisY},
        {"dz", kAxisZ},
        {"endx", kEndX},
        {"endy", kEndY},
        {"endz", kEndZ},
        {"endpointx", kEndX},
        {"endpointy", kEndY},
        {"endpointz", kEndZ},
        {"x2", kEndX},
        {"y2", kEndY},
        {"z2", kEndZ},
        {"parent", kParent},
        {"parentid", kParent},
        {"parentcylinder", kParent},
        {"id", kId},
        {"cylinderid", kId},
        {"cylid", kId},
        {"cylinder", kId},
        {"extension", kExtension},
        {"extensionid", kExtension},
        {"next", kExtension},
        {"branchorder", kOrder},
        {"order", kOrder},
    };
    return names;
}

std::string normalized(std::string_view name) {
    std::string out;
    bool in_unit = false;
    for (char c : name) {
        if (c == '(' || c == '[') in_unit = true;
        if (!in_unit && c != ' ' && c != '_' && c != '-' && c != '.' && c != '"' && c != '\'')
            out.push_back(static_cast<char>(std::tolower(static_cast<unsigned char>(c))));
        if (c == ')' || c == ']') in_unit = false;
    }
    return out;
}

std::vector<std::string_view> split(std::string_view line, char delimiter) {
    std::vector<std::string_view> cells;
    std::size_t start = 0;
    while (true) {
        if (delimiter == ' ') {
            while (start < line.size() && (line[start] == ' ' || line[start] == '\t')) ++start;
            if (start >= line.size()) break;
        }
        std::size_t end = line.find(delimiter, start);
        if (delimiter == ' ') end = std::min(end, line.find('\t', start));
        if (end == std::string_view::npos) end = line.size();
        std::string_view cell = line.substr(start, end - start);
        while (!cell.empty() && std::isspace(static_cast<unsigned char>(cell.front())))
            cell.remove_prefix(1);
        while (!cell.empty() && std::isspace(static_cast<unsigned char>(cell.back())))
            cell.remove_suffix(1);
        cells.push_back(cell);
        if (end >= line.size()) break;
        start = end + 1;
    }
    return cells;
}

std::optional<double> parse_number(std::string_view cell) {
    if (!cell.empty() && cell.front() == '+') cell.remove_prefix(1);
    double v = 0.0;
    auto [end, error] = std::from_chars(cell.data(), cell.data() + cell.size(), v);
    if (error != std::errc() || end != cell.data() + cell.size() || cell.empty())
        return std::nullopt;
    return v;
}

char pick_delimiter(std::string_view line) {
    const std::array<char, 3> candidates = {'\t', ',', ';'};
    char best = ' ';
    std::size_t most = 0;
    for (char c : candidates) {
        std::size_t n = static_cast<std::size_t>(std::count(line.begin(), line.end(), c));
        if (n > most) {
            most = n;
            best = c;
        }
    }
    return best;
}

glm::vec3 to_sylva(glm::dvec3 p, UpAxis up) {
    if (up == UpAxis::Z) p = {p.x, p.z, -p.y};
    return glm::vec3(p);
}

}  // namespace

ExampleTree parse_cylinder_csv(std::string_view text, const std::string& source, UpAxis up) {
    // Lines with their 1-based numbers, blank lines and '#' comments left out.
    std::vector<std::pair<int, std::string_view>> lines;
    int number = 0;
    for (std::size_t at = 0; at < text.size();) {
        std::size_t end = text.find('\n', at);
        if (end == std::string_view::npos) end = text.size();
        std::string_view line = text.substr(at, end - at);
        if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
        ++number;
        at = end + 1;
        std::string_view trimmed = line;
        while (!trimmed.empty() && std::isspace(static_cast<unsigned char>(trimmed.front())))
            trimmed.remove_prefix(1);
        if (trimmed.empty() || trimmed.front() == '#') continue;
        lines.emplace_back(number, line);
        if (lines.size() > kMaxExampleSegments + 1)
            throw InputError("more than " + std::to_string(kMaxExampleSegments) +
                                 " cylinders; infer takes at most that many",
                             {source, number, 0});
    }
    if (lines.empty()) throw InputError("the file has no cylinders", {source, 0, 0});
    const char delimiter = pick_delimiter(lines.front().second);

    std::array<int, kColumns> column;
    column.fill(-1);
    std::size_t first_row = 0;
    const std::vector<std::string_view> head = split(lines.front().second, delimiter);
    const bool has_header = !head.empty() && !parse_number(head.front());
    if (has_header) {
        first_row = 1;
        for (std::size_t c = 0; c < head.size(); ++c) {
            auto it = column_names().find(normalized(head[c]));
            if (it != column_names().end() && column[it->second] < 0)
                column[it->second] = static_cast<int>(c);
        }
    } else {
        // TreeQSM's order.
        const Column order[] = {kRadius, kLength, kStartX, kStartY, kStartZ,
                                kAxisX,  kAxisY,  kAxisZ,  kParent, kExtension};
        for (int c = 0; c < 10; ++c) column[order[c]] = c;
        column[kOrder] = 11;
    }
    auto need = [&](Column c, const char* name) {
        if (column[c] < 0)
            throw InputError(std::string("the cylinder table has no ") + name + " column",
                             {source, lines.front().first, 0});
    };
    need(kStartX, "start_x");
    need(kStartY, "start_y");
    need(kStartZ, "start_z");
    need(kParent, "parent");
    const bool by_end = column[kEndX] >= 0 && column[kEndY] >= 0 && column[kEndZ] >= 0;
    if (!by_end) {
        need(kAxisX, "axis_x (or end_x)");
        need(kAxisY, "axis_y");
        need(kAxisZ, "axis_z");
        need(kLength, "length");
    }

    struct Row {
        int line;
        double id;
        double parent;
        double extension;
        Segment segment;
    };
    std::vector<Row> rows;
    rows.reserve(lines.size() - first_row);
    for (std::size_t r = first_row; r < lines.size(); ++r) {
        // Copies, not a structured binding: clang 14 cannot capture those in the lambda below.
        const auto line_number = lines[r].first;
        const auto line = lines[r].second;
        const std::vector<std::string_view> cells = split(line, delimiter);
        auto cell = [&](Column c, double fallback) -> double {
            if (column[c] < 0) return fallback;
            const std::size_t i = static_cast<std::size_t>(column[c]);
            if (i >= cells.size()) {
                if (c == kExtension || c == kOrder || c == kRadius) return fallback;
                throw InputError("the row has " + std::to_string(cells.size()) +
                                     " columns; column " + std::to_string(i + 1) + " is missing",
                                 {source, line_number, 0}, std::string(line));
            }
            std::optional<double> v = parse_number(cells[i]);
            if (!v || !std::isfinite(*v))
                throw InputError("column " + std::to_string(i + 1) + " ('" +
                                     std::string(cells[i].substr(0, 40)) +
                                     "') is not a finite number",
                                 {source, line_number, 0}, std::string(line));
            return *v;
        };
        Row row;
        row.line = line_number;
        row.id = cell(kId, static_cast<double>(rows.size() + 1));
        row.parent = cell(kParent, 0.0);
        row.extension = cell(kExtension, 0.0);
        const glm::dvec3 start(cell(kStartX, 0), cell(kStartY, 0), cell(kStartZ, 0));
        glm::dvec3 end;
        if (by_end) {
            end = glm::dvec3(cell(kEndX, 0), cell(kEndY, 0), cell(kEndZ, 0));
        } else {
            glm::dvec3 axis(cell(kAxisX, 0), cell(kAxisY, 0), cell(kAxisZ, 0));
            const double length = cell(kLength, 0);
            const double norm = glm::length(axis);
            if (!(norm > 0.0) || !(length > 0.0))
                throw InputError("the cylinder has no length (zero axis or length)",
                                 {source, line_number, 0}, std::string(line));
            end = start + axis / norm * length;
        }
        row.segment.a = to_sylva(start, up);
        row.segment.b = to_sylva(end, up);
        const double radius = cell(kRadius, 0.0);
        row.segment.ra = row.segment.rb = static_cast<float>(std::clamp(radius, 0.0, 1e6));
        const double order = cell(kOrder, -1.0);
        row.segment.depth = order >= 0.0 && order < 1e6 ? static_cast<int>(order) : -1;
        rows.push_back(row);
    }

    // Parents name ids (an id column) or rows counted from 1; 0 or a negative number is none.
    std::unordered_map<double, int> index_of;
    const bool has_ids = column[kId] >= 0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        if (has_ids && !index_of.emplace(rows[i].id, static_cast<int>(i)).second)
            throw InputError("id " + std::to_string(rows[i].id) + " is used by an earlier row",
                             {source, rows[i].line, 0});
    }
    auto find = [&](double reference) -> int {
        if (has_ids) {
            auto it = index_of.find(reference);
            return it == index_of.end() ? -2 : it->second;
        }
        if (reference != std::floor(reference) || reference > static_cast<double>(rows.size()))
            return -2;
        return static_cast<int>(reference) - 1;
    };
    ExampleTree tree;
    tree.format = "cylinder csv";
    for (std::size_t i = 0; i < rows.size(); ++i) {
        Segment s = rows[i].segment;
        const bool none =
            has_ids ? (rows[i].parent < 0 || !index_of.count(rows[i].parent)) && rows[i].parent <= 0
                    : rows[i].parent <= 0;
        if (none) {
            s.parent = -1;
        } else {
            s.parent = find(rows[i].parent);
            if (s.parent < 0)
                throw InputError("parent " + std::to_string(rows[i].parent) + " is no row",
                                 {source, rows[i].line, 0});
        }
        tree.skeleton.segments.push_back(s);
        tree.places.push_back("row " + std::to_string(i + 1) + " (line " +
                              std::to_string(rows[i].line) + ")");
        const int next = rows[i].extension > 0 ? find(rows[i].extension) : -1;
        tree.continuation.push_back(next >= 0 ? next : -1);
    }
    if (up == UpAxis::Z) tree.notes.push_back("read Z-up: the file's Z is the height");
    finish_example_tree(tree, source);
    return tree;
}

}  // namespace sylva
