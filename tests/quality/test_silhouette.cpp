#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "core/errors.h"
#include "quality/silhouette.h"
#include "shapes.h"

namespace sylva {
namespace {

using test::box;
using test::flipped;
using test::icosphere;

TEST(Silhouette, AMeshMatchesItself) {
    const Mesh sphere = icosphere(2);
    const Mesh leaf = box({0.8f, 0.8f, 0.8f}, {1.3f, 1.4f, 1.2f});
    const Mesh* parts[] = {&sphere, &leaf};
    const SilhouetteScore score = silhouette_iou(parts, parts);
    for (double v : score.views) EXPECT_EQ(v, 1.0);
    EXPECT_EQ(score.mean, 1.0);

    // Which way the triangles face, and how the parts are split, is not seen.
    const Mesh inside_out = flipped(sphere);
    Mesh together = sphere;
    test::append(together, leaf);
    const Mesh* others[] = {&together};
    const Mesh* flipped_parts[] = {&inside_out, &leaf};
    EXPECT_EQ(silhouette_iou(parts, others).mean, 1.0);
    EXPECT_EQ(silhouette_iou(parts, flipped_parts).mean, 1.0);
}

TEST(Silhouette, ShiftedCubeOverlapsByHand) {
    const Mesh cube = box({0, 0, 0}, {1, 1, 1});
    const Mesh shifted = box({0.5f, 0, 0}, {1.5f, 1, 1});
    const Mesh* reference[] = {&cube};
    const Mesh* candidate[] = {&shifted};
    const SilhouetteScore score = silhouette_iou(reference, candidate);
    // Seen along z (azimuths 0 and 180) and from above the shift is half the width:
    // overlap 1/2 over union 3/2.
    EXPECT_NEAR(score.views[0], 1.0 / 3.0, 0.01);
    EXPECT_NEAR(score.views[4], 1.0 / 3.0, 0.01);
    EXPECT_NEAR(score.views[8], 1.0 / 3.0, 0.01);
    // Seen along x, 15 degrees down, the cube is a rectangle cos 15 + sin 15 high and the
    // shift moves it sin(15) / 2 up or down.
    const double e = 15.0 * std::numbers::pi / 180.0;
    const double high = std::cos(e) + std::sin(e), moved = 0.5 * std::sin(e);
    EXPECT_NEAR(score.views[2], (high - moved) / (high + moved), 0.01);
    EXPECT_NEAR(score.views[6], (high - moved) / (high + moved), 0.01);
    for (double v : score.views) EXPECT_LT(v, 0.99);
}

TEST(Silhouette, SmallerMeshGivesTheAreaRatio) {
    const Mesh large = box({-1, -1, -1}, {1, 1, 1});
    const Mesh small = box({-0.5f, -0.5f, -0.5f}, {0.5f, 0.5f, 0.5f});
    const Mesh* reference[] = {&large};
    const Mesh* candidate[] = {&small};
    const SilhouetteScore score = silhouette_iou(reference, candidate);
    for (double v : score.views) EXPECT_NEAR(v, 0.25, 0.01);
    EXPECT_NEAR(score.mean, 0.25, 0.01);
    // The same figure at another resolution, within its coarser pixels.
    EXPECT_NEAR(silhouette_iou(reference, candidate, 64).mean, 0.25, 0.03);
}

TEST(Silhouette, NothingAgainstSomething) {
    const Mesh cube = box({0, 0, 0}, {1, 1, 1});
    const Mesh empty;
    const Mesh* reference[] = {&cube};
    const Mesh* candidate[] = {&empty};
    EXPECT_EQ(silhouette_iou(reference, candidate).mean, 0.0);
    EXPECT_THROW(silhouette_iou(candidate, reference), InputError);
    // Far beyond the frame: not seen, and no pixel outside the image is touched.
    const Mesh far = box({1e30f, 1e30f, 1e30f}, {2e30f, 2e30f, 2e30f});
    const Mesh* away[] = {&far};
    EXPECT_EQ(silhouette_iou(reference, away).mean, 0.0);
}

TEST(Silhouette, FrameHoldsTheReference) {
    const Mesh cube = box({0, 0, 0}, {2, 2, 2});
    const Mesh* meshes[] = {&cube};
    const SilhouetteFrame frame = silhouette_frame(meshes);
    EXPECT_NEAR(frame.center.x, 1.0, 1e-12);
    EXPECT_NEAR(frame.radius, 1.25 * std::sqrt(3.0), 1e-9);
    const Silhouettes images = rasterize_silhouettes(meshes, frame, 32);
    for (const auto& view : images.views) {
        ASSERT_EQ(view.size(), 32u * 32u);
        // The border rows and columns lie beyond the cube's outline.
        for (int i = 0; i < 32; ++i) {
            EXPECT_EQ(view[i], 0);
            EXPECT_EQ(view[31 * 32 + i], 0);
            EXPECT_EQ(view[i * 32], 0);
            EXPECT_EQ(view[i * 32 + 31], 0);
        }
    }
}

}  // namespace
}  // namespace sylva
