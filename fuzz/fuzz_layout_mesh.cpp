// The layout readers (layout/polygon_mesh.h): the same bytes go to the .mesh reader and the
// JSON reader. Bad input must raise InputError; a structure either reader accepts must give
// an angle graph that, when connected, passes the planarity test of angle_graph.h (the
// reader's geometric checks and the graph's turning test agree).
#include <cstdint>

#include "fuzz_guard.h"
#include "layout/angle_graph.h"
#include "layout/polygon_mesh.h"

namespace {

using namespace sylva;

void check(const layout::PolygonMesh& mesh) {
    const layout::Example ex = layout::make_example(mesh);
    const layout::Analysis a = layout::analyze(ex.graph, ex.dirs);
    if (!a.planar && a.why != "not connected") {
        std::fprintf(stderr, "sylva fuzz: accepted input is not planar: %s\n", a.why.c_str());
        fuzz_finding("the reader and the planarity test disagree");
    }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    if (size > 64 * 1024) return 0;  // the pairwise checks are quadratic
    const std::string_view text = fuzz_text(data, size);
    expect_only_input_errors([&] { check(layout::read_mesh_text(text, "fuzz.mesh")); });
    expect_only_input_errors([&] { check(layout::read_mesh_json(text, "fuzz.json")); });
    return 0;
}
