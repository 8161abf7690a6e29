#include "export/export.h"

#include <algorithm>
#include <cctype>
#include <string>

#include "core/errors.h"
#include "core/file_set.h"
#include "core/name_list.h"
#include "export/fbx_writer.h"
#include "export/glb_writer.h"
#include "export/obj_writer.h"
#include "export/ply_writer.h"

namespace sylva {
namespace {

// The registry: one line per format.
const ExportFormat* const kFormats[] = {
    &obj_format,
    &glb_format,
    &ply_format,
    &fbx_format,
};

std::string lower(std::string_view text) {
    std::string out(text);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

const ExportFormat& resolve(const std::filesystem::path& path, const ExportFormat* format) {
    if (format) return *format;
    if (const ExportFormat* by_extension = format_from_extension(path)) return *by_extension;
    throw InputError("cannot tell the format of '" + path.string() + "' from its extension '" +
                     path.extension().string() + "': use " + name_list(format_extensions()));
}

}  // namespace

std::vector<std::filesystem::path> lod_file_names(const std::filesystem::path& path,
                                                  std::size_t levels) {
    std::vector<std::filesystem::path> names;
    for (std::size_t i = 0; i < levels; ++i) {
        std::filesystem::path level = path;
        level.replace_filename(path.stem().string() + "_LOD" + std::to_string(i) +
                               path.extension().string());
        names.push_back(level);
    }
    return names;
}

std::filesystem::path texture_file_name(const std::filesystem::path& path, std::string_view texture,
                                        std::string_view map) {
    std::filesystem::path file = path;
    file.replace_filename(path.stem().string() + "_" + std::string(texture) + "_" +
                          std::string(map) + ".png");
    return file;
}

std::span<const ExportFormat* const> export_formats() {
    return kFormats;
}

std::span<const std::string_view> format_extensions() {
    static const std::vector<std::string_view> extensions = [] {
        std::vector<std::string_view> out;
        for (const ExportFormat* f : kFormats) out.push_back(f->extension);
        return out;
    }();
    return extensions;
}

const ExportFormat* format_from_extension(const std::filesystem::path& path) {
    const std::string ext = lower(path.extension().string());
    for (const ExportFormat* f : kFormats)
        if (f->extension == ext) return f;
    return nullptr;
}

const ExportFormat* format_from_name(std::string_view name) {
    const std::string n = lower(name);
    for (const ExportFormat* f : kFormats)
        if (f->name == n) return f;
    return nullptr;
}

std::vector<std::filesystem::path> write_model(const std::filesystem::path& path,
                                               const ModelParts& parts,
                                               const ExportOptions& options,
                                               const ExportFormat* format) {
    return write_lod_chain(path, {parts}, options, format);
}

std::vector<std::filesystem::path> write_lod_chain(const std::filesystem::path& path,
                                                   const std::vector<ModelParts>& levels,
                                                   const ExportOptions& options,
                                                   const ExportFormat* format,
                                                   const std::function<void(FileSet&)>& extra) {
    const ExportFormat& chosen = resolve(path, format);
    // Siblings (an .mtl, the other levels) go beside the file a symlink at `path` points to.
    FileSet files;
    const std::filesystem::path target = output_target(path);
    chosen.write(files, target, levels, options);
    for (const ExportOptions::Sidecar& sidecar : options.sidecars) {
        std::filesystem::path file = target;
        file.replace_filename(target.stem().string() + sidecar.suffix);
        files.add(file, [&sidecar](std::ostream& out) { out << sidecar.text; });
    }
    if (extra) extra(files);
    return files.commit();
}

std::string format_names() {
    static const std::vector<std::string_view> names = [] {
        std::vector<std::string_view> out;
        for (const ExportFormat* f : kFormats) out.push_back(f->name);
        return out;
    }();
    return name_list(names);
}

}  // namespace sylva
