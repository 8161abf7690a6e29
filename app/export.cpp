#include "app/export.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "app/atomic_file.h"
#include "app/errors.h"
#include "app/glb_writer.h"
#include "app/obj_writer.h"
#include "app/ply_writer.h"

namespace sylva {
namespace {

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

ExportFormat resolve(const std::filesystem::path& path, std::optional<ExportFormat> format) {
    if (format) return *format;
    if (auto by_extension = format_from_extension(path)) return *by_extension;
    throw InputError("cannot tell the format of '" + path.string() + "' from its extension '" +
                     path.extension().string() + "': use .obj, .glb or .ply");
}

}  // namespace

std::optional<ExportFormat> format_from_extension(const std::filesystem::path& path) {
    const std::string ext = lower(path.extension().string());
    if (ext.empty()) return std::nullopt;
    return format_from_name(std::string_view(ext).substr(1));
}

std::optional<ExportFormat> format_from_name(std::string_view name) {
    const std::string n = lower(name);
    if (n == "obj") return ExportFormat::Obj;
    if (n == "glb") return ExportFormat::Glb;
    if (n == "ply") return ExportFormat::Ply;
    return std::nullopt;
}

std::string_view format_extension(ExportFormat format) {
    switch (format) {
        case ExportFormat::Obj:
            return ".obj";
        case ExportFormat::Glb:
            return ".glb";
        case ExportFormat::Ply:
            return ".ply";
    }
    return "";
}

std::vector<std::filesystem::path> write_model(const std::filesystem::path& path,
                                               const std::vector<NamedMesh>& parts,
                                               const ExportOptions& options,
                                               std::optional<ExportFormat> format) {
    switch (resolve(path, format)) {
        case ExportFormat::Obj:
            return write_obj_with_mtl(path, parts, options);
        case ExportFormat::Glb:
            write_glb(path, parts, options);
            return {path};
        case ExportFormat::Ply:
            write_ply(path, parts, options);
            return {path};
    }
    return {};
}

std::vector<std::filesystem::path> lod_file_names(const std::filesystem::path& path,
                                                  std::size_t levels, ExportFormat format) {
    if (format == ExportFormat::Glb) return {path};
    std::vector<std::filesystem::path> names;
    for (std::size_t i = 0; i < levels; ++i) {
        std::filesystem::path level = path;
        level.replace_filename(path.stem().string() + "_LOD" + std::to_string(i) +
                               path.extension().string());
        names.push_back(level);
    }
    return names;
}

std::vector<std::filesystem::path> write_lod_chain(
    const std::filesystem::path& path, const std::vector<std::vector<NamedMesh>>& levels,
    const ExportOptions& options, std::optional<ExportFormat> format) {
    const ExportFormat f = resolve(path, format);
    if (f == ExportFormat::Glb) {
        write_glb_lods(path, levels, options);
        return {path};
    }
    const std::vector<std::filesystem::path> names = lod_file_names(path, levels.size(), f);
    std::vector<std::filesystem::path> written;
    if (f == ExportFormat::Obj) {
        // One material library for all levels: the materials are the same.
        std::filesystem::path mtl = path;
        mtl.replace_extension(".mtl");
        std::vector<NamedMesh> all_parts;
        for (const auto& level : levels)
            for (const NamedMesh& part : level)
                if (part.mesh && !part.mesh->triangles.empty() &&
                    std::none_of(all_parts.begin(), all_parts.end(),
                                 [&](const NamedMesh& p) { return p.name == part.name; }))
                    all_parts.push_back(part);
        write_file_atomically(mtl, [&](std::ostream& out) { write_mtl(out, all_parts); });
        written.push_back(mtl);
        for (std::size_t i = 0; i < levels.size(); ++i) {
            write_file_atomically(names[i], [&](std::ostream& out) {
                write_obj_with_mtl(out, levels[i], options, mtl.filename().string());
            });
            written.push_back(names[i]);
        }
        return written;
    }
    for (std::size_t i = 0; i < levels.size(); ++i) {
        write_ply(names[i], levels[i], options);
        written.push_back(names[i]);
    }
    return written;
}

}  // namespace sylva
