// docs/parameters.md carries the tables the parameter registry makes: a parameter added,
// moved or reworded in its table without `scripts/docs` fails here.
#include <gtest/gtest.h>

#include <string>

#include "tests/helpers.h"
#include "tree/parameter_help.h"
#include "tree/parameters.h"

namespace sylva {
namespace {

std::string committed_doc() {
    return test::read_file(std::string(SYLVA_SOURCE_DIR) + "/docs/parameters.md");
}

TEST(ParameterDocs, TheCommittedTablesAreTheRegistrysOwn) {
    const std::string doc = committed_doc();
    ASSERT_FALSE(doc.empty());
    EXPECT_TRUE(parameters_doc(doc) == doc)
        << "docs/parameters.md is stale: run scripts/docs (or build/app/sylva-param-docs "
           "docs/parameters.md) and commit it";
}

TEST(ParameterDocs, EveryParameterHasARow) {
    const std::string tables = parameter_reference_markdown();
    for (const ParamInfo& info : param_infos())
        EXPECT_NE(tables.find("| " + std::string(info.key) + " |"), std::string::npos) << info.key;
}

}  // namespace
}  // namespace sylva
