// The error types the CLI and GUI catch at their boundary. Each carries a message a person
// can act on; the CLI maps them to SPEC exit codes (InputError 3, IoError 4).
#pragma once

#include <stdexcept>

namespace sylva {

// Bad input: a template, a parameter, a file's contents. (Grammar errors have their own
// type in turtle/, GrammarError, and count as bad input too.)
struct InputError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

// A file could not be read or written; the message names the path and the reason.
struct IoError : std::runtime_error {
    using std::runtime_error::runtime_error;
};

}  // namespace sylva
