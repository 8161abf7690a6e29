// The space colonization algorithm (Runions, Lane, Prusinkiewicz 2007; Liebemann 2017, 3.3-3.5):
// a tree graph grows from a root towards attraction points, which die once a node comes
// within the kill distance. Works on plain settings and points, knows no template.
#pragma once

#include <cstdint>
#include <functional>
#include <glm/vec3.hpp>
#include <span>
#include <vector>

#include "core/cancel.h"

namespace sylva {

// How each iteration finds a point's nearest node. Both give the same graph, bit for bit;
// brute force is the reference the benchmark and the tests compare against.
enum class NearestSearch { Grid, BruteForce };

// What a run did, counted the same on every machine for the same input: the basis of its
// cost (colonization_cost.h turns it into seconds and bytes) and of any limit on it, which
// a clock could not hold deterministically.
struct ColonizationWork {
    int iterations = 0;
    std::uint64_t nodes = 0;
    // Points and nodes passed in order (once per iteration each), and what a stalled node's
    // hand-over passes over (max_no_grow: the points near it, the nodes near each of its own).
    std::uint64_t scans = 0;
    std::uint64_t visits = 0;  // points and nodes whose distance a grid query takes
};

struct ColonizationSettings {
    float influence_radius = 1.5f;  // d_i: a point attracts only nodes this close
    float kill_distance = 0.4f;     // d_k: a point dies when a node is this close
    float step_size = 0.25f;        // D: distance of a new node from its parent
    glm::vec3 tropism{0.0f};        // T, added to the normalised mean direction (eq. 3.2)
    // When set, added to T at the growing node's position (tropism variation: a noise
    // field, so neighbouring growth bends alike).
    std::function<glm::vec3(const glm::vec3&)> tropism_field = nullptr;
    int max_iterations = 300;
    // The trunk grows straight up from the root, at least this high and until an
    // attraction point is within d_i of its top, before the points take over.
    float trunk_height = 0.0f;
    int max_degree = 0;   // max_grad: successors per node (0 = no limit)
    int max_depth = 0;    // max_Z: branch depth of eq. 3.5 (0 = no limit)
    int max_no_grow = 0;  // max_NG: iterations without a new successor before a node
                          // stops attracting (0 = never stops)
    // Weighted growth (3.5): step 2D at branch depth 0, D at max_depth (at depth 8 when
    // max_depth is 0), linear in between.
    bool weighted_growth = false;
    NearestSearch search = NearestSearch::Grid;
    // Obstacles: no node grows where this is true (a trunk stops below it, a branch's
    // growth into it is refused). Empty: nothing is blocked. Place no points there either.
    std::function<bool(const glm::vec3&)> blocked = nullptr;
    CancelFlag cancel = nullptr;  // polled every iteration; throws Cancelled
    // Called once per iteration with the finished fraction (rising, ends with 1): the larger
    // of the iterations used and the attraction points removed, each as a share of all.
    std::function<void(float)> progress = nullptr;
    // Called with the work so far (rising) after every iteration, and within one about
    // every four million visits; it may throw to stop the growth (how a cost limit holds
    // whatever an estimate said). Called on the growing thread.
    std::function<void(const ColonizationWork&)> work_done = nullptr;
};

struct ColonizationNode {
    glm::vec3 position{0.0f};
    int parent = -1;     // -1 for a root; parents always precede their children
    int depth = 0;       // branch depth Z (eq. 3.5), fixed when the node is made
    int successors = 0;  // number of children
    int no_grow = 0;     // iterations in a row without a new successor (NG counter)
    int born = 0;        // the iteration that made it, from 1 (0: root and trunk), so
                         // growth can be replayed step by step
};

enum class ColonizationStop { NoPointsLeft, NothingGrew, MaxIterations };

struct ColonizationGraph {
    std::vector<ColonizationNode> nodes;  // the roots first, in the order given
    std::vector<glm::vec3> remaining;     // attraction points still alive at the end
    int iterations = 0;
    // Growth refused because the new node would fall back onto the tree (within D/2 of
    // another node) or the pulls cancelled out: the back-and-forth growth of Liebemann 2017, 5.3.
    int oscillations = 0;
    ColonizationStop stop = ColonizationStop::NoPointsLeft;
    // What max_no_grow had to act on: passes in which a node that points attract grew
    // nothing (summed over nodes), and new nodes grown towards a point that a release
    // (max_no_grow reached) had handed on from another node (grid search only).
    int idle_attracted = 0;
    int moved_growth = 0;
    ColonizationWork work;  // what the run did (its cost)
};

// Grows a tree from `root` towards `points`. Throws Cancelled when the flag is set, and what
// settings.work_done throws.
// Precondition: 0 < kill_distance, 0 < step_size, kill_distance <= influence_radius.
ColonizationGraph colonize(std::span<const glm::vec3> points, const glm::vec3& root,
                           const ColonizationSettings& settings);

// A forest: one tree from each root (each grows its trunk in turn, then all compete for
// the same points). Precondition: roots is not empty, plus the above.
ColonizationGraph colonize(std::span<const glm::vec3> points, std::span<const glm::vec3> roots,
                           const ColonizationSettings& settings);

}  // namespace sylva
