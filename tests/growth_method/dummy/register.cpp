// The one registration line: the method joins the registry before main() runs.
#include "tests/growth_method/dummy/dummy_growth.h"
#include "tree/growth.h"

namespace {
[[maybe_unused]] const bool registered =
    (sylva::register_growth_method(sylva::dummy::dummy_growth), true);
}  // namespace
