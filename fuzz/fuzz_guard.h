// The contract every fuzz target checks: bad input raises InputError (GrammarError is one)
// or succeeds. Any other exception escaping is a finding: it is printed and the run aborts,
// so libFuzzer saves the input as a crash.
#pragma once

#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <exception>
#include <string_view>

#include "core/errors.h"

namespace sylva {

inline std::string_view fuzz_text(const std::uint8_t* data, std::size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

template <class Body>
void expect_only_input_errors(Body&& body) {
    try {
        body();
    } catch (const InputError&) {
        // The expected answer to bad input.
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sylva fuzz: unexpected exception: %s\n", e.what());
        std::abort();
    } catch (...) {
        std::fprintf(stderr, "sylva fuzz: unexpected non-std exception\n");
        std::abort();
    }
}

// A property of a successful run does not hold (e.g. a round trip).
[[noreturn]] inline void fuzz_finding(const char* what) {
    std::fprintf(stderr, "sylva fuzz: %s\n", what);
    std::abort();
}

}  // namespace sylva
