// The binary FBX container (7.4 and 7.5): a tree of named records, each with a list of
// typed values and child records, as Blender's FBX add-on (io_scene_fbx, encode_bin.py and
// parse_fbx.py) writes and reads it. encode_fbx() is the one writer of the bytes (what
// export/fbx_writer.cpp builds goes through it); decode_fbx() reads them back for tests
// and the fuzzer. No Debian library writes FBX that Blender or assimp can read back (see
// third_party_notes.md), hence a container of our own.
//
// Arrays are written uncompressed (encoding 0, which every reader takes at any size), so the
// bytes are the same on every machine. Reading takes uncompressed arrays only.
// Thread safety: plain functions on caller-owned values.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace sylva::fbx {

// One value of a record. `code` is the FBX type letter; the field it uses:
// 'C' (bool/char), 'Y' (int16), 'I' (int32), 'L' (int64): integer; 'F' (float32), 'D'
// (float64): real; 'S' (string), 'R' (raw bytes): text; 'i' (int32[]), 'l' (int64[]),
// 'b' (bool[]): integers; 'f' (float32[]), 'd' (float64[]): reals.
struct Value {
    char code = 'I';
    std::int64_t integer = 0;
    double real = 0.0;
    std::string text;
    std::vector<std::int64_t> integers;
    std::vector<double> reals;
};

Value int32(std::int32_t v);
Value int64(std::int64_t v);
Value float64(double v);
Value character(char v);  // 'C': Blender writes Model::Shading as one
Value string(std::string_view v);
Value raw(std::string_view bytes);
Value int32_array(std::vector<std::int64_t> v);  // each value must fit in 32 bits
Value float64_array(std::vector<double> v);

struct Node {
    std::string name;
    std::vector<Value> values;
    std::vector<Node> children;

    // Appends a child and returns it (references stay valid until the next add()).
    Node& add(std::string child_name, std::vector<Value> child_values = {});
    // The first child of that name, or nullptr.
    const Node* find(std::string_view child_name) const;
};

// The file: magic, version, the top-level records, a closing null record and the footer.
// `version` is 7400 (32-bit record offsets) or 7500 (64-bit). Throws IoError when a 7400 file
// would pass 4 GiB (use 7500).
std::string encode_fbx(const std::vector<Node>& top, std::uint32_t version = 7400);

struct Document {
    std::uint32_t version = 0;
    std::vector<Node> top;
};

// Reads bytes as encode_fbx() writes them. Throws InputError (naming `source` and the byte
// offset) for anything else: a bad magic, a record or array running past its parent or the
// end, an unknown type letter, a compressed array, nesting deeper than 64.
Document decode_fbx(std::string_view bytes, const std::string& source = "FBX data");

}  // namespace sylva::fbx
