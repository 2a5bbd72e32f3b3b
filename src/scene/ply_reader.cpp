#include <scene/ply_reader.h>

#include <fmt/format.h>

#include <cctype>
#include <cmath>
#include <cstring>
#include <fstream>
#include <sstream>
#include <stdexcept>

namespace rayrad::scene {

namespace {

/// Files above this size are refused before reading (2 GiB holds ~60 M triangles).
constexpr uint64_t kMaxPlyBytes = uint64_t(2) << 30;

enum class Format { Ascii, BinaryLittle, BinaryBig };

/// The size in bytes of a PLY scalar type, 0 for an unknown name.
int typeSize(const std::string& t) {
    if (t == "char" || t == "uchar" || t == "int8" || t == "uint8") return 1;
    if (t == "short" || t == "ushort" || t == "int16" || t == "uint16") return 2;
    if (t == "int" || t == "uint" || t == "int32" || t == "uint32" || t == "float" || t == "float32") return 4;
    if (t == "double" || t == "float64") return 8;
    return 0;
}

struct Property {
    std::string name;
    std::string type;       ///< the scalar type, or the item type of a list
    std::string countType;  ///< lists only
    bool isList = false;
};

struct Element {
    std::string name;
    uint64_t count = 0;
    std::vector<Property> properties;
};

/// Reads values from the body: binary (either byte order) or ASCII tokens.
class BodyReader {
  public:
    BodyReader(const std::string& data, size_t offset, Format format) : m_data(data), m_pos(offset), m_format(format) {}

    /// Reads one scalar of `type` as a double. Throws with `what` on a short or bad file.
    double read(const std::string& type, const std::string& what) {
        if (m_format == Format::Ascii) return readToken(what);
        const int size = typeSize(type);
        if (m_pos + size > m_data.size()) throw std::runtime_error(what + ": the file ends early");
        unsigned char b[8];
        std::memcpy(b, m_data.data() + m_pos, size);
        m_pos += size;
        bool swap = (m_format == Format::BinaryBig) != isBigEndianHost();
        if (swap)
            for (int i = 0; i < size / 2; ++i) std::swap(b[i], b[size - 1 - i]);
        if (type == "char" || type == "int8") return static_cast<int8_t>(b[0]);
        if (type == "uchar" || type == "uint8") return b[0];
        if (type == "short" || type == "int16") return load<int16_t>(b);
        if (type == "ushort" || type == "uint16") return load<uint16_t>(b);
        if (type == "int" || type == "int32") return load<int32_t>(b);
        if (type == "uint" || type == "uint32") return load<uint32_t>(b);
        if (type == "float" || type == "float32") return load<float>(b);
        return load<double>(b);
    }

    size_t remaining() const { return m_data.size() - m_pos; }

  private:
    template <class T>
    static double load(const unsigned char* b) {
        T v;
        std::memcpy(&v, b, sizeof v);
        return static_cast<double>(v);
    }
    static bool isBigEndianHost() {
        const uint16_t one = 1;
        unsigned char first;
        std::memcpy(&first, &one, 1);
        return first == 0;
    }
    double readToken(const std::string& what) {
        while (m_pos < m_data.size() && std::isspace(static_cast<unsigned char>(m_data[m_pos]))) ++m_pos;
        size_t start = m_pos;
        while (m_pos < m_data.size() && !std::isspace(static_cast<unsigned char>(m_data[m_pos]))) ++m_pos;
        if (start == m_pos) throw std::runtime_error(what + ": the file ends early");
        std::string token = m_data.substr(start, m_pos - start);
        char* end = nullptr;
        double v = std::strtod(token.c_str(), &end);
        if (end != token.c_str() + token.size()) throw std::runtime_error(what + ": '" + token + "' is not a number");
        return v;
    }

    const std::string& m_data;
    size_t m_pos;
    Format m_format;
};

std::string readWholeFile(const std::string& path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) throw std::runtime_error("cannot open the file");
    std::streamoff size = in.tellg();
    if (size < 0) throw std::runtime_error("cannot tell the file's size");
    if (static_cast<uint64_t>(size) > kMaxPlyBytes)
        throw std::runtime_error(
            fmt::format("the file has {} bytes, more than the {} rayrad reads", size, kMaxPlyBytes));
    std::string data(static_cast<size_t>(size), '\0');
    in.seekg(0);
    if (size > 0 && !in.read(data.data(), size)) throw std::runtime_error("cannot read the file");
    return data;
}

/// The header: the body's format, its elements, and where the body starts.
struct Header {
    Format format;
    std::vector<Element> elements;
    size_t bodyStart;
};

Header readHeader(const std::string& data) {
    // Header: text lines up to "end_header".
    size_t pos = 0;
    int lineNo = 0;
    auto nextLine = [&]() -> std::string {
        if (pos >= data.size())
            throw std::runtime_error(fmt::format("header line {}: the file ends before end_header", lineNo + 1));
        size_t end = data.find('\n', pos);
        if (end == std::string::npos || end - pos > 4096)
            throw std::runtime_error(fmt::format("header line {}: no end of line (not a PLY header)", lineNo + 1));
        std::string line = data.substr(pos, end - pos);
        if (!line.empty() && line.back() == '\r') line.pop_back();
        pos = end + 1;
        ++lineNo;
        return line;
    };
    if (nextLine() != "ply") throw std::runtime_error("header line 1: the file does not start with 'ply'");
    Format format = Format::Ascii;
    bool haveFormat = false;
    std::vector<Element> elements;
    for (;;) {
        std::string line = nextLine();
        std::istringstream words(line);
        std::string keyword;
        words >> keyword;
        auto bad = [&](const std::string& why) {
            std::string shown;  // printable characters only, at most 60
            for (char ch : line.substr(0, 60)) shown += std::isprint(static_cast<unsigned char>(ch)) ? ch : '?';
            return std::runtime_error(fmt::format("header line {} ('{}'): {}", lineNo, shown, why));
        };
        if (keyword == "end_header") break;
        if (keyword.empty() || keyword == "comment" || keyword == "obj_info") continue;
        if (keyword == "format") {
            std::string f, version;
            words >> f >> version;
            if (f == "ascii")
                format = Format::Ascii;
            else if (f == "binary_little_endian")
                format = Format::BinaryLittle;
            else if (f == "binary_big_endian")
                format = Format::BinaryBig;
            else
                throw bad("unknown format (expected ascii, binary_little_endian or binary_big_endian)");
            haveFormat = true;
        } else if (keyword == "element") {
            Element e;
            long long count = -1;
            words >> e.name >> count;
            if (e.name.empty() || !words || count < 0) throw bad("expected 'element NAME COUNT'");
            e.count = static_cast<uint64_t>(count);
            elements.push_back(e);
        } else if (keyword == "property") {
            if (elements.empty()) throw bad("a property before any element");
            Property p;
            std::string type;
            words >> type;
            if (type == "list") {
                p.isList = true;
                words >> p.countType >> p.type >> p.name;
                if (typeSize(p.countType) == 0 || typeSize(p.type) == 0 || p.name.empty())
                    throw bad("expected 'property list COUNT_TYPE ITEM_TYPE NAME'");
            } else {
                p.type = type;
                words >> p.name;
                if (typeSize(p.type) == 0 || p.name.empty()) throw bad("expected 'property TYPE NAME'");
            }
            elements.back().properties.push_back(p);
        } else {
            throw bad("unknown keyword '" + keyword + "'");
        }
    }
    if (!haveFormat) throw std::runtime_error("the header has no 'format' line");
    return {format, elements, pos};
}

/// Element e's records, read from the body; vertices and faces go into `mesh`.
void readElement(BodyReader& body, Format format, const Element& e, PlyMesh& mesh) {
    // Every record takes at least one byte (binary: its fixed part), so a count the
    // rest of the file cannot hold is an error before anything is allocated.
    uint64_t minRecord = 0;
    for (const Property& p : e.properties)
        minRecord += static_cast<uint64_t>(typeSize(p.isList ? p.countType : p.type));
    if (format == Format::Ascii) minRecord = e.properties.empty() ? 0 : 2 * e.properties.size() - 1;
    if (minRecord > 0 && e.count > body.remaining() / minRecord)
        throw std::runtime_error(fmt::format("element '{}' claims {} records, more than the {} bytes left can hold",
                                             e.name, e.count, body.remaining()));
    const bool isVertex = e.name == "vertex", isFace = e.name == "face";
    int ix = -1, iy = -1, iz = -1, iFace = -1;
    for (size_t k = 0; k < e.properties.size(); ++k) {
        const std::string& n = e.properties[k].name;
        if (n == "x") ix = static_cast<int>(k);
        if (n == "y") iy = static_cast<int>(k);
        if (n == "z") iz = static_cast<int>(k);
        if ((n == "vertex_indices" || n == "vertex_index") && e.properties[k].isList) iFace = static_cast<int>(k);
    }
    if (isVertex && (ix < 0 || iy < 0 || iz < 0))
        throw std::runtime_error("element 'vertex' lacks one of the properties x, y, z");
    // An element without properties has empty records: nothing to read, however many
    // it claims (a hostile header claimed 2.7e15 of them: a loop, not an error).
    if (e.properties.empty()) return;
    if (isVertex) mesh.positions.reserve(e.count);
    if (isFace) mesh.faces.reserve(e.count);
    std::vector<uint32_t> face;
    for (uint64_t r = 0; r < e.count; ++r) {
        const std::string what = fmt::format("{} {}", e.name, r);
        Vec3 p(0.0);
        face.clear();
        for (size_t k = 0; k < e.properties.size(); ++k) {
            const Property& prop = e.properties[k];
            if (!prop.isList) {
                double v = body.read(prop.type, what);
                if (static_cast<int>(k) == ix) p.x = v;
                if (static_cast<int>(k) == iy) p.y = v;
                if (static_cast<int>(k) == iz) p.z = v;
                continue;
            }
            double n = body.read(prop.countType, what);
            if (!(n >= 0) || n != std::floor(n) || n > 65536)
                throw std::runtime_error(fmt::format("{}: list length {} is not a count", what, n));
            for (int i = 0; i < static_cast<int>(n); ++i) {
                double v = body.read(prop.type, what);
                if (static_cast<int>(k) != iFace) continue;
                if (!(v >= 0) || v != std::floor(v) || v > 4294967295.0)
                    throw std::runtime_error(fmt::format("{}: vertex index {} is not a valid index", what, v));
                face.push_back(static_cast<uint32_t>(v));
            }
        }
        if (isVertex) mesh.positions.push_back(p);
        if (isFace) mesh.faces.push_back(face);
    }
}

}  // namespace

PlyMesh readPly(const std::string& path) {
    const std::string data = readWholeFile(path);
    const Header header = readHeader(data);
    PlyMesh mesh;
    BodyReader body(data, header.bodyStart, header.format);
    for (const Element& e : header.elements) readElement(body, header.format, e, mesh);
    return mesh;
}

}  // namespace rayrad::scene
