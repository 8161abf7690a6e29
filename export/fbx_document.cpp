#include "export/fbx_document.h"

#include <bit>
#include <cstring>
#include <limits>

#include "core/errors.h"

namespace sylva::fbx {
namespace {

static_assert(std::endian::native == std::endian::little, "FBX is little-endian");

constexpr std::string_view kMagic("Kaydara FBX Binary  \x00\x1a\x00", 23);
// The footer id and closing magic every FBX file carries, as Blender writes them
// (encode_bin.py).
constexpr std::string_view kFootId(
    "\xfa\xbc\xab\x09\xd0\xc8\xd4\x66\xb1\x76\xfb\x83\x1c\xf7\x26\x7e", 16);
constexpr std::string_view kFootMagic(
    "\xf8\x5a\x8c\x6a\xde\xf5\xd9\x7e\xec\xe9\x0c\xe3\x75\x8f\x29\x0b", 16);
constexpr int kMaxDepth = 64;

// Bytes a value takes after its type letter.
std::uint64_t value_size(const Value& v) {
    switch (v.code) {
        case 'C':
            return 1;
        case 'Y':
            return 2;
        case 'I':
        case 'F':
            return 4;
        case 'L':
        case 'D':
            return 8;
        case 'S':
        case 'R':
            return 4 + v.text.size();
        case 'i':
            return 12 + 4 * v.integers.size();
        case 'l':
            return 12 + 8 * v.integers.size();
        case 'b':
            return 12 + v.integers.size();
        case 'f':
            return 12 + 4 * v.reals.size();
        case 'd':
            return 12 + 8 * v.reals.size();
        default:
            throw IoError(std::string("FBX value of unknown type '") + v.code + "'");
    }
}

class Encoder {
  public:
    explicit Encoder(std::uint32_t version) : wide_(version >= 7500), header_(wide_ ? 25 : 13) {}

    std::string encode(const std::vector<Node>& top, std::uint32_t version) {
        out_.append(kMagic);
        put<std::uint32_t>(version);
        for (std::size_t i = 0; i < top.size(); ++i) node(top[i], i + 1 == top.size());
        out_.append(header_, '\0');  // the top-level list's null record
        out_.append(kFootId);
        out_.append(4, '\0');
        // Padding to 16-byte alignment, a whole 16 when already aligned (as the SDK does).
        const std::size_t pad = 16 - out_.size() % 16;
        out_.append(pad, '\0');
        put<std::uint32_t>(version);
        out_.append(120, '\0');
        out_.append(kFootMagic);
        return std::move(out_);
    }

  private:
    template <class T>
    void put(T v) {
        char bytes[sizeof(T)];
        std::memcpy(bytes, &v, sizeof(T));
        out_.append(bytes, sizeof(T));
    }

    void offset(std::uint64_t v) {
        if (wide_) {
            put<std::uint64_t>(v);
        } else {
            if (v > std::numeric_limits<std::uint32_t>::max())
                throw IoError("the FBX file would pass 4 GiB, the limit of FBX 7.4");
            put<std::uint32_t>(static_cast<std::uint32_t>(v));
        }
    }

    // Size of a record from its start to its end offset.
    std::uint64_t size(const Node& n, bool last) const {
        std::uint64_t s = header_ + n.name.size();
        for (const Value& v : n.values) s += 1 + value_size(v);
        for (std::size_t i = 0; i < n.children.size(); ++i)
            s += size(n.children[i], i + 1 == n.children.size());
        if (sentinel(n, last)) s += header_;
        return s;
    }

    // A null record closes a child list, and (as Blender writes it) an empty record that is
    // not the last of its list.
    static bool sentinel(const Node& n, bool last) {
        return !n.children.empty() || (n.values.empty() && !last);
    }

    void node(const Node& n, bool last) {
        if (n.name.size() > 255) throw IoError("FBX record name longer than 255 bytes");
        const std::uint64_t end = out_.size() + size(n, last);
        std::uint64_t values = 0;
        for (const Value& v : n.values) values += 1 + value_size(v);
        offset(end);
        offset(n.values.size());
        offset(values);
        out_.push_back(static_cast<char>(n.name.size()));
        out_.append(n.name);
        for (const Value& v : n.values) value(v);
        for (std::size_t i = 0; i < n.children.size(); ++i)
            node(n.children[i], i + 1 == n.children.size());
        if (sentinel(n, last)) out_.append(header_, '\0');
    }

    void array_header(std::size_t count, std::size_t bytes) {
        if (count > std::numeric_limits<std::uint32_t>::max() ||
            bytes > std::numeric_limits<std::uint32_t>::max())
            throw IoError("an FBX array of more than 4 GiB");
        put<std::uint32_t>(static_cast<std::uint32_t>(count));
        put<std::uint32_t>(0);  // encoding: raw
        put<std::uint32_t>(static_cast<std::uint32_t>(bytes));
    }

    void value(const Value& v) {
        out_.push_back(v.code);
        switch (v.code) {
            case 'C':
                out_.push_back(static_cast<char>(v.integer));
                break;
            case 'Y':
                put<std::int16_t>(static_cast<std::int16_t>(v.integer));
                break;
            case 'I':
                put<std::int32_t>(static_cast<std::int32_t>(v.integer));
                break;
            case 'L':
                put<std::int64_t>(v.integer);
                break;
            case 'F':
                put<float>(static_cast<float>(v.real));
                break;
            case 'D':
                put<double>(v.real);
                break;
            case 'S':
            case 'R':
                if (v.text.size() > std::numeric_limits<std::uint32_t>::max())
                    throw IoError("an FBX string of more than 4 GiB");
                put<std::uint32_t>(static_cast<std::uint32_t>(v.text.size()));
                out_.append(v.text);
                break;
            case 'i':
                array_header(v.integers.size(), 4 * v.integers.size());
                for (std::int64_t x : v.integers) put<std::int32_t>(static_cast<std::int32_t>(x));
                break;
            case 'l':
                array_header(v.integers.size(), 8 * v.integers.size());
                for (std::int64_t x : v.integers) put<std::int64_t>(x);
                break;
            case 'b':
                array_header(v.integers.size(), v.integers.size());
                for (std::int64_t x : v.integers) out_.push_back(x ? 1 : 0);
                break;
            case 'f':
                array_header(v.reals.size(), 4 * v.reals.size());
                for (double x : v.reals) put<float>(static_cast<float>(x));
                break;
            case 'd':
                array_header(v.reals.size(), 8 * v.reals.size());
                for (double x : v.reals) put<double>(x);
                break;
            default:
                throw IoError(std::string("FBX value of unknown type '") + v.code + "'");
        }
    }

    bool wide_;
    // Bytes of a record header, 3 offsets and the name's length byte, and of a null record.
    std::size_t header_;
    std::string out_;
};

class Decoder {
  public:
    Decoder(std::string_view bytes, const std::string& source) : in_(bytes), source_(source) {}

    Document decode() {
        if (in_.size() < kMagic.size() + 4 || in_.substr(0, kMagic.size()) != kMagic)
            fail("not a binary FBX file (no 'Kaydara FBX Binary' magic)", 0);
        pos_ = kMagic.size();
        Document doc;
        doc.version = get<std::uint32_t>(in_.size());
        if (doc.version < 7000 || doc.version >= 8000)
            fail("FBX version " + std::to_string(doc.version) + " is not 7.x", pos_ - 4);
        wide_ = doc.version >= 7500;
        // Top-level records until the null record; the footer after it is not checked.
        while (true) {
            Node n;
            if (!node(n, in_.size(), 0)) break;
            doc.top.push_back(std::move(n));
        }
        return doc;
    }

  private:
    [[noreturn]] void fail(const std::string& what, std::size_t at) const {
        throw InputError(what + " at byte " + std::to_string(at), {source_, 0, 0});
    }

    void need(std::uint64_t n, std::uint64_t end) const {
        if (n > end - pos_) fail("a record or value runs past its end", pos_);
    }

    template <class T>
    T get(std::uint64_t end) {
        need(sizeof(T), end);
        T v;
        std::memcpy(&v, in_.data() + pos_, sizeof(T));
        pos_ += sizeof(T);
        return v;
    }

    std::uint64_t offset(std::uint64_t end) {
        return wide_ ? get<std::uint64_t>(end) : get<std::uint32_t>(end);
    }

    // Reads one record ending by `end`; false for a null record (end of the list).
    bool node(Node& n, std::uint64_t end, int depth) {
        if (depth > kMaxDepth) fail("FBX records nested deeper than 64", pos_);
        const std::size_t start = pos_;
        const std::uint64_t node_end = offset(end);
        const std::uint64_t count = offset(end);
        const std::uint64_t values_size = offset(end);
        const auto name_size = get<std::uint8_t>(end);
        if (node_end == 0 && count == 0 && values_size == 0 && name_size == 0) return false;
        if (node_end > end || node_end <= start)
            fail("a record's end offset is out of range", start);
        need(name_size, node_end);
        n.name.assign(in_.data() + pos_, name_size);
        pos_ += name_size;
        if (values_size > node_end - pos_) fail("a record's values run past its end", pos_);
        const std::uint64_t values_end = pos_ + values_size;
        if (count > values_size) fail("more values than bytes for them", pos_);
        for (std::uint64_t i = 0; i < count; ++i) n.values.push_back(value(values_end));
        if (pos_ != values_end) fail("a record's values do not fill their length", pos_);
        while (pos_ < node_end) {
            Node child;
            if (!node(child, node_end, depth + 1)) break;
            n.children.push_back(std::move(child));
        }
        if (pos_ != node_end) fail("a record's children do not end at its end offset", pos_);
        return true;
    }

    template <class T>
    void array(Value& v, std::uint64_t end) {
        const auto count = get<std::uint32_t>(end);
        const auto encoding = get<std::uint32_t>(end);
        const auto bytes = get<std::uint32_t>(end);
        if (encoding != 0) fail("compressed FBX arrays are not read", pos_);
        if (static_cast<std::uint64_t>(count) * sizeof(T) != bytes)
            fail("an array's byte length does not match its count", pos_);
        need(bytes, end);
        for (std::uint32_t i = 0; i < count; ++i) {
            T x;
            std::memcpy(&x, in_.data() + pos_, sizeof(T));
            pos_ += sizeof(T);
            if constexpr (std::is_floating_point_v<T>)
                v.reals.push_back(x);
            else
                v.integers.push_back(static_cast<std::int64_t>(x));
        }
    }

    Value value(std::uint64_t end) {
        Value v;
        v.code = static_cast<char>(get<std::uint8_t>(end));
        switch (v.code) {
            case 'C':
                v.integer = get<std::uint8_t>(end);
                break;
            case 'Y':
                v.integer = get<std::int16_t>(end);
                break;
            case 'I':
                v.integer = get<std::int32_t>(end);
                break;
            case 'L':
                v.integer = get<std::int64_t>(end);
                break;
            case 'F':
                v.real = get<float>(end);
                break;
            case 'D':
                v.real = get<double>(end);
                break;
            case 'S':
            case 'R': {
                const auto n = get<std::uint32_t>(end);
                need(n, end);
                v.text.assign(in_.data() + pos_, n);
                pos_ += n;
                break;
            }
            case 'i':
                array<std::int32_t>(v, end);
                break;
            case 'l':
                array<std::int64_t>(v, end);
                break;
            case 'b':
                array<std::uint8_t>(v, end);
                break;
            case 'f':
                array<float>(v, end);
                break;
            case 'd':
                array<double>(v, end);
                break;
            default:
                fail(std::string("unknown FBX value type ") +
                         std::to_string(static_cast<unsigned char>(v.code)),
                     pos_ - 1);
        }
        return v;
    }

    std::string_view in_;
    const std::string& source_;
    std::size_t pos_ = 0;
    bool wide_ = false;
};

}  // namespace

Value int32(std::int32_t v) {
    Value out;
    out.code = 'I';
    out.integer = v;
    return out;
}

Value int64(std::int64_t v) {
    Value out;
    out.code = 'L';
    out.integer = v;
    return out;
}

Value float64(double v) {
    Value out;
    out.code = 'D';
    out.real = v;
    return out;
}

Value character(char v) {
    Value out;
    out.code = 'C';
    out.integer = static_cast<unsigned char>(v);
    return out;
}

Value string(std::string_view v) {
    Value out;
    out.code = 'S';
    out.text = v;
    return out;
}

Value raw(std::string_view bytes) {
    Value out;
    out.code = 'R';
    out.text = bytes;
    return out;
}

Value int32_array(std::vector<std::int64_t> v) {
    Value out;
    out.code = 'i';
    out.integers = std::move(v);
    return out;
}

Value float64_array(std::vector<double> v) {
    Value out;
    out.code = 'd';
    out.reals = std::move(v);
    return out;
}

Node& Node::add(std::string child_name, std::vector<Value> child_values) {
    children.push_back({std::move(child_name), std::move(child_values), {}});
    return children.back();
}

const Node* Node::find(std::string_view child_name) const {
    for (const Node& c : children)
        if (c.name == child_name) return &c;
    return nullptr;
}

std::string encode_fbx(const std::vector<Node>& top, std::uint32_t version) {
    return Encoder(version).encode(top, version);
}

Document decode_fbx(std::string_view bytes, const std::string& source) {
    return Decoder(bytes, source).decode();
}

}  // namespace sylva::fbx
