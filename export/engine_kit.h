// The engine import kits (engine_kits/ in the source tree: godot3, godot4, unity, unreal),
// compiled into the binary and written beside an export on request (`--engine-kit DIR`):
// the scripts and shaders that turn Sylva's files into LODs, colliders and swaying trees in
// each engine. engine_kits/README.md says what each file does.
#pragma once

#include <filesystem>
#include <string_view>
#include <utility>
#include <vector>

#include "export/engine_profile.h"

namespace sylva {

class FileSet;

// Every kit file: (path below engine_kits/, e.g. "godot3/sylva_post_import.gd", contents).
const std::vector<std::pair<std::string_view, std::string_view>>& engine_kit_files();

// The files of `profile`'s kits (ProfileInfo::kits; generic: all of them), by path.
std::vector<std::pair<std::string_view, std::string_view>> engine_kit(EngineProfile profile);

// Adds `dir`/<kit>/<file> for each of `profile`'s kit files to `files` (core/file_set.h), so
// they land with the export they go with; creates the folders first. Throws IoError naming
// a folder that cannot be made.
void add_engine_kit(FileSet& files, const std::filesystem::path& dir, EngineProfile profile);

}  // namespace sylva
