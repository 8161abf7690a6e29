#include "tree/parameters.h"

#include <charconv>
#include <cmath>
#include <map>
#include <sstream>

#include "core/errors.h"
#include "core/wind_params.h"
#include "tree/growth.h"

namespace sylva {
namespace {

struct Location {
    const ParamTable* table;
    std::size_t index;
};

struct Registry {
    std::size_t methods = 0;  // growth methods it was built from
    std::vector<ParamInfo> infos;
    std::vector<Location> where;
    std::map<std::string_view, std::size_t, std::less<>> by_key;
};

Registry build() {
    Registry r;
    auto add = [&](const ParamTable& table) {
        for (std::size_t i = 0; i < table.infos().size(); ++i) {
            r.by_key.emplace(table.infos()[i].key, r.infos.size());
            r.infos.push_back(table.infos()[i]);
            r.where.push_back({&table, i});
        }
    };
    add(shared_param_table());
    add(wind_param_table());
    for (const GrowthMethod* method : growth_methods())
        if (method->params) add(method->params());
    r.methods = growth_methods().size();
    return r;
}

const Registry& registry() {
    static Registry r = build();
    if (r.methods != growth_methods().size()) r = build();  // a method registered since
    return r;
}

std::optional<std::size_t> index_of(std::string_view key) {
    const Registry& r = registry();
    const auto found = r.by_key.find(key);
    if (found == r.by_key.end()) return std::nullopt;
    return found->second;
}

std::size_t known_index(std::string_view key) {
    if (const std::optional<std::size_t> index = index_of(key)) return *index;
    std::string known;
    for (const ParamInfo& info : registry().infos)
        known += (known.empty() ? "" : ", ") + std::string(info.key);
    throw InputError("unknown parameter '" + std::string(key) + "' (known: " + known + ")");
}

}  // namespace

const std::vector<ParamInfo>& param_infos() {
    return registry().infos;
}

const ParamInfo* find_param(std::string_view key) {
    const std::optional<std::size_t> index = index_of(key);
    return index ? &registry().infos[*index] : nullptr;
}

std::optional<double> get_param(const TreeParams& params, std::string_view key) {
    const std::optional<std::size_t> index = index_of(key);
    if (!index) return std::nullopt;
    const Location& at = registry().where[*index];
    return at.table->get(params, at.index);
}

std::string range_text(const ParamInfo& info) {
    std::ostringstream out;
    if (!info.choices.empty()) {
        for (size_t i = 0; i < info.choices.size(); ++i) out << (i ? ", " : "") << info.choices[i];
        return out.str();
    }
    out << info.min << " to " << info.max;
    return out.str();
}

void set_param(TreeParams& params, std::string_view key, double value) {
    const std::size_t index = known_index(key);
    const ParamInfo& info = registry().infos[index];
    // The shortest text that reads back as `value`: 10.0000000001 is not shown as "10".
    char digits[32];
    const std::string shown(digits, std::to_chars(digits, digits + sizeof digits, value).ptr);
    if (!std::isfinite(value) || value < info.min || value > info.max)
        throw InputError("parameter " + std::string(key) + " = " + shown + " is out of range " +
                         range_text(info));
    if (info.integer && value != std::floor(value))
        throw InputError("parameter " + std::string(key) + " must be a whole number, not " + shown);
    const Location& at = registry().where[index];
    at.table->set(params, at.index, value);
}

void set_param(TreeParams& params, std::string_view key, std::string_view text) {
    const ParamInfo& info = registry().infos[known_index(key)];
    for (size_t i = 0; i < info.choices.size(); ++i)
        if (info.choices[i] == text) return set_param(params, key, static_cast<double>(i));
    if (info.flag) {
        if (text == "on" || text == "true") return set_param(params, key, 1.0);
        if (text == "off" || text == "false") return set_param(params, key, 0.0);
    }
    double value = 0.0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty())
        throw InputError("parameter " + std::string(key) + ": '" + std::string(text) + "' is not " +
                         (info.choices.empty() ? "a number" : "one of the choices") + " (" +
                         range_text(info) + ")");
    set_param(params, key, value);
}

std::string param_text(const TreeParams& params, const ParamInfo& info) {
    double value = *get_param(params, info.key);
    if (!info.choices.empty()) return std::string(info.choices[static_cast<size_t>(value)]);
    std::ostringstream out;
    out << value;
    return out.str();
}

}  // namespace sylva
