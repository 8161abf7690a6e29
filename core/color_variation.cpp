#include "core/color_variation.h"

#include <glm/common.hpp>

#include "core/noise.h"
#include "core/random.h"

namespace sylva {
namespace {

glm::vec3 shifted(const glm::vec3& color, double amount, Random& random) {
    auto draw = [&] { return 2.0 * random.uniform() - 1.0; };
    const double brightness = 1.0 + 0.3 * amount * draw();
    glm::dvec3 tint(1.0 + 0.15 * amount * draw(), 1.0 + 0.15 * amount * draw(),
                    1.0 + 0.15 * amount * draw());
    return glm::vec3(glm::clamp(glm::dvec3(color) * brightness * tint, 0.0, 1.0));
}

}  // namespace

PartColors varied_colors(const PartColors& base, double amount, std::uint64_t seed) {
    if (amount == 0.0) return base;
    Random trunk(derive_seed(seed, noise_stream::color));
    Random crown(derive_seed(derive_seed(seed, noise_stream::color), 1));
    Random leaves = crown;  // the same draws: crown and leaves shift together
    PartColors out = base;  // the palette of colour indices stays as the grammar chose it
    out.trunk = shifted(base.trunk, amount, trunk);
    out.crown = shifted(base.crown, amount, crown);
    out.leaves = shifted(base.leaves, amount, leaves);
    return out;
}

}  // namespace sylva
