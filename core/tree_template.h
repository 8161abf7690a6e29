// A tree template: everything that decides a tree's shape and look. Built-in templates are
// compiled in (tree/template_library.h), others read from TOML files (tree/template_file.h).
#pragma once

#include <cstddef>
#include <glm/vec3.hpp>
#include <string>
#include <vector>

#include "core/tree_params.h"

namespace sylva {

// Base colours of the parts, linear RGB in [0, 1].
struct PartColors {
    glm::vec3 trunk{0.36f, 0.24f, 0.15f};
    glm::vec3 crown{0.22f, 0.45f, 0.18f};
    glm::vec3 leaves{0.30f, 0.55f, 0.20f};
    // The colour of each colour index the grammar sets with ' and ; (ABOP's colour map),
    // index i taking palette[i % size]. Empty: no colour by index (every part its colour).
    // With a palette, trunk, leaves and organs are coloured by index in the exports' vertex
    // colours (export/index_colors.h).
    std::vector<glm::vec3> palette;
};

// Colour indices past this are refused in template files: more than any colour map needs.
inline constexpr std::size_t kMaxPaletteColors = 256;

// The turtle's frame (docs/grammar.md): ABOP's H, L, U, or Heuer's (2022) elevation and
// azimuth.
enum class TurtleMode { Abop, Lptg };

enum class WidthModel {
    Explicit,  // widths change only through '!'
    Taper,     // Heuer 2022, 5.3-5.5: every F on the trunk level multiplies the width by
               // trunk_taper, deeper levels by branch_taper; '!' still sets the width
    Pipe,      // Liebemann's (2017) pipe model on the finished skeleton (core/pipe_model.h)
};

struct TreeTemplate {
    std::string name;
    std::string description;
    std::string growth = "lsystem";  // the growth method (tree/growth.h) that makes the skeleton
    std::string grammar;             // the syntax of docs/grammar.md
    TurtleMode mode = TurtleMode::Abop;
    WidthModel width_model = WidthModel::Taper;
    TreeParams params;
    PartColors colors;
    // Where the template was read from, for error messages: the file, and the line of that
    // file on which the grammar's first line stands. Empty for built-in and edited templates
    // (errors then count the grammar's own lines).
    std::string source;
    int grammar_line = 1;
};

}  // namespace sylva
