// The one reader of input files: templates, grammars, species lists, ground plans, layout
// examples and grammars all come in through read_input_file(), so every file from a stranger
// gets the same checks before a byte of it is parsed.
//
// Only a regular file is read: a directory, device (/dev/zero), FIFO or socket is refused
// (a FIFO is opened without blocking, so a writer that never comes cannot hang Sylva). A
// file larger than the limit is refused before it is read.
#pragma once

#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

namespace sylva {

// The default size limit: 64 MiB, far above any template or plan Sylva ships (the largest
// is a few kilobytes) and small enough that a wrong file fails at once. The environment
// variable SYLVA_MAX_INPUT_MB overrides it for the process (a whole number of MiB >= 1).
inline constexpr std::uintmax_t kDefaultInputLimit = std::uintmax_t{64} << 20;

// The limit in force: SYLVA_MAX_INPUT_MB when set to a valid value, else the default.
std::uintmax_t input_size_limit();

// The whole file as bytes. `what` names the file's role in messages ("template", "species
// file"). Throws IoError (core/errors.h) naming the path when it does not exist, cannot be
// opened, is not a regular file or is larger than `max_bytes`. Thread-safe.
std::string read_input_file(const std::filesystem::path& path, std::string_view what,
                            std::uintmax_t max_bytes = input_size_limit());

}  // namespace sylva
