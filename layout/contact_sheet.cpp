#include "layout/contact_sheet.h"

#include <algorithm>
#include <cstdio>
#include <glm/common.hpp>

namespace sylva::layout {

namespace {

std::string escaped(const std::string& s) {
    std::string out;
    for (char c : s) {
        if (c == '<')
            out += "&lt;";
        else if (c == '>')
            out += "&gt;";
        else if (c == '&')
            out += "&amp;";
        else
            out += c;
    }
    return out;
}

}  // namespace

std::string write_sheet_svg(const std::vector<SheetItem>& items, int columns, double cell,
                            bool same_scale) {
    columns = std::max(1, columns);
    const int rows = static_cast<int>((items.size() + columns - 1) / columns);
    double extent = 1e-9;
    for (const SheetItem& it : items) {
        glm::dvec2 lo(1e300), hi(-1e300);
        for (const glm::dvec2& v : it.mesh->vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
        if (!it.mesh->vertices.empty()) extent = std::max({extent, hi.x - lo.x, hi.y - lo.y});
    }
    const double pad = 10.0, caption = 18.0;
    double scale = (cell - 2 * pad) / extent;
    char buf[200];
    std::snprintf(buf, sizeof buf,
                  "<svg xmlns=\"http://www.w3.org/2000/svg\" width=\"%.0f\" height=\"%.0f\" "
                  "font-family=\"sans-serif\" font-size=\"12\">\n"
                  "<rect width=\"100%%\" height=\"100%%\" fill=\"#ffffff\"/>\n",
                  columns * cell, rows * (cell + caption));
    std::string out = buf;
    for (std::size_t k = 0; k < items.size(); ++k) {
        const PolygonMesh& mesh = *items[k].mesh;
        const double x0 = static_cast<double>(k % columns) * cell;
        const double y0 = static_cast<double>(k / columns) * (cell + caption);
        glm::dvec2 lo(1e300), hi(-1e300);
        for (const glm::dvec2& v : mesh.vertices) lo = glm::min(lo, v), hi = glm::max(hi, v);
        if (mesh.vertices.empty()) lo = hi = glm::dvec2(0);
        if (!same_scale) scale = (cell - 2 * pad) / std::max({hi.x - lo.x, hi.y - lo.y, 1e-9});
        std::snprintf(
            buf, sizeof buf,
            "<rect x=\"%.1f\" y=\"%.1f\" width=\"%.1f\" height=\"%.1f\" fill=\"#f7f7f2\"/>\n",
            x0 + 2, y0 + 2, cell - 4, cell - 4);
        out += buf;
        for (const Polygon& p : mesh.polygons) {
            out += "<polygon points=\"";
            for (int i : p.vertices) {
                const glm::dvec2 v = mesh.vertices[i];
                std::snprintf(buf, sizeof buf, "%.1f,%.1f ", x0 + pad + (v.x - lo.x) * scale,
                              y0 + cell - pad - (v.y - lo.y) * scale);
                out += buf;
            }
            out.back() = '"';
            out +=
                " fill=\"" + color_hex(p.color) + "\" stroke=\"#333333\" stroke-width=\"0.6\"/>\n";
        }
        std::snprintf(buf, sizeof buf, "<text x=\"%.1f\" y=\"%.1f\">", x0 + pad, y0 + cell + 13);
        out += buf + escaped(items[k].caption) + "</text>\n";
    }
    return out + "</svg>\n";
}

}  // namespace sylva::layout
