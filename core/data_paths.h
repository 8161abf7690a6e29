// Paths and names that come from data files. A template, species list or plan is a file
// from a stranger: what it names must never lead Sylva outside the folder the user pointed
// at, neither to read (a species list naming "/etc/shadow") nor to write (a template named
// "../../escaped" in a batch's file names).
//
// Reading: a file a data file names is looked up relative to the folder of the file that
// names it, never absolute, never through "..", never through a link that leads out of
// that folder. Writing: a file name built from data keeps only a safe alphabet.
#pragma once

#include <filesystem>
#include <string>
#include <string_view>

namespace sylva {

// The path of `name` (as written in a data file) inside `folder`, the folder of the file
// that names it. `where` says where the name was written, for messages ("plan.json:
// species[2].template"). Throws InputError (core/errors.h) when the name is empty, holds a
// NUL, is absolute, has a ".." component or leads outside `folder` through a symbolic link,
// or when `folder` is empty (text that came from no file may name no file). Does not check
// that the file exists: read it with read_input_file() (core/input_file.h), which refuses
// devices, FIFOs and sockets. Thread-safe.
std::filesystem::path resolve_data_reference(std::string_view name,
                                             const std::filesystem::path& folder,
                                             std::string_view where);

// The folder a data file's references are looked up in: the file's own folder ("." for a
// bare file name).
std::filesystem::path data_folder(const std::filesystem::path& file);

// `name` made a safe file name: letters, digits, '-' and '_' kept, '.' kept only between
// two letters or digits ("oak.v2"), every other run of bytes one '_' inside the name and
// none at its ends; at most 64 bytes; `fallback` when nothing is left. No result holds a
// '/', starts with a '.' or is "." or "..". The same name always gives the same result.
std::string safe_file_name(std::string_view name, std::string_view fallback = "tree");

}  // namespace sylva
