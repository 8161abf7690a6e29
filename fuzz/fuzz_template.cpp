// Fuzzes the template loader: parse a template file; a template it accepts must write back
// (template_file_text) to a text it reads again to the same grammar and parameters.
#include "fuzz_guard.h"
#include "tree/parameters.h"
#include "tree/template_file.h"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
    using namespace sylva;
    std::optional<TreeTemplate> tree;
    expect_only_input_errors(
        [&] { tree = parse_template_file(fuzz_text(data, size), "fuzz.toml"); });
    if (!tree) return 0;
    const std::string text = template_file_text(*tree);
    TreeTemplate again;
    try {
        again = parse_template_file(text, "again.toml");
    } catch (const std::exception& e) {
        std::fprintf(stderr, "sylva fuzz: written template does not read back: %s\n%s\n", e.what(),
                     text.c_str());
        std::abort();
    }
    if (again.grammar != tree->grammar || again.name != tree->name) {
        fuzz_finding("written template reads back with another grammar or name");
    }
    if (again.params.seed != tree->params.seed)
        fuzz_finding("written template reads back with another seed");
    for (const ParamInfo& info : param_infos())
        if (*get_param(again.params, info.key) != *get_param(tree->params, info.key))
            fuzz_finding("written template reads back with another parameter value");
    return 0;
}
