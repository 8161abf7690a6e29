#include "impostor/impostor_layout.h"

#include <oneapi/tbb/blocked_range.h>
#include <oneapi/tbb/parallel_reduce.h>

#include <algorithm>
#include <cstdint>
#include <cstdio>

namespace sylva {

double thin_share(const ImpostorAtlas& atlas) {
    const Image8& a = atlas.albedo;
    const int tile = atlas.tile;
    if (tile <= 0 || a.channels != 4) return 0.0;
    auto covered = [&](int x, int y) {
        return a.pixels[(static_cast<std::size_t>(y) * static_cast<std::size_t>(a.width) +
                         static_cast<std::size_t>(x)) *
                            4 +
                        3] >= 128;
    };
    struct Count {
        std::size_t covered = 0, thin = 0;
    };
    const Count total = tbb::parallel_reduce(
        tbb::blocked_range<int>(0, a.height), Count{},
        [&](const tbb::blocked_range<int>& rows, Count c) {
            for (int y = rows.begin(); y < rows.end(); ++y) {
                const int ty = y - y % tile;
                for (int x = 0; x < a.width; ++x) {
                    if (!covered(x, y)) continue;
                    ++c.covered;
                    const int tx = x - x % tile;
                    // Transparent (or the tile's edge) within kThinPixels on one side.
                    auto open = [&](int dx, int dy) {
                        for (int k = 1; k <= kThinPixels; ++k) {
                            const int px = x + dx * k, py = y + dy * k;
                            if (px < tx || py < ty || px >= tx + tile || py >= ty + tile ||
                                !covered(px, py))
                                return true;
                        }
                        return false;
                    };
                    if ((open(-1, 0) && open(1, 0)) || (open(0, -1) && open(0, 1))) ++c.thin;
                }
            }
            return c;
        },
        [](Count l, Count r) {
            return Count{l.covered + r.covered, l.thin + r.thin};
        });
    return total.covered ? static_cast<double>(total.thin) / static_cast<double>(total.covered)
                         : 0.0;
}

ImpostorAtlas bake_impostor_auto(std::span<const BakePart> parts, ImpostorSettings settings) {
    const int views = std::clamp(settings.views, 2, 32);
    settings.views = views;
    settings.size = 128 * views;
    ImpostorAtlas atlas = bake_impostor(parts, settings);
    const double thin = thin_share(atlas);
    char line[200];
    if (thin >= kThinShareLimit) {
        settings.views = std::max(kThinViews, views);
        settings.size = std::max(kThinSize, 128 * settings.views);
        atlas = bake_impostor(parts, settings);
        std::snprintf(line, sizeof line,
                      "auto: %.1f%% of the silhouette is in parts at most %d px across in %d x %d "
                      "views (%.0f%% or more is thin), so %d x %d views at %d px",
                      thin * 100.0, 2 * kThinPixels - 1, views, views, kThinShareLimit * 100.0,
                      settings.views, settings.views, settings.size);
    } else {
        std::snprintf(line, sizeof line,
                      "auto: %.1f%% of the silhouette is in parts at most %d px across (under "
                      "%.0f%%), so %d x %d views at %d px",
                      thin * 100.0, 2 * kThinPixels - 1, kThinShareLimit * 100.0, views, views,
                      settings.size);
    }
    atlas.thin = thin;
    atlas.layout = line;
    return atlas;
}

}  // namespace sylva
