#include "tree/parameter_help.h"

#include <cstdio>
#include <sstream>
#include <stdexcept>

#include "tree/growth.h"
#include "tree/parameters.h"

namespace sylva {
namespace {

std::string number_text(double value) {
    char text[32];
    std::snprintf(text, sizeof text, "%g", value);
    return text;
}

std::string default_text(const ParamInfo& info) {
    if (!info.choices.empty())
        return std::string(info.choices[static_cast<size_t>(info.default_value)]);
    return number_text(info.default_value);
}

std::string range_of(const ParamInfo& info) {
    if (!info.choices.empty()) return range_text(info);
    if (info.flag) return "1 or 0";
    return number_text(info.min) + " to " + number_text(info.max);
}

// `text` in lines of at most `width` characters, the first after `first`, the others
// indented to line up under it.
std::string wrapped(const std::string& first, const std::string& text, std::size_t width) {
    std::string out = first, word;
    std::size_t column = first.size();
    const std::string indent(first.size(), ' ');
    std::istringstream words(text);
    bool line_start = true;
    while (words >> word) {
        if (!line_start && column + 1 + word.size() > width) {
            out += "\n" + indent;
            column = indent.size();
            line_start = true;
        }
        if (!line_start) {
            out += ' ';
            ++column;
        }
        out += word;
        column += word.size();
        line_start = false;
    }
    return out + "\n";
}

std::string reader(const ParamInfo& info) {
    return info.owner.empty() ? "every method" : std::string(info.owner);
}

}  // namespace

std::string parameter_help() {
    std::ostringstream out;
    out << "Growth methods (a template's growth = \"NAME\"):\n";
    for (const GrowthMethod* method : growth_methods()) {
        char name[64];
        std::snprintf(name, sizeof name, "  %-21s ", std::string(method->name).c_str());
        out << wrapped(name, std::string(method->description), 92);
    }
    out << "\nParameters (--set KEY=VALUE, a template's [params]; a method's own are marked):\n";
    for (ParamGroup group : param_groups()) {
        bool header = false;
        for (const ParamInfo& info : param_infos()) {
            if (info.group != group) continue;
            if (!header) out << " " << group_title(group) << "\n";
            header = true;
            char key[64];
            std::snprintf(key, sizeof key, "  %-21s ", std::string(info.key).c_str());
            out << wrapped(key,
                           (info.owner.empty() ? "" : std::string(info.owner) + ": ") +
                               std::string(info.help) + " (" + range_of(info) + "; default " +
                               default_text(info) + ")",
                           92);
        }
    }
    return out.str();
}

std::string parameter_reference_markdown() {
    std::ostringstream out;
    for (ParamGroup group : param_groups()) {
        bool header = false;
        for (const ParamInfo& info : param_infos()) {
            if (info.group != group) continue;
            if (!header) {
                out << (out.tellp() > 0 ? "\n" : "") << "### " << group_title(group) << "\n\n"
                    << "| key | read by | thesis | default | range | meaning |\n"
                    << "|---|---|---|---|---|---|\n";
                header = true;
            }
            out << "| " << info.key << " | " << reader(info) << " | " << info.symbol << " | "
                << default_text(info) << " | " << range_of(info) << " | " << info.help << " |\n";
        }
    }
    return out.str();
}

std::string parameters_doc(std::string_view doc) {
    const std::size_t begin = doc.find(kGeneratedBegin);
    const std::size_t end = doc.find(kGeneratedEnd);
    if (begin == std::string_view::npos || end == std::string_view::npos || end < begin)
        throw std::invalid_argument("the parameters' doc has no generated-text markers");
    const std::size_t body = begin + kGeneratedBegin.size();
    return std::string(doc.substr(0, body)) + "\n\n" + parameter_reference_markdown() + "\n" +
           std::string(doc.substr(end));
}

}  // namespace sylva
