#include "impostor/impostor_fidelity.h"

#include <oneapi/tbb/parallel_for.h>

#include <algorithm>
#include <cstdlib>
#include <glm/common.hpp>
#include <glm/vec2.hpp>

#include "impostor/atlas_sampler.h"
#include "impostor/hemi_octahedral.h"

namespace sylva {
namespace {

struct Match {
    double iou = 0.0;
    double color = 0.0;
};

Match compare(const ViewImage& tree, const ViewImage& impostor) {
    std::size_t both = 0, either = 0;
    double color = 0.0;
    for (std::size_t p = 0; p < tree.alpha.size(); ++p) {
        const bool a = tree.alpha[p] >= 0.5f, b = impostor.alpha[p] >= 0.5f;
        either += a || b;
        if (!(a && b)) continue;
        ++both;
        for (int c = 0; c < 3; ++c)
            color += std::abs(static_cast<int>(srgb_byte(tree.color[p][c])) -
                              static_cast<int>(srgb_byte(impostor.color[p][c])));
    }
    return {either ? static_cast<double>(both) / static_cast<double>(either) : 1.0,
            both ? color / (3.0 * static_cast<double>(both)) : 0.0};
}

}  // namespace

std::vector<glm::vec3> between_directions(int views) {
    const glm::vec2 cells[8] = {{0.33f, 0.33f}, {6.67f, 0.33f}, {0.67f, 6.67f}, {6.33f, 6.33f},
                                {2.33f, 4.33f}, {3.67f, 3.67f}, {4.33f, 1.33f}, {1.67f, 2.67f}};
    std::vector<glm::vec3> out;
    const float last = static_cast<float>(std::max(views, 2) - 1);
    for (glm::vec2 c : cells) {
        // The same half-cell at the layout's scale: the cell scaled, its place inside kept.
        const glm::vec2 inside = c - glm::floor(c);
        const glm::vec2 cell = glm::min(glm::floor(c / 7.0f * last), glm::vec2(last - 1.0f));
        out.push_back(hemi_octahedral_decode((cell + inside) / last * 2.0f - 1.0f));
    }
    return out;
}

ImpostorFidelity impostor_fidelity(std::span<const BakePart> parts, const ImpostorAtlas& atlas) {
    const int size = atlas.tile;
    std::vector<glm::vec3> directions;
    for (int j = 0; j < atlas.views; ++j)
        for (int i = 0; i < atlas.views; ++i)
            directions.push_back(view_direction(i, j, atlas.views));
    const std::size_t captures = directions.size();
    for (const glm::vec3& d : between_directions(atlas.views)) directions.push_back(d);
    std::vector<Match> matches(directions.size());
    tbb::parallel_for(std::size_t{0}, directions.size(), [&](std::size_t k) {
        const ViewFrame frame = view_frame(directions[k]);
        matches[k] = compare(render_view(parts, frame, atlas.bounds, size, 2),
                             render_impostor(atlas, frame, size));
    });
    ImpostorFidelity out;
    for (std::size_t k = 0; k < matches.size(); ++k) {
        double& worst = k < captures ? out.capture_iou : out.between_iou;
        worst = std::min(worst, matches[k].iou);
        out.color = std::max(out.color, matches[k].color);
        if (k >= captures) out.between.push_back(matches[k].iou);
    }
    return out;
}

}  // namespace sylva
