#include "app/impostor_cli.h"

#include <charconv>
#include <cstdio>
#include <stdexcept>

namespace sylva {
namespace {

int whole_number(const std::string& flag, const std::string& text, int lo, int hi) {
    int value = 0;
    auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
    if (error != std::errc() || end != text.data() + text.size() || text.empty() || value < lo ||
        value > hi)
        throw std::invalid_argument(flag + " expects a whole number from " + std::to_string(lo) +
                                    " to " + std::to_string(hi) + ", not '" + text + "'");
    return value;
}

}  // namespace

bool parse_impostor_flag(const std::string& arg, const std::function<std::string()>& value,
                         ImpostorOptions& options) {
    if (arg == "--impostor") {
        if (options.kind == ImpostorKind::None) options.kind = ImpostorKind::Octahedral;
    } else if (arg == "--impostor-kind") {
        const std::string name = value();
        if (name == "octahedral")
            options.kind = ImpostorKind::Octahedral;
        else if (name == "billboard")
            options.kind = ImpostorKind::Billboard;
        else if (name == "both")
            options.kind = ImpostorKind::Both;
        else
            throw std::invalid_argument(
                "--impostor-kind expects octahedral, billboard or both, not '" + name + "'");
    } else if (arg == "--impostor-size") {
        const std::string size = value();  // auto: chosen per tree (impostor/impostor_layout.h)
        options.size = size == "auto" ? 0 : whole_number(arg, size, 64, 8192);
    } else if (arg == "--impostor-views") {
        options.views = whole_number(arg, value(), 2, 32);
    } else if (arg == "--impostor-quads") {
        options.billboard_quads = whole_number(arg, value(), 2, 3);
    } else {
        return false;
    }
    return true;
}

void print_far_levels(const ImpostorOptions& options, std::size_t levels,
                      const std::string& layout) {
    const ImpostorKind kind = options.kind;
    if (kind == ImpostorKind::None) return;
    if (kind == ImpostorKind::Billboard || kind == ImpostorKind::Both)
        std::printf("  LOD%zu: billboard, %d crossed quads\n", levels++, options.billboard_quads);
    if (kind == ImpostorKind::Octahedral || kind == ImpostorKind::Both) {
        if (options.size == 0) {
            std::printf("  LOD%zu: octahedral impostor, %s\n", levels, layout.c_str());
            return;
        }
        const int tile = options.size / options.views;
        std::printf("  LOD%zu: octahedral impostor, %d x %d views of %d px (a %d px atlas)\n",
                    levels, options.views, options.views, tile, tile * options.views);
    }
}

}  // namespace sylva
