// The readers of `sylva infer` (infer/example_tree.h: skeleton.json, cylinder tables, OBJ
// line segments) on the same bytes, Z-up and Y-up. An accepted tree must satisfy what the
// readers promise (parents before children, finite, non-zero segments, the root at the
// origin), and a small one must infer a template whose text reads back.
#include <cmath>
#include <glm/geometric.hpp>

#include "fuzz_guard.h"
#include "infer/example_tree.h"
#include "infer/rule_inference.h"
#include "tree/template_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    const std::string_view text = fuzz_text(data, size);
    for (UpAxis up : {UpAxis::Z, UpAxis::Y}) {
        expect_only_input_errors([&] {
            const ExampleTree tree = parse_example_tree(text, "fuzz", up);
            const auto& segments = tree.skeleton.segments;
            if (segments.empty() || segments.size() > kMaxExampleSegments)
                fuzz_finding("an accepted tree has no or too many segments");
            if (glm::length(segments.front().a) > 1e-3f)
                fuzz_finding("the root is not at the origin");
            for (std::size_t i = 0; i < segments.size(); ++i) {
                if (segments[i].parent >= static_cast<int>(i))
                    fuzz_finding("a parent after its child");
                if (!(glm::length(segments[i].b - segments[i].a) > 0.0f))
                    fuzz_finding("a segment without length");
            }
            if (segments.size() <= 500) {
                const InferredTemplate inferred = infer_template(tree);
                if (parse_template_file(inferred.text, "inferred").grammar != inferred.tree.grammar)
                    fuzz_finding("the inferred template does not read back");
            }
        });
    }
    return 0;
}
