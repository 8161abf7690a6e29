#include "app/obj_writer.h"

#include "app/atomic_file.h"

#include <charconv>

namespace sylva {
namespace {

void append_number(std::string& line, float value) {
    char buffer[32];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    line.push_back(' ');
    line.append(buffer, result.ptr);
}

void append_index(std::string& line, std::size_t value) {
    char buffer[24];
    auto result = std::to_chars(buffer, buffer + sizeof buffer, value);
    line.push_back(' ');
    line.append(buffer, result.ptr);
}

}  // namespace

void write_obj(std::ostream& out, const std::vector<NamedMesh>& parts) {
    out << "# Sylva low-poly tree: Y up, meters\n";
    std::size_t base = 1;  // OBJ indices are 1-based and global across groups
    std::string line;
    for (const NamedMesh& part : parts) {
        const Mesh& mesh = *part.mesh;
        out << "o " << part.name << "\ng " << part.name << "\n";
        for (const glm::vec3& p : mesh.positions) {
            line.assign("v");
            append_number(line, p.x);
            append_number(line, p.y);
            append_number(line, p.z);
            line.push_back('\n');
            out << line;
        }
        for (const auto& t : mesh.triangles) {
            line.assign("f");
            for (std::uint32_t i : t) append_index(line, base + i);
            line.push_back('\n');
            out << line;
        }
        base += mesh.positions.size();
    }
}

void write_obj(const std::filesystem::path& path, const std::vector<NamedMesh>& parts) {
    write_file_atomically(path, [&](std::ostream& out) { write_obj(out, parts); });
}

}  // namespace sylva
