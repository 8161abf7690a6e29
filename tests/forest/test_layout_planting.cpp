// sylva forest --layout: a plan from `sylva layout generate` (tests/forest/data/farm_plan.json,
// generated from farm.mesh beside it with --seed 2) planted by class: forest stands, orchard
// rows, meadow solitaires, nothing on paths.
#include <gtest/gtest.h>
#include <unistd.h>

#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <glm/geometric.hpp>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>

#include "core/errors.h"
#include "forest/forest.h"
#include "forest/ground.h"
#include "forest/orchard.h"
#include "tests/helpers.h"
#include "tree/template_library.h"

namespace {

namespace fs = std::filesystem;
using namespace sylva;
using namespace sylva::forest;

// The checked-in plan, turned 30 degrees (so rows are not axis-aligned) and scaled to meters.
Ground farm_plan() {
    Ground ground = load_ground(fs::path(SYLVA_SOURCE_DIR) / "tests/forest/data/farm_plan.json");
    const double a = std::acos(-1.0) / 6.0;
    for (GroundPolygon& polygon : ground.polygons)
        for (glm::dvec2& p : polygon.points)
            p = {std::cos(a) * p.x - std::sin(a) * p.y, std::sin(a) * p.x + std::cos(a) * p.y};
    scale_ground(ground, 4.0);
    return ground;
}

ForestSettings farm_settings() {
    ForestSettings s;
    s.ground = farm_plan();
    s.layout = LayoutPlanting{};
    s.species = {{load_template("spruce"), 1.0},
                 {load_template("maple"), 1.0, std::string(kOrchardClass)}};
    s.variants = 2;
    s.spacing = 4.0;
    s.seed = 7;
    s.finish.budget.total = 200;
    return s;
}

double edge_distance(const GroundPolygon& polygon, glm::dvec2 p) {
    double d = 1e300;
    for (std::size_t i = 0; i < polygon.points.size(); ++i) {
        const glm::dvec2 a = polygon.points[i];
        const glm::dvec2 b = polygon.points[(i + 1) % polygon.points.size()];
        const double t = std::clamp(glm::dot(p - a, b - a) / glm::dot(b - a, b - a), 0.0, 1.0);
        d = std::min(d, glm::distance(p, a + t * (b - a)));
    }
    return d;
}

// Distance of x / step from the nearest whole number, in units of step.
double off_lattice(double x, double step) {
    return std::abs(x / step - std::round(x / step));
}

TEST(LayoutPlanting, TheFarmPlanHasEveryClass) {
    std::map<std::string, int> classes;
    for (const GroundPolygon& polygon : farm_plan().polygons) ++classes[polygon.cls];
    EXPECT_GT(classes["forest"], 0);
    EXPECT_GT(classes["orchard"], 1);
    EXPECT_GT(classes["meadow"], 0);
    EXPECT_GT(classes["path"], 0);
}

TEST(LayoutPlanting, ForestAndOrchardTreesOnlyAndOrchardsInRows) {
    const ForestSettings s = farm_settings();
    const ForestPlan plan = plan_forest(s);
    const OrchardSettings& o = s.layout->orchard;
    std::map<std::string, std::size_t> per_class;
    std::map<std::size_t, std::vector<glm::dvec2>> per_orchard;  // polygon -> its trees
    for (const Placement& t : plan.placements) {
        const glm::dvec2 p(t.position.x, -t.position.z);
        ++per_class[t.cls];
        std::vector<std::size_t> in;
        for (std::size_t i = 0; i < s.ground.polygons.size(); ++i)
            if (contains(s.ground.polygons[i], p)) in.push_back(i);
        ASSERT_EQ(in.size(), 1u) << "a tree at " << p.x << ", " << p.y;
        const GroundPolygon& polygon = s.ground.polygons[in[0]];
        EXPECT_EQ(polygon.cls, t.cls);
        EXPECT_TRUE(t.cls == kForestClass || t.cls == kOrchardClass) << t.cls;
        EXPECT_EQ(s.species[t.species].cls, t.cls);
        if (t.cls == kOrchardClass) {
            EXPECT_GE(edge_distance(polygon, p), o.margin - 1e-9);
            per_orchard[in[0]].push_back(p);
        }
    }
    EXPECT_GT(per_class["forest"], 20u);
    EXPECT_GT(per_class["orchard"], 20u);
    EXPECT_EQ(per_class.size(), 2u);

    // Each orchard's trees on a lattice: rows along its longest edge, tree_spacing apart in a
    // row and row_spacing between rows (offsets from the first tree are whole multiples).
    for (const auto& [index, trees] : per_orchard) {
        const GroundPolygon& polygon = s.ground.polygons[index];
        glm::dvec2 longest(0.0);
        for (std::size_t i = 0; i < polygon.points.size(); ++i) {
            const glm::dvec2 e =
                polygon.points[(i + 1) % polygon.points.size()] - polygon.points[i];
            if (glm::length(e) > glm::length(longest) + 1e-9) longest = e;
        }
        const glm::dvec2 u = glm::normalize(longest), v(-u.y, u.x);
        EXPECT_NEAR(std::abs(glm::dot(row_direction(polygon), u)), 1.0, 1e-12);
        std::map<long, int> rows;
        for (glm::dvec2 p : trees) {
            EXPECT_LT(off_lattice(glm::dot(p - trees[0], u), o.tree_spacing), 1e-6);
            EXPECT_LT(off_lattice(glm::dot(p - trees[0], v), o.row_spacing), 1e-6);
            ++rows[std::lround(glm::dot(p - trees[0], v) / o.row_spacing)];
        }
        // A plot at least 40 m x 40 m after scaling holds several rows of several trees.
        EXPECT_GE(rows.size(), 3u) << "orchard polygon " << index;
        for (const auto& [row, count] : rows) EXPECT_GE(count, 3) << "row " << row;
    }
    EXPECT_GE(per_orchard.size(), 2u);
}

TEST(LayoutPlanting, MeadowsGetSolitaryTreesOnlyWhenAsked) {
    ForestSettings s = farm_settings();
    s.layout->meadow_density = 25.0;
    const ForestPlan plan = plan_forest(s);
    std::vector<glm::dvec2> meadow;
    for (const Placement& t : plan.placements) {
        if (t.cls != kMeadowClass) continue;
        const glm::dvec2 p(t.position.x, -t.position.z);
        meadow.push_back(p);
        for (const GroundPolygon& polygon : s.ground.polygons)
            if (contains(polygon, p)) {
                EXPECT_EQ(polygon.cls, kMeadowClass);
            }
        EXPECT_EQ(s.species[t.species].cls, kForestClass);
    }
    EXPECT_GE(meadow.size(), 1u);
    for (std::size_t i = 0; i < meadow.size(); ++i)
        for (std::size_t j = i + 1; j < meadow.size(); ++j)
            EXPECT_GE(glm::distance(meadow[i], meadow[j]), 3.0 * s.spacing);
    // The same plan without --meadow-density plants no meadow tree and the same others.
    const ForestPlan bare = plan_forest(farm_settings());
    EXPECT_EQ(bare.placements.size(), plan.placements.size() - meadow.size());
}

TEST(LayoutPlanting, GroundModePlantsOnlyForestsAndSkipsUnusedSpecies) {
    ForestSettings s = farm_settings();
    s.layout.reset();  // --ground: orchards are holes
    const ForestPlan plan = plan_forest(s);
    for (const Placement& t : plan.placements) EXPECT_EQ(t.cls, kForestClass);
    EXPECT_EQ(plan.variants.size(), 2u);  // no maple variants without orchard planting
    // A plan with nothing to plant says so.
    ForestSettings paths = farm_settings();
    std::erase_if(paths.ground.polygons, [](const GroundPolygon& p) { return p.cls != "path"; });
    EXPECT_THROW(plan_forest(paths), InputError);
    ForestSettings bad = farm_settings();
    bad.layout->orchard.row_spacing = 0.0;
    EXPECT_THROW(plan_forest(bad), InputError);
}

class LayoutScene : public ::testing::Test {
  protected:
    void SetUp() override {
        dir_ = fs::temp_directory_path() / ("sylva_layout_forest_" + std::to_string(::getpid()));
        fs::create_directories(dir_ / "again");
    }
    void TearDown() override { fs::remove_all(dir_); }
    fs::path dir_;
};

TEST_F(LayoutScene, PlacementListsRecordClassesAndRepeat) {
    const ForestSettings s = farm_settings();
    const ForestResult result = plant_forest(s, dir_ / "farm.glb");
    const nlohmann::json doc =
        nlohmann::json::parse(test::read_file(placements_json_path(dir_ / "farm.glb")));
    ASSERT_EQ(doc["placements"].size(), result.plan.placements.size());
    for (std::size_t i = 0; i < result.plan.placements.size(); ++i)
        EXPECT_EQ(doc["placements"][i]["class"], result.plan.placements[i].cls);
    EXPECT_EQ(doc["species"][1]["class"], "orchard");
    std::istringstream csv(test::read_file(placements_csv_path(dir_ / "farm.glb")));
    std::string line;
    std::getline(csv, line);
    std::size_t rows = 0;
    while (std::getline(csv, line)) {
        ASSERT_LT(rows, result.plan.placements.size());
        const std::string cls = line.substr(line.rfind(',') + 1);
        EXPECT_EQ(cls, result.plan.placements[rows++].cls);
    }
    EXPECT_EQ(rows, result.plan.placements.size());

    plant_forest(s, dir_ / "again" / "farm.glb");
    for (const char* name : {"farm.glb", "farm.placements.csv", "farm.placements.json"})
        EXPECT_EQ(test::read_file(dir_ / name), test::read_file(dir_ / "again" / name)) << name;
}

// An orchard spacing of 1e-9 m walked 1e+20 lattice points (sylva forest --layout PLAN
// --tree-spacing 1e-9 hung): the whole forest's trees are estimated together and refused
// with the figure before any is placed.
TEST(LayoutPlanting, AnOrchardPastTheTreeLimitIsRefusedBeforePlanting) {
    ForestSettings s = farm_settings();
    s.layout->orchard.tree_spacing = 1e-9;
    EXPECT_GT(estimated_trees(s), kMaxForestTrees);
    const auto start = std::chrono::steady_clock::now();
    std::string message;
    try {
        plan_forest(s);
    } catch (const InputError& e) {
        message = e.what();
    }
    EXPECT_LT(std::chrono::steady_clock::now() - start, std::chrono::seconds(2));
    EXPECT_NE(message.find("e+"), std::string::npos) << message;
    EXPECT_NE(message.find("limit is 1000000"), std::string::npos) << message;
    for (const GroundPolygon& polygon : s.ground.polygons) {
        if (polygon.cls != kOrchardClass) continue;
        EXPECT_THROW(orchard_rows(polygon, s.ground, s.layout->orchard), InputError);
    }
}

// The estimate is an upper bound: every tree planted was counted.
TEST(LayoutPlanting, TheTreeEstimateBoundsThePlantedTrees) {
    ForestSettings s = farm_settings();
    s.layout->meadow_density = 4.0;
    const ForestPlan plan = plan_forest(s);
    EXPECT_GE(estimated_trees(s), static_cast<double>(plan.placements.size()));
    // The job counts every variant: four times the variants, about four times the time
    // (planting and writing the scene cost a little besides).
    const Cost two = estimate_forest_cost(s);
    s.variants = 8;
    EXPECT_GT(estimate_forest_cost(s).seconds, 3.0 * two.seconds);
}

}  // namespace
