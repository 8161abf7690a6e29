// A table of parameters: for each key its meaning, range, group and where its value lives,
// so --set, template files, help text, docs, skeleton.json and the studio's controls are all
// made from one list (tree/parameters.h joins the tables). TreeParams' shared parameters are
// one table (core/tree_params.cpp); a module with parameters of its own (a growth method)
// keeps them in a struct of its own, stored in TreeParams::blocks, with a table beside it.
//
// Adding a parameter is one line in its module's table:
//
//   param("step_size", &ColonizationParams::step_size, 0.001, 10, ParamGroup::GrowthMethod,
//         "distance of a new node from its parent, meters").symbol("D"),
//
// Tables are built once and read-only after: safe to read from any thread.
#pragma once

#include <cstddef>
#include <functional>
#include <glm/vec3.hpp>
#include <span>
#include <string_view>
#include <type_traits>
#include <vector>

#include "core/tree_params.h"

namespace sylva {

// Where an artist looks for a parameter; the studio and the help group them so, in this order.
enum class ParamGroup { Shape, Branches, Crown, Leaves, GameMesh, Wind, Variation, GrowthMethod };

// Every group in display order, and each one's title ("Game mesh").
std::span<const ParamGroup> param_groups();
std::string_view group_title(ParamGroup group);

// One parameter's key, meaning and valid range, for --set, sliders and validation. Values are
// read and written as doubles whatever the member's type (whole numbers, flags and choices
// are exact).
struct ParamInfo {
    std::string_view key = {};
    std::string_view help = {};
    double min = 0;
    double max = 0;
    bool integer = false;  // whole numbers only (flags and choices too)
    // For a choice parameter: the names of its values 0, 1, ... (empty for numbers).
    std::span<const std::string_view> choices = {};
    ParamGroup group = ParamGroup::Shape;
    bool flag = false;             // on (1) or off (0): a checkbox
    std::string_view symbol = {};  // its name in the work it comes from ("P_Tres", "d_i"), or ""
    std::string_view owner = {};   // the growth method that reads it; "" for every method
    double default_value = 0;      // the value in a default TreeParams
};

// One line of a table over the struct Block: the parameter and how to read and write it.
template <class Block>
struct ParamField {
    ParamInfo info;
    std::function<double(const Block&)> get;
    std::function<void(Block&, double)> set;  // the value is valid (set_param checked it)

    // The parameter's name in the work it comes from, for the docs' thesis column.
    ParamField symbol(std::string_view name) && {
        info.symbol = name;
        return std::move(*this);
    }
};

// A real number in [min, max].
template <class Block>
ParamField<Block> param(std::string_view key, double Block::*member, double min, double max,
                        ParamGroup group, std::string_view help) {
    return {{.key = key, .help = help, .min = min, .max = max, .group = group},
            [member](const Block& b) { return b.*member; },
            [member](Block& b, double v) { b.*member = v; }};
}

// A whole number in [min, max].
template <class Block>
ParamField<Block> param(std::string_view key, int Block::*member, double min, double max,
                        ParamGroup group, std::string_view help) {
    return {{.key = key, .help = help, .min = min, .max = max, .integer = true, .group = group},
            [member](const Block& b) { return static_cast<double>(b.*member); },
            [member](Block& b, double v) { b.*member = static_cast<int>(v); }};
}

// On or off, read and written as 1 and 0.
template <class Block>
ParamField<Block> param(std::string_view key, bool Block::*member, ParamGroup group,
                        std::string_view help) {
    return {{.key = key,
             .help = help,
             .min = 0,
             .max = 1,
             .integer = true,
             .group = group,
             .flag = true},
            [member](const Block& b) { return b.*member ? 1.0 : 0.0; },
            [member](Block& b, double v) { b.*member = v != 0.0; }};
}

// One of `names`, stored as the enum (or int) value of its index.
template <class Block, class Choice>
requires std::is_enum_v<Choice> || std::is_same_v<Choice, int> ParamField<Block> param(
    std::string_view key, Choice Block::*member, std::span<const std::string_view> names,
    ParamGroup group, std::string_view help) {
    return {{.key = key,
             .help = help,
             .min = 0,
             .max = static_cast<double>(names.size()) - 1.0,
             .integer = true,
             .choices = names,
             .group = group},
            [member](const Block& b) { return static_cast<double>(static_cast<int>(b.*member)); },
            [member](Block& b, double v) { b.*member = static_cast<Choice>(static_cast<int>(v)); }};
}

// One component (0: x, 1: y, 2: z) of a vector, under a key of its own: a vector is three
// keys ("tropism_vector_x", ...), so files and --set name each component.
template <class Block>
ParamField<Block> param(std::string_view key, glm::dvec3 Block::*member, int axis, double min,
                        double max, ParamGroup group, std::string_view help) {
    return {{.key = key, .help = help, .min = min, .max = max, .group = group},
            [member, axis](const Block& b) { return (b.*member)[axis]; },
            [member, axis](Block& b, double v) { (b.*member)[axis] = v; }};
}

// The parameters of one owner: TreeParams' shared ones, or a module's block.
class ParamTable {
  public:
    // The shared parameters, members of TreeParams itself.
    static ParamTable shared(std::vector<ParamField<TreeParams>> fields) {
        return ParamTable(
            "", std::move(fields), [](const TreeParams& p) -> const TreeParams& { return p; },
            [](TreeParams& p) -> TreeParams& { return p; });
    }

    // A module's parameters, kept in TreeParams::blocks as a Block. `owner` is the growth
    // method that reads them.
    template <class Block>
    static ParamTable owned(std::string_view owner, std::vector<ParamField<Block>> fields) {
        return ParamTable(
            owner, std::move(fields),
            [](const TreeParams& p) -> const Block& { return p.blocks.get<Block>(); },
            [](TreeParams& p) -> Block& { return p.blocks.edit<Block>(); });
    }

    std::string_view owner() const { return owner_; }
    std::span<const ParamInfo> infos() const { return infos_; }

    // The value of parameter `index` (of infos()); set() takes a value already checked
    // against the parameter's range (set_param in tree/parameters.h checks).
    double get(const TreeParams& params, std::size_t index) const { return get_[index](params); }
    void set(TreeParams& params, std::size_t index, double value) const {
        set_[index](params, value);
    }

  private:
    template <class Block, class Read, class Write>
    ParamTable(std::string_view owner, std::vector<ParamField<Block>> fields, Read read,
               Write write)
        : owner_(owner) {
        const Block defaults{};
        for (ParamField<Block>& f : fields) {
            f.info.owner = owner;
            f.info.default_value = f.get(defaults);
            infos_.push_back(f.info);
            get_.push_back([read, get = f.get](const TreeParams& p) { return get(read(p)); });
            set_.push_back([write, set = f.set](TreeParams& p, double v) { set(write(p), v); });
        }
    }

    std::string_view owner_;
    std::vector<ParamInfo> infos_;
    std::vector<std::function<double(const TreeParams&)>> get_;
    std::vector<std::function<void(TreeParams&, double)>> set_;
};

}  // namespace sylva
