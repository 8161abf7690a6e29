// The impostor flags of `sylva export` (--impostor, --impostor-kind, --impostor-size,
// --impostor-views, --impostor-quads; docs/impostors.md) and the lines the export prints
// about the far levels.
#pragma once

#include <cstddef>
#include <functional>
#include <stdexcept>
#include <string>

#include "export/export_options.h"

namespace sylva {

// Reads `arg` (and its value through `value`) into `options`. False when `arg` is no
// impostor flag. Throws std::invalid_argument with a message for the user on a bad value
// (the CLI turns it into a usage error, exit 2); rethrows what `value` throws.
bool parse_impostor_flag(const std::string& arg, const std::function<std::string()>& value,
                         ImpostorOptions& options);

// "  LOD<i>: octahedral impostor, ..." for each far level appended after `levels` levels of
// the tree; nothing without an impostor. `layout` is what write_tree() said the automatic
// layout chose.
void print_far_levels(const ImpostorOptions& options, std::size_t levels,
                      const std::string& layout);

}  // namespace sylva
