// What the layout tests share: examples and their grammars, derived once per test binary
// (deriving the larger examples takes a few hundred milliseconds, seconds under the
// sanitizers).
#pragma once

#include <map>
#include <memory>
#include <string>

#include "layout/derive.h"
#include "layout/examples.h"
#include "layout/generate.h"

namespace sylva::layout::testing {

inline Example example(const std::string& name) {
    return make_example(load_example(name));
}

inline const Grammar& grammar_of(const std::string& name) {
    static std::map<std::string, Grammar> cache;
    auto it = cache.find(name);
    if (it == cache.end()) it = cache.emplace(name, derive_grammar(example(name))).first;
    return it->second;
}

inline const GrowthTable& table_of(const std::string& name) {
    static std::map<std::string, std::unique_ptr<GrowthTable>> cache;
    auto& slot = cache[name];
    if (!slot) slot = std::make_unique<GrowthTable>(grammar_of(name));
    return *slot;
}

}  // namespace sylva::layout::testing
