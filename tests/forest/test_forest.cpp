// sylva forest: the ground, Poisson disk spacing, species stands, and the scene read back
// with tinygltf against the placement list.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <tiny_gltf.h>
#include <unistd.h>

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
#include "forest/poisson_disk.h"
#include "forest/species_file.h"
#include "tests/helpers.h"
#include "tree/parameters.h"
#include "tree/template_library.h"

namespace {

namespace fs = std::filesystem;
using namespace sylva;
using namespace sylva::forest;

double min_pair_distance(const std::vector<glm::dvec2>& points) {
    double d = 1e30;
    for (std::size_t i = 0; i < points.size(); ++i)
        for (std::size_t j = i + 1; j < points.size(); ++j)
            d = std::min(d, glm::distance(points[i], points[j]));
    return d;
}

std::vector<glm::dvec2> map_points(const ForestPlan& plan) {
    std::vector<glm::dvec2> points;
    for (const Placement& p : plan.placements) points.push_back({p.position.x, -p.position.z});
    return points;
}

TEST(PoissonDisk, KeepsTheSpacingFillsTheBoxAndRepeats) {
    PoissonSettings s;
    s.min_distance = 3.0;
    s.seed = 5;
    const auto points = poisson_disk({0, 0}, {60, 40}, s);
    EXPECT_GE(min_pair_distance(points), 3.0);
    for (glm::dvec2 p : points) {
        EXPECT_GE(p.x, 0.0);
        EXPECT_LE(p.x, 60.0);
        EXPECT_GE(p.y, 0.0);
        EXPECT_LE(p.y, 40.0);
    }
    // Bridson fills to about 0.7 / r^2 points per square meter; a grid at r holds 1 / r^2.
    EXPECT_GT(points.size(), static_cast<std::size_t>(0.5 * 60 * 40 / 9.0));
    EXPECT_EQ(points, poisson_disk({0, 0}, {60, 40}, s));
    s.seed = 6;
    EXPECT_NE(points, poisson_disk({0, 0}, {60, 40}, s));
    s.min_distance = 0.0;
    EXPECT_THROW(poisson_disk({0, 0}, {60, 40}, s), InputError);
    s.min_distance = 0.001;
    EXPECT_THROW(poisson_disk({0, 0}, {1000, 1000}, s), InputError);  // far too many points
}

// Areas and spacings far past any integer (sylva forest --area 1e308x1e308, --spacing
// 1e-300) are refused with the figure as a person reads it, before any count is cast to an
// integer: the cast overflowed and the refusal read "about -9223372036854775808 trees".
std::string refusal(glm::dvec2 lo, glm::dvec2 hi, double spacing) {
    PoissonSettings s;
    s.min_distance = spacing;
    try {
        poisson_disk(lo, hi, s);
    } catch (const InputError& e) {
        return e.what();
    }
    return "(accepted)";
}

TEST(PoissonDisk, RefusesAreasAndSpacingsPastAnyCountWithTheFigure) {
    const std::string huge_area = refusal({0, 0}, {1e308, 1e308}, 4.0);
    EXPECT_NE(huge_area.find("more than 1e+308 trees"), std::string::npos) << huge_area;
    const std::string tiny_spacing = refusal({0, 0}, {60, 40}, 1e-300);
    EXPECT_NE(tiny_spacing.find("more than 1e+308 trees"), std::string::npos) << tiny_spacing;
    const std::string many = refusal({0, 0}, {1e9, 1e9}, 1.0);
    EXPECT_NE(many.find("about 1.2e+18 trees"), std::string::npos) << many;
    // Sides that overflow to infinity: the area is named, not its tree count.
    const std::string infinite = refusal({-1e308, -1e308}, {1e308, 1e308}, 4.0);
    EXPECT_NE(infinite.find("must be finite"), std::string::npos) << infinite;
    for (const std::string& message : {huge_area, tiny_spacing, many, infinite})
        EXPECT_EQ(message.find("-9"), std::string::npos) << message;
}

// A number past any double (1e999) is bad input naming the file, line and token, not an
// internal error (nlohmann's out_of_range escaped as exit 1).
TEST(Ground, ANumberPastAnyDoubleIsBadInputWithTheLine) {
    for (int file = 0; file < 2; ++file) {
        try {
            if (file == 0)
                parse_ground_json(
                    "{\"polygons\": [\n  {\"points\": [[0, 0], [1e999, 0], [1, 1]]}]}", "g.json");
            else
                parse_species_json(
                    "{\"species\": [\n  {\"template\": \"oak\", \"weight\": 1e999}]}", "s.json",
                    ".");
            ADD_FAILURE() << "no error";
        } catch (const InputError& e) {
            EXPECT_EQ(e.where().source, file == 0 ? "g.json" : "s.json");
            EXPECT_EQ(e.line(), 2);
            EXPECT_NE(std::string(e.what()).find("1e999"), std::string::npos) << e.what();
        }
    }
}

TEST(Ground, PolygonsWithHoles) {
    const Ground ground = parse_ground_json(R"({"polygons": [
        {"points": [[0, 0], [20, 0], [20, 10], [0, 10]]},
        {"points": [[8, -1], [12, -1], [12, 11], [8, 11]], "class": "road"}]})",
                                            "ground.json");
    ASSERT_EQ(ground.polygons.size(), 2u);
    EXPECT_EQ(ground.polygons[0].cls, "forest");
    EXPECT_TRUE(plantable(ground, {2, 5}));
    EXPECT_TRUE(plantable(ground, {18, 5}));
    EXPECT_FALSE(plantable(ground, {10, 5}));  // on the road
    EXPECT_FALSE(plantable(ground, {25, 5}));  // outside
    EXPECT_EQ(forest_bounds(ground).hi, glm::dvec2(20, 10));
}

TEST(Ground, BadFilesNameThePlace) {
    try {
        parse_ground_json("{\"polygons\": [\n  {\"points\": [[0, 0], [1, 0]],}\n]}", "g.json");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_EQ(e.line(), 2) << e.what();
        EXPECT_NE(std::string(e.what()).find("g.json"), std::string::npos) << e.what();
    }
    try {
        parse_ground_json(R"({"polygons": [{"points": [[0, 0], [1, 0]]}]})", "g.json");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("polygons[0]"), std::string::npos) << e.what();
    }
    EXPECT_THROW(
        parse_ground_json(R"({"polygons": [{"points": [[0, 0], [1, "a"], [2, 2]]}]})", "g"),
        InputError);
    EXPECT_THROW(load_ground("/nonexistent/ground.json"), IoError);
}

TEST(SpeciesFile, TemplatesWeightsAndOverrides) {
    const auto species = parse_species_json(R"({"species": [
        {"template": "oak", "weight": 2, "set": {"leaf_density": 40, "leaf_shape": "needle"}},
        {"template": "birch"}]})",
                                            "s.json");
    ASSERT_EQ(species.size(), 2u);
    EXPECT_EQ(species[0].tree.name, "oak");
    EXPECT_EQ(species[0].weight, 2.0);
    EXPECT_EQ(species[0].tree.params.leaf_density, 40.0);
    EXPECT_EQ(species[0].tree.params.leaf_shape, LeafShape::Needle);
    EXPECT_EQ(species[1].weight, 1.0);
    try {
        parse_species_json(R"({"species": [{"template": "oak"}, {"template": "birch",
            "set": {"age": 3}}]})",
                           "s.json");
        FAIL() << "no error";
    } catch (const InputError& e) {
        EXPECT_NE(std::string(e.what()).find("species[1].set.age"), std::string::npos) << e.what();
    }
    // A #define of the template's rules is set as `--set` sets it, held to its range.
    const auto set =
        parse_species_json(R"({"species": [{"template": "oak", "set": {"a": 60}}]})", "s.json");
    EXPECT_NE(set[0].tree.grammar.find("#define a  60"), std::string::npos) << set[0].tree.grammar;
    EXPECT_THROW(
        parse_species_json(R"({"species": [{"template": "oak", "set": {"a": 90}}]})", "s.json"),
        InputError);
    EXPECT_THROW(parse_species_json(R"({"species": []})", "s.json"), InputError);
    EXPECT_THROW(parse_species_json(R"({"species": [{"template": "nosuchtree"}]})", "s.json"),
                 InputError);
}

// A species file names templates beside it, never a file outside its folder, and a refusal
// never shows the content of the file it refused.
TEST(SpeciesFile, TemplatesAreLookedUpBesideTheFileOnly) {
    const fs::path root =
        fs::temp_directory_path() / ("sylva_species_" + std::to_string(::getpid()));
    fs::remove_all(root);
    fs::create_directories(root / "plans");
    std::ofstream(root / "secret.txt") << "top secret line\n";
    std::ofstream(root / "plans" / "mine.txt") << "axiom: F\nF -> F[+F]F\n";
    const auto species_file = [&](const std::string& name) {
        const fs::path path = root / "plans" / "species.json";
        std::ofstream(path) << R"({"species": [{"template": ")" + name + R"("}]})";
        return path;
    };
    const auto species = load_species(species_file("mine.txt"));
    ASSERT_EQ(species.size(), 1u);
    EXPECT_EQ(species[0].tree.name, "mine");
    for (const std::string& name :
         std::vector<std::string>{"../secret.txt", (root / "secret.txt").string(), "/dev/zero",
                                  "/etc/passwd", "plans/../../secret.txt"}) {
        try {
            load_species(species_file(name));
            FAIL() << "accepted " << name;
        } catch (const InputError& e) {
            const std::string message = e.what();
            EXPECT_NE(message.find("species[0].template"), std::string::npos) << message;
            EXPECT_EQ(message.find("top secret"), std::string::npos) << message;
            EXPECT_EQ(message.find("root:"), std::string::npos) << message;
        }
    }
    // A device or FIFO beside the file is refused by the reader, at once.
    ASSERT_EQ(::mkfifo((root / "plans" / "pipe.toml").c_str(), 0600), 0);
    EXPECT_THROW(load_species(species_file("pipe.toml")), IoError);
    // Text that came from no file names only built-in templates.
    EXPECT_THROW(parse_species_json(R"({"species": [{"template": "mine.txt"}]})", "s.json"),
                 InputError);
    fs::remove_all(root);
}

TEST(ForestInputs, DevicesAndFifosAreRefusedNotRead) {
    EXPECT_THROW(load_ground("/dev/zero"), IoError);
    EXPECT_THROW(load_species("/dev/zero"), IoError);
    const fs::path pipe = fs::temp_directory_path() / ("sylva_fifo_" + std::to_string(::getpid()));
    fs::remove(pipe);
    ASSERT_EQ(::mkfifo(pipe.c_str(), 0600), 0);
    EXPECT_THROW(load_ground(pipe), IoError);
    fs::remove(pipe);
}

ForestSettings small_forest() {
    ForestSettings s;
    s.species = {{load_template("spruce"), 1.0}, {load_template("pine"), 1.0}};
    s.ground = rectangle_ground(50, 30);
    s.variants = 2;
    s.spacing = 3.0;
    s.stand_size = 15.0;
    s.seed = 3;
    s.finish.budget.total = 200;
    return s;
}

TEST(ForestPlan, TreesStandInsideTheAreaApartAndInStands) {
    ForestSettings s = small_forest();
    s.ground = rectangle_ground(160, 120);
    s.species.push_back({load_template("birch"), 2.0});
    s.variants = 4;
    const ForestPlan plan = plan_forest(s);
    ASSERT_GT(plan.placements.size(), 500u);
    ASSERT_EQ(plan.variants.size(), 12u);
    const auto points = map_points(plan);
    EXPECT_GE(min_pair_distance(points), s.spacing - 1e-9);
    std::vector<std::size_t> count(3, 0);
    for (const Placement& p : plan.placements) {
        EXPECT_TRUE(plantable(s.ground, {p.position.x, -p.position.z}));
        EXPECT_EQ(p.position.y, 0.0);
        EXPECT_EQ(plan.variants[p.variant].species, p.species);
        EXPECT_GE(p.scale, 1.0 - s.scale_jitter);
        EXPECT_LE(p.scale, 1.0 + s.scale_jitter);
        ++count[p.species];
    }
    // Shares follow the weights 1 : 1 : 2.
    const double n = static_cast<double>(points.size());
    EXPECT_NEAR(static_cast<double>(count[0]) / n, 0.25, 0.08);
    EXPECT_NEAR(static_cast<double>(count[2]) / n, 0.5, 0.08);
    // Like stands with like: a tree's nearest neighbour is of its species far more often
    // than the ~37 % of species drawn at random with these shares; and the neighbour's
    // variant differs when the species is the same.
    std::size_t same_species = 0, same_variant = 0;
    for (std::size_t i = 0; i < points.size(); ++i) {
        std::size_t nearest = i == 0 ? 1 : 0;
        for (std::size_t j = 0; j < points.size(); ++j)
            if (j != i &&
                glm::distance(points[i], points[j]) < glm::distance(points[i], points[nearest]))
                nearest = j;
        if (plan.placements[i].species == plan.placements[nearest].species) {
            ++same_species;
            same_variant += plan.placements[i].variant == plan.placements[nearest].variant;
        }
    }
    EXPECT_GT(static_cast<double>(same_species) / n, 0.7);
    EXPECT_LT(static_cast<double>(same_variant), 0.1 * static_cast<double>(same_species));
    // Variants age from min_age to 1 (the templates have `age`), and a tree's age is its
    // variant's.
    for (std::size_t k = 0; k < 4; ++k) {
        EXPECT_NEAR(plan.variants[k].age, s.min_age + (1.0 - s.min_age) * k / 3.0, 1e-12);
        EXPECT_EQ(*get_param(plan.variants[k].params, "age"), plan.variants[k].age);
    }
    for (const Placement& p : plan.placements) EXPECT_EQ(p.age, plan.variants[p.variant].age);
    // The same settings plan the same forest.
    const ForestPlan again = plan_forest(s);
    EXPECT_EQ(map_points(again), points);
}

TEST(ForestPlan, DensityAndTreeCount) {
    ForestSettings s = small_forest();
    s.ground = rectangle_ground(100, 100);  // one hectare
    s.density = 200.0;
    EXPECT_NEAR(static_cast<double>(plan_forest(s).placements.size()), 200.0, 5.0);
    s.density.reset();
    s.trees = 123;
    EXPECT_EQ(plan_forest(s).placements.size(), 123u);
    s.density = 10.0;
    EXPECT_THROW(plan_forest(s), InputError);  // both
    s.density.reset();
    s.species.clear();
    EXPECT_THROW(plan_forest(s), InputError);
}

using ForestScene = test::TempFolderTest;

tinygltf::Model load(const fs::path& path) {
    tinygltf::Model model;
    tinygltf::TinyGLTF gltf;
    std::string error, warning;
    EXPECT_TRUE(gltf.LoadBinaryFromFile(&model, &error, &warning, path.string())) << error;
    return model;
}

// Every CSV row after the header, split at commas.
std::vector<std::vector<std::string>> csv_rows(const fs::path& path) {
    std::vector<std::vector<std::string>> rows;
    std::istringstream in(test::read_file(path));
    std::string line;
    std::getline(in, line);
    EXPECT_EQ(line, "index,species,variant,x,y,z,yaw_degrees,scale,age,class");
    while (std::getline(in, line)) {
        std::vector<std::string> cells;
        std::istringstream cell_in(line);
        std::string cell;
        while (std::getline(cell_in, cell, ',')) cells.push_back(cell);
        rows.push_back(cells);
    }
    return rows;
}

TEST_F(ForestScene, SceneMatchesThePlacementListAndRepeats) {
    const ForestSettings s = small_forest();
    const ForestResult result = plant_forest(s, dir_ / "forest.glb");
    ASSERT_EQ(result.files.size(), 3u);
    const auto rows = csv_rows(placements_csv_path(dir_ / "forest.glb"));
    ASSERT_EQ(rows.size(), result.plan.placements.size());
    ASSERT_GT(rows.size(), 50u);

    const tinygltf::Model model = load(dir_ / "forest.glb");
    // Meshes stored once per variant part, not per tree.
    EXPECT_LE(model.meshes.size(), 3 * result.plan.variants.size());
    const tinygltf::Node& root = model.nodes[static_cast<std::size_t>(model.scenes[0].nodes[0])];
    ASSERT_EQ(root.children.size(), rows.size());  // one node per tree
    const double area_x = 25.0, area_y = 15.0;
    for (std::size_t i = 0; i < rows.size(); ++i) {
        const tinygltf::Node& tree = model.nodes[static_cast<std::size_t>(root.children[i])];
        EXPECT_EQ(tree.extras.Get("sylva_variant").Get<std::string>(), rows[i][2]);
        ASSERT_EQ(tree.translation.size(), 3u);
        EXPECT_NEAR(tree.translation[0], std::stod(rows[i][3]), 1e-3);
        EXPECT_EQ(tree.translation[1], 0.0);  // on the ground
        EXPECT_NEAR(tree.translation[2], std::stod(rows[i][5]), 1e-3);
        EXPECT_LE(std::abs(tree.translation[0]), area_x);
        EXPECT_LE(std::abs(tree.translation[2]), area_y);
        EXPECT_FALSE(tree.children.empty());
        for (int part : tree.children)
            EXPECT_GE(model.nodes[static_cast<std::size_t>(part)].mesh, 0);
    }
    // The JSON list says the same.
    const nlohmann::json doc =
        nlohmann::json::parse(test::read_file(placements_json_path(dir_ / "forest.glb")));
    EXPECT_EQ(doc["placements"].size(), rows.size());
    EXPECT_EQ(doc["variants"].size(), 4u);

    // Same seed, same bytes.
    fs::create_directories(dir_ / "again");
    plant_forest(s, dir_ / "again" / "forest.glb");
    for (const char* name : {"forest.glb", "forest.placements.csv", "forest.placements.json"})
        EXPECT_EQ(test::read_file(dir_ / name), test::read_file(dir_ / "again" / name)) << name;
}

TEST_F(ForestScene, GpuInstancingCarriesEveryTree) {
    ForestSettings s = small_forest();
    s.instancing = Instancing::Gpu;
    s.finish.lod = true;
    s.finish.budget.total = 200;
    const ForestResult result = plant_forest(s, dir_ / "gpu.glb");
    const tinygltf::Model model = load(dir_ / "gpu.glb");
    // Used, never required: the default scene places every tree as plain nodes.
    EXPECT_TRUE(model.extensionsRequired.empty());
    EXPECT_EQ(model.extensionsUsed, std::vector<std::string>{"EXT_mesh_gpu_instancing"});
    ASSERT_EQ(model.scenes.size(), 2u);
    EXPECT_EQ(model.defaultScene, 0);
    std::size_t tree_nodes = 0;
    for (int root : model.scenes[0].nodes)
        for (int child : model.nodes[static_cast<std::size_t>(root)].children) {
            const tinygltf::Node& tree = model.nodes[static_cast<std::size_t>(child)];
            EXPECT_TRUE(tree.extensions.empty()) << tree.name;
            EXPECT_EQ(tree.translation.size(), 3u) << tree.name;
            ++tree_nodes;
        }
    EXPECT_EQ(tree_nodes, result.plan.placements.size()) << "a plain node places every tree";
    // Per variant: the instance count of its (first) instanced node.
    std::map<std::string, std::size_t> instances;
    std::size_t lod_nodes = 0;
    for (const tinygltf::Node& node : model.nodes) {
        lod_nodes += node.name.find("_LOD3") != std::string::npos;
        auto ext = node.extensions.find("EXT_mesh_gpu_instancing");
        if (ext == node.extensions.end()) continue;
        const int accessor = ext->second.Get("attributes").Get("TRANSLATION").Get<int>();
        const std::string variant =
            node.name.substr(0, node.name.find('_', node.name.find("_v") + 1));
        instances[variant] = model.accessors[static_cast<std::size_t>(accessor)].count;
    }
    EXPECT_GT(lod_nodes, 0u);
    std::map<std::string, std::size_t> expected;
    for (const Placement& p : result.plan.placements)
        ++expected[result.plan.variants[p.variant].name];
    EXPECT_EQ(instances, expected);
    // The instanced scene puts each tree where its placement says: group * instance.
    const tinygltf::Node& gpu_root =
        model.nodes[static_cast<std::size_t>(model.scenes[1].nodes.at(0))];
    std::size_t placed = 0;
    for (int g : gpu_root.children) {
        const tinygltf::Node& group = model.nodes[static_cast<std::size_t>(g)];
        // The first instanced node below the group (a chain's parts sit in level nodes).
        const tinygltf::Node* part = &model.nodes[static_cast<std::size_t>(group.children.at(0))];
        while (!part->extensions.contains("EXT_mesh_gpu_instancing"))
            part = &model.nodes[static_cast<std::size_t>(part->children.at(0))];
        auto ext = part->extensions.find("EXT_mesh_gpu_instancing");
        const auto& a = model.accessors[static_cast<std::size_t>(
            ext->second.Get("attributes").Get("TRANSLATION").Get<int>())];
        const auto& view = model.bufferViews[static_cast<std::size_t>(a.bufferView)];
        const float* t = reinterpret_cast<const float*>(model.buffers[0].data.data() +
                                                        view.byteOffset + a.byteOffset);
        const double yaw = 2.0 * std::atan2(group.rotation[1], group.rotation[3]);
        for (std::size_t i = 0; i < a.count; ++i, ++placed) {
            const glm::dvec3 local(t[3 * i], t[3 * i + 1], t[3 * i + 2]);
            const glm::dvec3 world(
                group.translation[0] +
                    group.scale[0] * (local.x * std::cos(yaw) + local.z * std::sin(yaw)),
                group.translation[1] + group.scale[0] * local.y,
                group.translation[2] +
                    group.scale[0] * (-local.x * std::sin(yaw) + local.z * std::cos(yaw)));
            bool found = false;
            for (const Placement& p : result.plan.placements)
                found |= glm::length(glm::dvec3(glm::vec3(p.position)) - world) < 1e-3;
            EXPECT_TRUE(found) << group.name << " instance " << i;
        }
    }
    EXPECT_GT(placed, 0u);
}

}  // namespace
