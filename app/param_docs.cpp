// sylva-param-docs FILE: rewrites the generated tables of docs/parameters.md (between its
// markers) from the parameter registry, keeping the prose around them. scripts/docs runs it;
// tests/tree checks the committed file matches. Exit codes: 0 written or unchanged, 2 usage,
// 4 the file cannot be read or written.
#include <cstdio>
#include <exception>
#include <fstream>
#include <sstream>
#include <string>

#include "core/atomic_file.h"
#include "tree/parameter_help.h"

int main(int argc, char** argv) {
    if (argc != 2) {
        std::fprintf(stderr, "usage: sylva-param-docs docs/parameters.md\n");
        return 2;
    }
    try {
        std::ifstream in(argv[1], std::ios::binary);
        if (!in) throw std::runtime_error(std::string("cannot read ") + argv[1]);
        std::ostringstream text;
        text << in.rdbuf();
        const std::string updated = sylva::parameters_doc(text.str());
        if (updated == text.str()) return 0;
        sylva::write_file_atomically(argv[1], [&](std::ostream& out) { out << updated; });
        std::printf("wrote %s\n", argv[1]);
        return 0;
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sylva-param-docs: %s\n", e.what());
        return 4;
    }
}
