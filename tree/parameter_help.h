// The parameters' reference, made from the registry (tree/parameters.h): the text
// `sylva --help` prints and the tables of docs/parameters.md, so a parameter's help is
// written once, in its table.
#pragma once

#include <string>
#include <string_view>

namespace sylva {

// The growth methods and every parameter, by group: key, who reads it, help, range and
// default, one line each (plain text for a terminal).
std::string parameter_help();

// The same as Markdown: a table per group (key, read by, thesis symbol, default, range,
// meaning), the body docs/parameters.md carries between its generated-text markers.
std::string parameter_reference_markdown();

// The markers around that body in docs/parameters.md.
inline constexpr std::string_view kGeneratedBegin =
    "<!-- generated from the parameter tables by sylva-param-docs: do not edit below -->";
inline constexpr std::string_view kGeneratedEnd = "<!-- end of the generated tables -->";

// `doc` (the text of docs/parameters.md) with parameter_reference_markdown() between the
// markers; the text outside them is kept. Throws std::invalid_argument when a marker is
// missing.
std::string parameters_doc(std::string_view doc);

}  // namespace sylva
