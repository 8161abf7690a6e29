// The parameters' reference, made from the registry (tree/parameters.h): the text
// `sylva --help` prints and the tables of docs/parameters.md, so a parameter's help is
// written once, in its table.
#pragma once

#include <string>

namespace sylva {

// The growth methods and every parameter, by group: key, who reads it, help, range and
// default, one line each (plain text for a terminal).
std::string parameter_help();

// The same as Markdown: a table per group (key, read by, thesis symbol, default, range,
// meaning), the body docs/parameters.md carries between its generated-text markers.
std::string parameter_reference_markdown();

}  // namespace sylva
