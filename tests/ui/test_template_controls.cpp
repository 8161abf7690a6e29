// The "this tree" controls without a window: #define constants with a range become sliders
// and are written back in place; global parameters the rules never read are found, with the
// reason; slider ranges contain a template's own values.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <vector>

#include "colonization/colonization_params.h"
#include "tree/growth.h"
#include "tree/parameters.h"
#include "tree/template_library.h"
#include "ui/state/template_controls.h"

namespace sylva::studio {
namespace {

TEST(TemplateControls, DefinesWithARangeBecomeConstants) {
    const std::string grammar =
        "#define a  34      # [10, 60] fork angle, degrees\n"
        "#define s  0.82    # [0.5, 0.95] length ratio per fork\n"
        "#define n  5       # [2, 9] branches per whorl\n"
        "#define d  137.5   # divergence (no range: text only)\n"
        "#define e  a*2     # [0, 100] an expression: text only\n"
        "axiom: F(1)A\n";
    const std::vector<GrammarConstant> constants = grammar_constants(grammar);
    ASSERT_EQ(constants.size(), 3u);
    EXPECT_EQ(constants[0].name, "a");
    EXPECT_EQ(constants[0].value, 34.0);
    EXPECT_EQ(constants[0].min, 10.0);
    EXPECT_EQ(constants[0].max, 60.0);
    EXPECT_EQ(constants[0].help, "fork angle, degrees");
    EXPECT_EQ(constants[0].line, 1);
    EXPECT_TRUE(constants[0].integer);
    EXPECT_FALSE(constants[1].integer);
    EXPECT_EQ(constants[1].value, 0.82);
    EXPECT_EQ(constants[2].name, "n");
    EXPECT_EQ(constants[2].line, 3);
}

TEST(TemplateControls, SettingAConstantRewritesItsValueOnly) {
    std::string grammar =
        "#define s  0.82    # [0.5, 0.95] length ratio\n"
        "axiom: F(s)\n";
    ASSERT_TRUE(set_grammar_constant(grammar, "s", 0.7));
    EXPECT_EQ(grammar, "#define s  0.7     # [0.5, 0.95] length ratio\naxiom: F(s)\n");
    ASSERT_TRUE(set_grammar_constant(grammar, "s", 0.912345));
    EXPECT_EQ(grammar, "#define s  0.912345 # [0.5, 0.95] length ratio\naxiom: F(s)\n");
    EXPECT_FALSE(set_grammar_constant(grammar, "q", 1.0));
    EXPECT_EQ(grammar_constants(grammar).at(0).value, 0.912345);
}

TEST(TemplateControls, NumbersAreShortestAndRoundedToTheRange) {
    EXPECT_EQ(shortest_number(0.8), "0.8");
    EXPECT_EQ(shortest_number(34.0), "34");
    EXPECT_EQ(shortest_number(-0.0), "0");
    EXPECT_EQ(round_for_range(0.8213419, 0.5, 0.95), 0.821);
    EXPECT_EQ(round_for_range(34.27, 10, 60), 34.3);
    EXPECT_EQ(round_for_range(99.0, 10, 60), 60.0);
}

// The oak's rules give every F, &, ^, +, -, \ and / an explicit value, and its widths come
// from the pipe model: those globals are inert there, with the reason.
TEST(TemplateControls, InertParametersOfTheOak) {
    const auto inert = inert_params(load_template("oak"));
    for (const char* key : {"branch_length", "pitch_angle", "yaw_angle", "trunk_taper",
                            "branch_taper", "branch_width", "attraction_points", "envelope"})
        EXPECT_TRUE(inert.contains(key)) << key;
    EXPECT_NE(inert.at("branch_length").find("F"), std::string::npos);
    for (const char* key : {"generations", "tip_width", "pipe_exponent", "tropism",
                            "sphere_diameter", "leaf_density", "trunk_resolution"})
        EXPECT_FALSE(inert.contains(key)) << key;
}

TEST(TemplateControls, ADefaultUseOrANamedParameterIsRead) {
    TreeTemplate t;
    t.width_model = WidthModel::Taper;
    t.grammar = "axiom: A\nA -> F[+(30)A][&A]\n";
    auto inert = inert_params(t);
    EXPECT_FALSE(inert.contains("branch_length"));  // F has no argument
    EXPECT_FALSE(inert.contains("pitch_angle"));    // nor &
    EXPECT_TRUE(inert.contains("yaw_angle"));       // + has one
    EXPECT_FALSE(inert.contains("trunk_taper"));
    EXPECT_TRUE(inert.contains("tip_width"));
    t.grammar = "axiom: A\nA -> F(1)[+(yaw_angle)A] # pitch_angle in a comment\n";
    inert = inert_params(t);
    EXPECT_TRUE(inert.contains("branch_length"));
    EXPECT_FALSE(inert.contains("yaw_angle"));  // named in an expression
    EXPECT_TRUE(inert.contains("pitch_angle"));
}

TEST(TemplateControls, InertParametersOfSpaceColonization) {
    const auto inert = inert_params(load_template("elm"));
    for (const char* key : {"generations", "branch_length", "pitch_angle", "obstacle_x"})
        EXPECT_TRUE(inert.contains(key)) << key;
    for (const char* key : {"attraction_points", "kill_distance", "tip_width", "envelope"})
        EXPECT_FALSE(inert.contains(key)) << key;
}

// max_no_grow is greyed where the growth shows it has nothing to act on, with that reason:
// the windswept pine never stalls; on the hedge the points a stalled node releases find no
// node that can grow towards them. Where it acts (elm, maple) it stays enabled.
TEST(TemplateControls, MaxNoGrowIsGreyedWhereTheGrowthGivesItNothingToDo) {
    const auto windswept = inert_params(load_template("windswept"));
    ASSERT_TRUE(windswept.contains("max_no_grow"));
    EXPECT_NE(windswept.at("max_no_grow").find("never stalls"), std::string::npos);
    const auto hedge = inert_params(load_template("hedge"));
    ASSERT_TRUE(hedge.contains("max_no_grow"));
    EXPECT_NE(hedge.at("max_no_grow").find("no growth comes of releasing"), std::string::npos);
    for (const char* name : {"elm", "maple"})
        EXPECT_FALSE(inert_params(load_template(name)).contains("max_no_grow")) << name;
}

// A node that stalls in the last pass still gets its max_no_grow passes: the growth waits
// for its release instead of ending (the maple's last stall is 8 passes from the end).
TEST(TemplateControls, MaxNoGrowActsOnAStallInTheLastPass) {
    TreeTemplate maple = load_template("maple");
    maple.params.blocks.edit<ColonizationParams>().max_no_grow = 0;
    const Skeleton never = grow(maple);
    maple.params.blocks.edit<ColonizationParams>().max_no_grow = 8;
    EXPECT_NE(grow(maple).segments.size(), never.segments.size());
}

// What inert means: changing the parameter changes no segment of the skeleton. Checked on
// every built-in L-system template for the parameters that act through the skeleton alone.
TEST(TemplateControls, InertParametersChangeNoSkeleton) {
    for (const TreeTemplate* builtin : builtin_templates()) {
        if (builtin->growth != "lsystem") continue;
        const TreeTemplate& t = *builtin;
        const auto inert = inert_params(t);
        const Skeleton base = grow(t);
        for (const char* key :
             {"branch_length", "pitch_angle", "yaw_angle", "branch_width", "trunk_taper",
              "branch_taper", "tip_width", "pipe_exponent", "tropism"}) {
            TreeTemplate changed = t;
            const ParamInfo* info = nullptr;
            for (const ParamInfo& i : param_infos())
                if (i.key == key) info = &i;
            ASSERT_TRUE(info);
            const double value = *get_param(t.params, key);
            set_param(changed.params, key, std::clamp(value * 0.7 + 0.01, info->min, info->max));
            const Skeleton other = grow(changed);
            bool same = other.segments.size() == base.segments.size();
            for (std::size_t i = 0; same && i < base.segments.size(); ++i)
                same = base.segments[i].b == other.segments[i].b &&
                       base.segments[i].ra == other.segments[i].ra &&
                       base.segments[i].rb == other.segments[i].rb;
            EXPECT_EQ(same, inert.contains(key)) << t.name << " " << key;
        }
    }
}

TEST(TemplateControls, SliderRangesContainTheTemplatesOwnValue) {
    const TreeTemplate spruce = load_template("spruce");
    const SliderRange density = slider_range("leaf_density", spruce.params.leaf_density);
    EXPECT_GE(density.max, spruce.params.leaf_density);
    for (const TreeTemplate* t : builtin_templates())
        for (const ParamInfo& info : param_infos()) {
            const double value = *get_param(t->params, info.key);
            const SliderRange range = slider_range(info.key, value);
            EXPECT_LE(range.min, value) << t->name << " " << info.key;
            EXPECT_GE(range.max, value) << t->name << " " << info.key;
        }
}

}  // namespace
}  // namespace sylva::studio

namespace sylva::studio {
namespace {

// The acceptance sweep: every parameter that acts through the skeleton changes it on every
// built-in template, one way or the other (a slider moved down or up or to its low end,
// another choice),
// unless it is greyed out. `obstacle` is left out: switched on at its default place it may
// miss the envelope, and its place sliders (checked here) then move it in.
bool same_skeleton(const Skeleton& a, const Skeleton& b) {
    if (a.segments.size() != b.segments.size()) return false;
    for (std::size_t i = 0; i < a.segments.size(); ++i)
        if (a.segments[i].a != b.segments[i].a || a.segments[i].b != b.segments[i].b ||
            a.segments[i].ra != b.segments[i].ra || a.segments[i].rb != b.segments[i].rb)
            return false;
    return true;
}

TEST(TemplateControls, EveryGrowthSliderChangesTheSkeletonOrIsGreyed) {
    // What shapes the meshes or colours, not the skeleton.
    const std::vector<std::string_view> meshing_only = {
        "trunk_resolution", "crown_resolution", "sphere_diameter", "crown_offset",
        "crown_fusion",     "joint_blend",      "crown_blend",     "crown_mesh",
        "crown_merge",      "drop_hidden",      "leaf_density",    "leaf_size",
        "leaf_shape",       "triangle_budget",  "crown_shape",     "crown_lump_triangles",
        "obstacle",         "color_variation",  "branch_style",    "leaf_style",
        "polygon_part"};
    for (const TreeTemplate* t : builtin_templates()) {
        const auto inert = inert_params(*t);
        const Skeleton base = grow(*t);
        for (const ParamInfo& info : param_infos()) {
            if (std::find(meshing_only.begin(), meshing_only.end(), info.key) != meshing_only.end())
                continue;
            if (info.group == ParamGroup::Wind) continue;  // moves the tree, never shapes it
            const double value = *get_param(t->params, info.key);
            std::vector<double> others;
            if (!info.choices.empty()) {
                for (std::size_t c = 0; c < info.choices.size(); ++c)
                    if (static_cast<double>(c) != value) others.push_back(static_cast<double>(c));
            } else if (info.integer) {
                // Limits such as max_iterations only bite below what the growth needed.
                others = {value - std::max(1.0, std::round(0.3 * value)), value + 1, 1.0, info.min};
            } else {
                others = {value * 0.7 - 0.01, value * 1.3 + 0.01};
            }
            bool changes = false;
            for (double other : others) {
                other = std::clamp(other, info.min, info.max);
                if (other == value) continue;
                TreeTemplate changed = *t;
                set_param(changed.params, info.key, other);
                try {
                    changes |= !same_skeleton(base, grow(changed));
                } catch (const std::exception&) {
                    changes = true;  // an error is a change the artist sees
                }
            }
            EXPECT_EQ(!changes, inert.contains(info.key)) << t->name << " " << info.key;
        }
    }
}

// A slider above what the budget meshes at says so in its tooltip: the willow (drop_hidden)
// meshes its trunk and crown for the budget; the hedge's trunk keeps its resolution at 800
// (not below) and its crown (48) is meshed at the budget's 40.
TEST(TemplateControls, AResolutionTheBudgetLowersSaysWhatItIsMeshedAt) {
    TreeTemplate willow = load_template("willow");
    // Prisms: the game mesh meshes no trunk, and the note says what the resolution still sets.
    EXPECT_NE(budget_resolution_note(willow.params, "trunk_resolution").find("prisms"),
              std::string::npos);
    willow.params.branch_style = BranchStyle::Surface;
    const std::string willow_trunk = budget_resolution_note(willow.params, "trunk_resolution");
    EXPECT_NE(willow_trunk.find("meshed at 60"), std::string::npos);
    EXPECT_NE(willow_trunk.find("drop_hidden"), std::string::npos);
    EXPECT_NE(budget_resolution_note(willow.params, "crown_resolution").find("meshed at 40"),
              std::string::npos);
    TreeTemplate hedge = load_template("hedge");
    hedge.params.branch_style = BranchStyle::Surface;
    EXPECT_EQ(budget_resolution_note(hedge.params, "trunk_resolution"), "");
    EXPECT_NE(budget_resolution_note(hedge.params, "crown_resolution").find("meshed at 40"),
              std::string::npos);
    EXPECT_EQ(budget_resolution_note(willow.params, "leaf_size"), "");
    TreeParams small = hedge.params;  // below 800 every trunk is meshed coarser
    small.triangle_budget = 200;
    const std::string hedge_trunk = budget_resolution_note(small, "trunk_resolution");
    EXPECT_NE(hedge_trunk.find("meshed at 40 for the budget of 200"), std::string::npos);
    EXPECT_NE(hedge_trunk.find("below 800"), std::string::npos);
    TreeParams full = willow.params;
    full.triangle_budget = 0;  // no game mesh: the sliders' values are used
    EXPECT_EQ(budget_resolution_note(full, "trunk_resolution"), "");
}

// The "This tree" sliders read as the template's comments name them, not a, f, s, d.
TEST(TemplateControls, ConstantSlidersAreLabelledByTheirHelp) {
    const std::vector<GrammarConstant> constants = grammar_constants(
        "#define f 34 # [10, 60] fork angle, degrees\n#define n 5 # [2, 9] branches (per "
        "whorl)\n#define d 1 # [0, 2]\n");
    ASSERT_EQ(constants.size(), 3u);
    EXPECT_EQ(constant_label(constants[0]), "fork angle");
    EXPECT_EQ(constant_label(constants[1]), "branches");
    EXPECT_EQ(constant_label(constants[2]), "d");  // no help: the name
    for (const TreeTemplate* t : builtin_templates()) {
        std::vector<std::string> labels;
        for (const GrammarConstant& c : grammar_constants(t->grammar)) {
            const std::string label = constant_label(c);
            EXPECT_GT(label.size(), 1u) << t->name << ": #define " << c.name;
            EXPECT_EQ(std::count(labels.begin(), labels.end(), label), 0)
                << t->name << ": two sliders read \"" << label << "\"";
            labels.push_back(label);
        }
    }
}

// Every parameter sits in one of the artist's groups, and the search
// finds by words of the key, help or group, ignoring case.
TEST(TemplateControls, ParametersAreGroupedAndSearchable) {
    std::map<ParamGroup, int> per_group;
    for (const ParamInfo& info : param_infos()) ++per_group[info.group];
    for (const auto& [group, count] : per_group)
        EXPECT_NE(std::find(param_groups().begin(), param_groups().end(), group),
                  param_groups().end());
    EXPECT_GT(per_group[ParamGroup::Shape], 0);
    EXPECT_GT(per_group[ParamGroup::Leaves], 0);
    EXPECT_GT(per_group[ParamGroup::GameMesh], 0);

    auto found = [](std::string_view query) {
        std::vector<std::string> keys;
        for (const ParamInfo& info : param_infos())
            if (search_finds(query, parameter_search_text(info))) keys.emplace_back(info.key);
        return keys;
    };
    EXPECT_EQ(found("").size(), param_infos().size());
    const std::vector<std::string> leaf = found("Leaf Density");
    EXPECT_NE(std::find(leaf.begin(), leaf.end(), "leaf_density"), leaf.end());
    EXPECT_LT(leaf.size(), 4u);
    const std::vector<std::string> game = found("game mesh");  // a group's title
    EXPECT_NE(std::find(game.begin(), game.end(), "triangle_budget"), game.end());
    EXPECT_TRUE(found("no such word zzz").empty());
}

}  // namespace
}  // namespace sylva::studio
