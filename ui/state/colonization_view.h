// What the studio draws beside a space colonization tree (Liebemann 2017, chapter 3): the envelope
// as a wire cage, the attraction points the growth started from, and the skeleton as it
// stood after a given growth step. Headless: plain points in, line pairs out, so tests check
// them without a window.
#pragma once

#include <glm/vec3.hpp>
#include <vector>

#include "colonization/envelope.h"
#include "core/skeleton.h"
#include "core/tree_template.h"

namespace sylva::studio {

// True when the template grows by space colonization: the rules editor does not apply, the
// envelope, points and replay do.
bool grows_by_colonization(const TreeTemplate& tree_template);

// Line pairs tracing the envelope's boundary: `meridians` lines of longitude from bottom to
// top and lines of latitude at `rings` even steps of height (the flat rim of a cone, cylinder
// or hemisphere included, the poles and the cone's apex left out), each curve cut into
// `steps` straight pieces. Every point lies on the boundary. Precondition: meridians >= 1,
// rings >= 1, steps >= 1.
std::vector<glm::vec3> envelope_wire(const Envelope& envelope, int meridians = 12, int rings = 6,
                                     int steps = 48);

// The wire of the envelope the template's parameters set (colonization_growth's
// template_envelope).
std::vector<glm::vec3> template_envelope_wire(const TreeTemplate& tree_template);

// The attraction points the template's growth starts from: its envelope, count,
// distribution and seed, as colonization_growth places them.
std::vector<glm::vec3> template_attraction_points(const TreeTemplate& tree_template);

// The attraction points still alive after growth step `step` (0: after the trunk): the
// growth run again, stopped there. Costs one growth up to that step (milliseconds for the
// built-in templates, some 0.2 s at 100,000 points). Throws what the growth throws.
std::vector<glm::vec3> attraction_points_alive(const TreeTemplate& tree_template, int step);

// The last growth step any segment records: 0 for an L-system skeleton or a bare trunk.
int last_iteration(const Skeleton& skeleton);

// Line pairs of the segments made at or before growth step `iteration` (Segment::iteration):
// the skeleton as growth left it after that step. Parents are made before their children,
// so the lines form a tree rooted where the whole one is.
std::vector<glm::vec3> replay_lines(const Skeleton& skeleton, int iteration);

}  // namespace sylva::studio
