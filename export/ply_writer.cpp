#include "export/ply_writer.h"

#include <algorithm>
#include <array>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstring>
#include <string>

#include "core/atomic_file.h"
#include "core/file_set.h"
#include "export/mesh_normals.h"

namespace sylva {
namespace {

static_assert(std::endian::native == std::endian::little,
              "the binary PLY writer copies little-endian values as they are in memory");

std::uint8_t srgb8(float linear) {
    const float c = std::clamp(linear, 0.0f, 1.0f);
    const float s = c <= 0.0031308f ? 12.92f * c : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f;
    return static_cast<std::uint8_t>(std::lround(s * 255.0f));
}

// Shortest text that reads back to the same float (no locale, no lost digits).
void put_text(std::string& line, float value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    line.push_back(' ');
    line.append(buffer, result.ptr);
}

template <class T>
void put(std::string& bytes, T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    bytes.append(raw, sizeof(T));
}

// Y up to Z up, a rotation about X (so windings stay outward): Blender and most mesh tools
// take a PLY's Z as up.
glm::vec3 z_up(const glm::vec3& p) {
    return {p.x, -p.z, p.y};
}

}  // namespace

void write_ply(std::ostream& out, const std::vector<NamedMesh>& parts,
               const ExportOptions& options) {
    const bool smooth = options.shading == Shading::Smooth;
    const float scale = profile_info(options.profile).unitless_scale;
    // What is written of each part: its mesh, or with smooth shading the mesh split at
    // creases with its normals.
    struct Written {
        const NamedMesh* part;
        ShadedMesh shaded;
        const Mesh& mesh() const { return shaded.normals.empty() ? *part->mesh : shaded.mesh; }
        // The part's vertex that vertex i of mesh() copies (smooth shading appends copies).
        std::vector<std::uint32_t> copied;
        std::uint32_t source(std::size_t i) const {
            return i < copied.size() ? copied[i] : static_cast<std::uint32_t>(i);
        }
    };
    std::vector<Written> written;
    std::size_t vertices = 0, faces = 0;
    std::string names;
    for (const NamedMesh& part : parts) {
        if (!part.mesh || part.mesh->triangles.empty() || part.collision) continue;
        written.push_back(
            {&part, smooth ? smooth_shaded(*part.mesh, options.crease_degrees) : ShadedMesh{}, {}});
        Written& w = written.back();
        if (smooth) {
            w.copied.resize(w.shaded.mesh.positions.size());
            for (std::size_t f = 0; f < part.mesh->triangles.size(); ++f)
                for (std::size_t k = 0; k < 3; ++k)
                    w.copied[w.shaded.mesh.triangles[f][k]] = part.mesh->triangles[f][k];
        }
        vertices += w.mesh().positions.size();
        faces += part.mesh->triangles.size();
        names += " " + part.name;
    }
    out << "ply\nformat " << (options.ply_binary ? "binary_little_endian" : "ascii") << " 1.0\n"
        << "comment Sylva low-poly tree: Z up (Blender's axes), "
        << (scale == 1.0f ? "meters" : "centimeters") << "; parts in order:" << names << "\n"
        << "element vertex " << vertices << "\n"
        << "property float x\nproperty float y\nproperty float z\n"
        << (smooth ? "property float nx\nproperty float ny\nproperty float nz\n" : "")
        << "property uchar red\nproperty uchar green\nproperty uchar blue\n"
        << "element face " << faces << "\n"
        << "property list uchar uint vertex_indices\nend_header\n";

    std::string bytes;
    std::uint32_t base = 0;
    // Vertices of every part, then faces of every part (PLY lists elements in blocks).
    for (const Written& w : written) {
        const Mesh& mesh = w.mesh();
        const glm::vec3& color = w.part->color;
        const PartAttributes* attributes = w.part->attributes;
        const bool tinted = attributes && !attributes->tint.empty();
        std::array<std::uint8_t, 3> rgb{srgb8(color.r), srgb8(color.g), srgb8(color.b)};
        for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
            const glm::vec3 p = z_up(scale * mesh.positions[i]);
            const glm::vec3 n = smooth ? z_up(w.shaded.normals[i]) : glm::vec3(0.0f);
            if (tinted) {
                // A smooth-shaded copy of a vertex sits after the mesh's own vertices.
                const glm::vec3 c = color * attributes->tint[w.source(i)];
                rgb = {srgb8(c.r), srgb8(c.g), srgb8(c.b)};
            }
            bytes.clear();
            if (options.ply_binary) {
                for (float v : {p.x, p.y, p.z}) put(bytes, v);
                if (smooth)
                    for (float v : {n.x, n.y, n.z}) put(bytes, v);
                for (std::uint8_t c : rgb) put(bytes, c);
            } else {
                for (float v : {p.x, p.y, p.z}) put_text(bytes, v);
                if (smooth)
                    for (float v : {n.x, n.y, n.z}) put_text(bytes, v);
                for (std::uint8_t c : rgb) bytes += " " + std::to_string(c);
                bytes.erase(0, 1);  // no leading space
                bytes.push_back('\n');
            }
            out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
        }
    }
    for (const Written& w : written) {
        const Mesh& mesh = w.mesh();
        for (const auto& t : mesh.triangles) {
            if (options.ply_binary) {
                bytes.clear();
                put(bytes, std::uint8_t{3});
                for (std::uint32_t i : t) put(bytes, base + i);
                out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
            } else {
                out << "3 " << base + t[0] << ' ' << base + t[1] << ' ' << base + t[2] << '\n';
            }
        }
        base += static_cast<std::uint32_t>(mesh.positions.size());
    }
}

void write_ply(const std::filesystem::path& path, const std::vector<NamedMesh>& parts,
               const ExportOptions& options) {
    write_file_atomically(path, [&](std::ostream& out) { write_ply(out, parts, options); });
}

namespace {

void add_ply_files(FileSet& files, const std::filesystem::path& path,
                   const std::vector<ModelParts>& levels, const ExportOptions& options) {
    const std::vector<std::filesystem::path> names =
        levels.size() == 1 ? std::vector{path} : lod_file_names(path, levels.size());
    for (std::size_t i = 0; i < levels.size(); ++i)
        files.add(names[i], [&](std::ostream& out) { write_ply(out, levels[i], options); });
}

}  // namespace

const ExportFormat ply_format = {"ply", ".ply", add_ply_files};

}  // namespace sylva
