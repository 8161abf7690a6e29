// Fuzzes the forest's species list reader (a file artists share): any bytes give a list or
// an InputError. Text that comes from no file may name built-in templates only, so no input
// can make it read a file.
#include "forest/species_file.h"
#include "fuzz_guard.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    expect_only_input_errors([&] {
        const auto species =
            forest::parse_species_json(std::string(fuzz_text(data, size)), "fuzz.json");
        if (species.empty()) fuzz_finding("a species list was read with no species");
    });
    return 0;
}
