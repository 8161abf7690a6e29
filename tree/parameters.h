// Every parameter a template can set, joined from the registry: the shared ones
// (core/tree_params.h) and each growth method's own (GrowthMethod::params, tree/growth.h).
// --set, template files, skeleton.json, batches, help text and the studio read and write
// parameters here, by key, so a method's new parameter needs no edit outside its table.
//
// Thread safety: reading is safe from any thread once the growth methods are registered
// (register_growth_method() after a read rebuilds the list, and must not race with one).
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "core/param_table.h"
#include "core/tree_params.h"

namespace sylva {

// The shared parameters first, then the wind's (core/wind_params.h), then each growth
// method's in registry order. Keys are unique.
const std::vector<ParamInfo>& param_infos();

// nullptr for an unknown key.
const ParamInfo* find_param(std::string_view key);

// Value of a parameter by key, as double (whole numbers, flags and choices too). nullopt for
// an unknown key.
std::optional<double> get_param(const TreeParams& params, std::string_view key);

// Sets a parameter from text ("key=value" style input): a number, a choice parameter's name
// of a choice (or its index), a flag's on/off, true/false (or 1/0). Throws InputError naming
// the key and its range for an unknown key, a non-number, NaN/inf, an out-of-range value or a
// fraction for a whole number.
void set_param(TreeParams& params, std::string_view key, std::string_view value);

// Sets a parameter from a number, with the same checks as set_param.
void set_param(TreeParams& params, std::string_view key, double value);

// Text of a parameter's value: a number, or a choice's name.
std::string param_text(const TreeParams& params, const ParamInfo& info);

// The text of a parameter's range: "0 to 1", or its choices "root, pasko".
std::string range_text(const ParamInfo& info);

}  // namespace sylva
