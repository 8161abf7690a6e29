// An example tree for `sylva infer`: a skeleton read from a file another tool (or Sylva)
// wrote, checked so that every later stage can rely on one connected tree of finite,
// non-zero segments whose parents come before their children.
//
// Three formats come in through read_example_tree() (core/input_file.h reads the bytes):
// Sylva's skeleton.json (skeleton_json_reader.h), a cylinder list as laser-scan tools
// write it (cylinder_csv.h) and an OBJ of line segments (segment_obj.h).
#pragma once

#include <cstddef>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "core/skeleton.h"
#include "core/tree_params.h"

namespace sylva {

// A tree bigger than this is refused before any inference: a tree of a game asset has
// thousands of segments, a laser-scanned one tens of thousands; far more is a wrong file.
inline constexpr std::size_t kMaxExampleSegments = 200'000;

// Which axis of the file points up. Sylva is Y-up; laser-scan tools and most GIS data
// are Z-up (their Z becomes Sylva's Y, their Y Sylva's -Z).
enum class UpAxis { Y, Z };

struct ExampleTree {
    // Parents precede children, the first root starts at the origin, every segment has a
    // length and finite numbers. `depth` is the branch order the file gave, or -1 where
    // it gave none (the branch graph then finds the orders from the angles).
    Skeleton skeleton;
    std::optional<TreeParams> params;  // skeleton.json's "params"; none for other formats
    std::string format;                // "skeleton.json", "cylinder csv", "segment obj"
    // Things the reader changed or left out, for the fit report ("moved by (x, y, z) so the
    // root starts at the origin", "3 polygons kept as leaves are not regrown").
    std::vector<std::string> notes;
    // Per segment: where it stood in the file ("row 12", "segments[3]", "line 40"), for
    // messages of later stages.
    std::vector<std::string> places;
    // For each segment the segment its row continues on the same branch, when the file said
    // so (TreeQSM's "extension"); -1 where it did not say.
    std::vector<int> continuation;
};

// Reads the file and picks the format from its content: JSON with "format":
// "sylva-skeleton", an OBJ with `l` lines, or a delimited cylinder table. `up` applies to
// the CSV and OBJ formats (skeleton.json is Sylva's own, Y-up); nullopt takes Z for a
// cylinder table and Y for an OBJ. Throws IoError when the file cannot be read and
// InputError naming the file and the row, line or key at fault for bad content.
ExampleTree read_example_tree(const std::filesystem::path& path,
                              std::optional<UpAxis> up = std::nullopt);

// The same on text already read; `source` names it in messages.
ExampleTree parse_example_tree(std::string_view text, const std::string& source,
                               std::optional<UpAxis> up = std::nullopt);

// The checks every reader ends with, on a skeleton whose segments stand in `places`:
// at most kMaxExampleSegments segments, at least one, finite coordinates and radii, no
// zero-length segment, parents in range, no cycle, one connected tree (several roots only
// when they start at one point), then parents reordered before children and the first root
// moved to the origin. Throws InputError naming the place of the first bad segment.
void finish_example_tree(ExampleTree& tree, const std::string& source);

}  // namespace sylva
