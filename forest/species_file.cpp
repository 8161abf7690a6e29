#include "forest/species_file.h"

#include <algorithm>
#include <nlohmann/json.hpp>

#include "core/data_paths.h"
#include "core/errors.h"
#include "core/input_file.h"
#include "tree/parameters.h"
#include "tree/template_library.h"
#include "tree/template_setting.h"

namespace sylva::forest {

std::vector<Species> parse_species_json(const std::string& text, const std::string& source,
                                        const std::filesystem::path& folder) {
    nlohmann::json doc;
    try {
        doc = nlohmann::json::parse(text);
    } catch (const nlohmann::json::parse_error& e) {
        SourceLocation where{source, 1, 1};
        for (std::size_t i = 0; i + 1 < e.byte && i < text.size(); ++i) {
            if (text[i] == '\n') {
                ++where.line;
                where.column = 1;
            } else {
                ++where.column;
            }
        }
        throw InputError(std::string("invalid JSON: ") + e.what(), where);
    } catch (const nlohmann::json::exception& e) {
        // out_of_range 406, a number past any double (1e999), names the token but no byte.
        const std::string what = e.what();
        const std::size_t quote = what.find('\'');
        const std::string token =
            quote == std::string::npos ? "" : what.substr(quote + 1, what.rfind('\'') - quote - 1);
        SourceLocation where{source, 0, 0};
        if (const std::size_t at = token.empty() ? std::string::npos : text.find(token);
            at != std::string::npos) {
            const std::size_t line_start = text.rfind('\n', at);
            where.line = 1 + static_cast<int>(std::count(text.begin(), text.begin() + at, '\n'));
            where.column =
                1 + static_cast<int>(at - (line_start == std::string::npos ? 0 : line_start + 1));
        }
        throw InputError("a number no double can hold" + (token.empty() ? "" : ": " + token),
                         where);
    }
    if (!doc.is_object() || !doc.contains("species") || !doc["species"].is_array() ||
        doc["species"].empty())
        throw InputError(source + ": expected an object with a non-empty \"species\" array");
    std::vector<Species> species;
    for (std::size_t i = 0; i < doc["species"].size(); ++i) {
        const auto& entry = doc["species"][i];
        const std::string at = source + ": species[" + std::to_string(i) + "]";
        if (!entry.is_object() || !entry.contains("template") || !entry["template"].is_string())
            throw InputError(at + " needs a \"template\" (a name or a file)");
        Species sp{
            load_template_reference(entry["template"].get<std::string>(), folder, at + ".template"),
            1.0};
        if (entry.contains("weight")) {
            if (!entry["weight"].is_number()) throw InputError(at + ".weight must be a number");
            sp.weight = entry["weight"].get<double>();
        }
        if (entry.contains("set")) {
            if (!entry["set"].is_object())
                throw InputError(at + ".set must be an object of parameter values");
            for (const auto& [key, value] : entry["set"].items()) {
                try {
                    if (value.is_number())
                        set_template_value(sp.tree, key, value.get<double>());
                    else if (value.is_string())
                        set_template_value(sp.tree, key, value.get<std::string>());
                    else
                        throw InputError("must be a number or a choice's name");
                } catch (const InputError& e) {
                    throw InputError(at + ".set." + key + ": " + e.what());
                }
            }
        }
        species.push_back(std::move(sp));
    }
    return species;
}

std::vector<Species> load_species(const std::filesystem::path& path) {
    return parse_species_json(read_input_file(path, "species file"), path.string(),
                              data_folder(path));
}

}  // namespace sylva::forest
