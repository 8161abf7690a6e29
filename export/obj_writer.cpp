#include "export/obj_writer.h"

#include <algorithm>
#include <charconv>
#include <map>
#include <system_error>

#include "core/atomic_file.h"
#include "core/file_set.h"
#include "export/mesh_normals.h"

namespace sylva {
namespace {

void append_number(std::string& line, float value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    line.push_back(' ');
    line.append(buffer, result.ptr);
}

void append_digits(std::string& line, std::size_t value) {
    char buffer[24];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    line.append(buffer, result.ptr);
}

void append_index(std::string& line, std::size_t value) {
    line.push_back(' ');
    append_digits(line, value);
}

void append_vector(std::string& line, const char* tag, const glm::vec3& v) {
    line.assign(tag);
    append_number(line, v.x);
    append_number(line, v.y);
    append_number(line, v.z);
    line.push_back('\n');
}

bool has_triangles(const NamedMesh& part) {
    return part.mesh && !part.mesh->triangles.empty();
}

// An object of bare geometry (positions and faces, no material); `base` is the first
// vertex's 1-based index and moves past the part's vertices.
void write_bare_part(std::ostream& out, const NamedMesh& part, float scale, std::size_t& base) {
    std::string line;
    out << "o " << part.name << "\ng " << part.name << "\n";
    for (const glm::vec3& p : part.mesh->positions) {
        append_vector(line, "v", scale * p);
        out << line;
    }
    for (const auto& t : part.mesh->triangles) {
        line.assign("f");
        for (std::uint32_t i : t) append_index(line, base + i);
        line.push_back('\n');
        out << line;
    }
    base += part.mesh->positions.size();
}

}  // namespace

void write_obj(std::ostream& out, const std::vector<NamedMesh>& parts) {
    out << "# Sylva low-poly tree: Y up, meters\n";
    std::size_t base = 1;  // OBJ indices are 1-based and global across groups
    for (const NamedMesh& part : parts) write_bare_part(out, part, 1.0f, base);
}

void write_obj(const std::filesystem::path& path, const std::vector<NamedMesh>& parts) {
    write_file_atomically(path, [&](std::ostream& out) { write_obj(out, parts); });
}

void write_obj_with_mtl(std::ostream& out, const std::vector<NamedMesh>& parts,
                        const ExportOptions& options, std::string_view mtl_file_name,
                        std::string_view group_suffix) {
    const float scale = profile_info(options.profile).unitless_scale;
    out << "# Sylva low-poly tree: Y up, " << (scale == 1.0f ? "meters" : "centimeters") << ", "
        << (options.shading == Shading::Flat ? "flat" : "smooth") << " normals\n";
    out << "mtllib " << mtl_file_name << "\n";
    std::size_t vertex_base = 1, normal_base = 1, uv_base = 1;  // 1-based, global across groups
    std::string line;
    for (const NamedMesh& part : parts) {
        if (!has_triangles(part)) continue;
        const Mesh& mesh = *part.mesh;
        if (part.collision) {  // bare geometry, no material, never a LOD suffix
            write_bare_part(out, part, scale, vertex_base);
            continue;
        }
        const PartAttributes* attributes = part.attributes;
        const bool flat = options.shading == Shading::Flat;
        // Smooth: OBJ indexes normals apart from positions, so the vertices stay shared (the
        // part stays closed) and only the normals split at creases. UVs likewise: `vt` per
        // distinct corner UV, so seams split no vertex.
        const ShadedMesh shaded = flat ? ShadedMesh{} : smooth_shaded(mesh, options.crease_degrees);
        const std::string group = part.name + std::string(group_suffix);
        out << "o " << group << "\ng " << group << "\nusemtl " << material_name(part) << "\n"
            << (flat ? "s off\n" : "s 1\n");
        const bool tinted = attributes && !attributes->tint.empty();
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            append_vector(line, "v", scale * mesh.positions[i]);
            if (tinted) {  // the common `v x y z r g b` extension: linear RGB, like Kd
                line.pop_back();
                const glm::vec3 c = part.color * attributes->tint[i];
                append_number(line, c.r);
                append_number(line, c.g);
                append_number(line, c.b);
                line.push_back('\n');
            }
            out << line;
        }
        const std::vector<glm::vec3> normals = flat ? face_normals(mesh) : shaded.normals;
        for (const glm::vec3& n : normals) {
            append_vector(line, "vn", n);
            out << line;
        }
        const bool with_uv = attributes && !attributes->uv.empty();
        std::vector<std::array<std::size_t, 3>> uv_index(with_uv ? mesh.triangles.size() : 0);
        std::size_t uv_count = 0;
        if (with_uv) {
            std::map<std::pair<float, float>, std::size_t> known;
            for (std::size_t f = 0; f < mesh.triangles.size(); ++f)
                for (std::size_t k = 0; k < 3; ++k) {
                    const glm::vec2 uv = attributes->uv[f][k];
                    auto [it, added] = known.try_emplace({uv.x, uv.y}, known.size());
                    if (added) {
                        line.assign("vt");
                        append_number(line, uv.x);
                        append_number(line, uv.y);
                        line.push_back('\n');
                        out << line;
                    }
                    uv_index[f][k] = it->second;
                }
            uv_count = known.size();
        }
        for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
            line.assign("f");
            for (std::size_t k = 0; k < 3; ++k) {
                append_index(line, vertex_base + mesh.triangles[f][k]);  // " v/vt/vn" or " v//vn"
                line.push_back('/');
                if (with_uv) append_digits(line, uv_base + uv_index[f][k]);
                line.push_back('/');
                append_digits(line, normal_base + (flat ? f : shaded.mesh.triangles[f][k]));
            }
            line.push_back('\n');
            out << line;
        }
        vertex_base += mesh.positions.size();
        normal_base += normals.size();
        uv_base += uv_count;
    }
}

void write_mtl(std::ostream& out, const std::vector<NamedMesh>& parts, std::string_view texture,
               const std::filesystem::path& model_path) {
    out << "# Sylva materials: Kd is the part's base colour, linear RGB\n";
    std::string line;
    for (const NamedMesh& part : parts) {
        if (!has_triangles(part) || part.collision) continue;
        out << "\nnewmtl " << material_name(part) << "\n";
        if (part.textures) {  // alpha-tested images: the map's alpha is the cut-out
            const PartTextures& t = *part.textures;
            const std::string albedo =
                texture_file_name(model_path, t.name, "albedo").filename().string();
            out << "Ka 0 0 0\nKd 1 1 1\nKs 0 0 0\nNs 10\nd 1\nillum 1\nmap_Kd " << albedo
                << "\nmap_d " << albedo << "\n";
            if (!t.normal_png.empty())
                out << "norm "
                    << texture_file_name(model_path, t.name, "normal").filename().string() << "\n";
            continue;
        }
        out << "Ka 0 0 0\n";
        append_vector(line, "Kd", texture.empty() ? part.color : glm::vec3(1.0f));
        out << line;
        out << "Ks 0 0 0\nNs 10\nd 1\nillum 1\n";
        if (!texture.empty()) out << "map_Kd " << texture << "\n";
    }
}

namespace {

// With a palette: `<stem>_palette.png` beside `path`, added to `files`; its file name for
// the .mtl (empty without a palette).
std::string add_palette(FileSet& files, const std::filesystem::path& path,
                        const ExportOptions& options) {
    if (options.palette_png.empty()) return {};
    std::filesystem::path png = path;
    png.replace_filename(path.stem().string() + "_palette.png");
    const std::vector<std::uint8_t>& bytes = options.palette_png;
    files.add(png, [&bytes](std::ostream& out) {
        out.write(reinterpret_cast<const char*>(bytes.data()),
                  static_cast<std::streamsize>(bytes.size()));
    });
    return png.filename().string();
}

// The PNGs of every part with textures (once each), beside `path` as texture_file_name()
// names them.
void add_part_textures(FileSet& files, const std::filesystem::path& path,
                       const std::vector<ModelParts>& levels) {
    std::vector<const PartTextures*> done;
    auto add = [&](const std::string& name, std::string_view map,
                   const std::vector<std::uint8_t>& bytes) {
        files.add(texture_file_name(path, name, map), [&bytes](std::ostream& out) {
            out.write(reinterpret_cast<const char*>(bytes.data()),
                      static_cast<std::streamsize>(bytes.size()));
        });
    };
    for (const ModelParts& level : levels)
        for (const NamedMesh& part : level) {
            const PartTextures* t = part.textures;
            if (!t || !has_triangles(part) || std::find(done.begin(), done.end(), t) != done.end())
                continue;
            done.push_back(t);
            add(t->name, "albedo", t->albedo_png);
            if (!t->normal_png.empty()) add(t->name, "normal", t->normal_png);
        }
}

}  // namespace

namespace {

void add_obj_with_mtl(FileSet& files, const std::filesystem::path& path,
                      const std::vector<NamedMesh>& parts, const ExportOptions& options) {
    std::filesystem::path mtl = path;
    mtl.replace_extension(".mtl");
    files.add(path, [&](std::ostream& out) {
        write_obj_with_mtl(out, parts, options, mtl.filename().string());
    });
    files.add(mtl, [&, texture = add_palette(files, path, options)](std::ostream& out) {
        write_mtl(out, parts, texture, path);
    });
    add_part_textures(files, path, {parts});
}

}  // namespace

std::vector<std::filesystem::path> write_obj_with_mtl(const std::filesystem::path& path,
                                                      const std::vector<NamedMesh>& parts,
                                                      const ExportOptions& options) {
    FileSet files;
    add_obj_with_mtl(files, output_target(path), parts, options);
    return files.commit();
}

namespace {

void add_obj_files(FileSet& files, const std::filesystem::path& path,
                   const std::vector<ModelParts>& levels, const ExportOptions& options) {
    if (levels.size() == 1) return add_obj_with_mtl(files, path, levels[0], options);
    // One material library for all levels: the materials are the same.
    std::filesystem::path mtl = path;
    mtl.replace_extension(".mtl");
    ModelParts all_parts;
    for (const auto& level : levels)
        for (const NamedMesh& part : level)
            if (part.mesh && !part.mesh->triangles.empty() && !part.collision &&
                std::none_of(all_parts.begin(), all_parts.end(), [&](const NamedMesh& p) {
                    return material_name(p) == material_name(part);
                }))
                all_parts.push_back(part);
    files.add(mtl, [&, texture = add_palette(files, path, options)](std::ostream& out) {
        write_mtl(out, all_parts, texture, path);
    });
    add_part_textures(files, path, levels);
    const std::vector<std::filesystem::path> names = lod_file_names(path, levels.size());
    for (std::size_t i = 0; i < levels.size(); ++i)
        files.add(names[i], [&](std::ostream& out) {
            write_obj_with_mtl(out, levels[i], options, mtl.filename().string(),
                               "_LOD" + std::to_string(i));
        });
}

}  // namespace

const ExportFormat obj_format = {"obj", ".obj", add_obj_files};

}  // namespace sylva
