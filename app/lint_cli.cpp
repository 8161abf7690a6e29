#include "app/lint_cli.h"

#include <string>

#include "core/errors.h"
#include "tree/organ_surfaces.h"
#include "tree/template_file.h"
#include "tree/template_library.h"
#include "turtle/lint.h"
#include "turtle/lsystem_growth.h"

namespace sylva {
namespace {

// Where warnings point: the template's file and the file's line of the grammar's first
// line. A built-in template points into its templates/NAME.toml (it was read from there).
struct GrammarPlace {
    std::string file;
    int first_line = 1;
};

GrammarPlace grammar_place(const TreeTemplate& tree) {
    if (!tree.source.empty()) return {tree.source, tree.grammar_line};
    const std::string_view text = builtin_template_text(tree.name);
    if (!text.empty()) {
        const std::string file = "templates/" + tree.name + ".toml";
        const TreeTemplate parsed = parse_template_file(text, file);
        // An edited copy of a built-in template has other lines: its own text it is then.
        if (parsed.grammar == tree.grammar) return {file, parsed.grammar_line};
    }
    return {tree.name.empty() ? "grammar" : tree.name, 1};
}

}  // namespace

std::size_t print_lint(const TreeTemplate& tree, std::FILE* to) {
    if (tree.growth != lsystem_growth.name) return 0;
    const GrammarPlace place = grammar_place(tree);
    std::vector<LintWarning> warnings;
    try {
        warnings = lint_grammar(tree.grammar, param_constants(tree.params), organ_surface_names());
    } catch (InputError& e) {
        e.relocate(place.file, place.first_line);
        throw;
    }
    for (const LintWarning& w : warnings)
        std::fprintf(to, "%s:%d:%d: warning: %s\n", place.file.c_str(),
                     place.first_line + w.line - 1, w.column, w.message.c_str());
    return warnings.size();
}

int run_lint(const TreeTemplate& tree) {
    const std::size_t n = print_lint(tree, stdout);
    std::fprintf(stderr, "%zu warning%s\n", n, n == 1 ? "" : "s");
    return 0;
}

}  // namespace sylva
