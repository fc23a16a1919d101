// The PLY reader: the header, then the elements it announces, in ASCII or in binary of either
// byte order. Only the vertex element's x, y, z and the face element's vertex_indices are kept;
// everything else is read past (see readers.h).

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "readers.h"
#include "text_input.h"

namespace geodex::detail {
namespace {

enum class PlyType : std::uint8_t { Int8, UInt8, Int16, UInt16, Int32, UInt32, Float32, Float64 };

bool parsePlyType(std::string_view name, PlyType& type) {
  static constexpr std::pair<std::string_view, PlyType> kNames[] = {
      {"char", PlyType::Int8},     {"int8", PlyType::Int8},       {"uchar", PlyType::UInt8},
      {"uint8", PlyType::UInt8},   {"short", PlyType::Int16},     {"int16", PlyType::Int16},
      {"ushort", PlyType::UInt16}, {"uint16", PlyType::UInt16},   {"int", PlyType::Int32},
      {"int32", PlyType::Int32},   {"uint", PlyType::UInt32},     {"uint32", PlyType::UInt32},
      {"float", PlyType::Float32}, {"float32", PlyType::Float32}, {"double", PlyType::Float64},
      {"float64", PlyType::Float64}};
  for (const auto& [typeName, value] : kNames) {
    if (typeName == name) {
      type = value;
      return true;
    }
  }
  return false;
}

std::size_t plySize(PlyType type) {
  switch (type) {
    case PlyType::Int8:
    case PlyType::UInt8: return 1;
    case PlyType::Int16:
    case PlyType::UInt16: return 2;
    case PlyType::Int32:
    case PlyType::UInt32:
    case PlyType::Float32: return 4;
    case PlyType::Float64: return 8;
  }
  return 1;
}

struct PlyProperty {
  std::string name;
  PlyType type = PlyType::Float32;  ///< of the value, or of each list item
  bool isList = false;
  PlyType countType = PlyType::UInt8;  ///< of a list's length
};

struct PlyElement {
  std::string name;
  std::uint64_t count = 0;
  std::vector<PlyProperty> properties;
  int line = 0;  ///< of its "element" header line
};

enum class PlyEncoding { Ascii, LittleEndian, BigEndian };

/// Reads binary PLY values; callers check `remaining()` first.
class PlyBytes {
 public:
  PlyBytes(const char* begin, const char* end, bool bigEndian)
      : next_(begin), begin_(begin), end_(end), bigEndian_(bigEndian) {}

  std::size_t remaining() const { return static_cast<std::size_t>(end_ - next_); }
  std::size_t offset() const { return static_cast<std::size_t>(next_ - begin_); }
  void skip(std::size_t bytes) { next_ += bytes; }

  double read(PlyType type) {
    switch (type) {
      case PlyType::Int8: return take<std::int8_t>();
      case PlyType::UInt8: return take<std::uint8_t>();
      case PlyType::Int16: return take<std::int16_t>();
      case PlyType::UInt16: return take<std::uint16_t>();
      case PlyType::Int32: return take<std::int32_t>();
      case PlyType::UInt32: return take<std::uint32_t>();
      case PlyType::Float32: return take<float>();
      case PlyType::Float64: return take<double>();
    }
    return 0.0;
  }

 private:
  template <class T>
  T take() {
    unsigned char raw[sizeof(T)];
    std::memcpy(raw, next_, sizeof(T));
    next_ += sizeof(T);
    const bool hostIsBig = std::endian::native == std::endian::big;
    if (bigEndian_ != hostIsBig) std::reverse(raw, raw + sizeof(T));
    T value;
    std::memcpy(&value, raw, sizeof(T));
    return value;
  }
  const char* next_;
  const char* begin_;
  const char* end_;
  bool bigEndian_;
};

/// A value read as a double that must be a count or a vertex index: integral, ≥ 0, < 2^32 - 1.
bool asIndex(double value, Index& out) {
  if (!(value >= 0.0) || value >= static_cast<double>(kMaxElements) ||
      value != std::floor(value)) {
    return false;
  }
  out = static_cast<Index>(value);
  return true;
}

/// Which parts of an element the soup needs.
struct PlyRoles {
  int x = -1, y = -1, z = -1;  ///< property positions in a vertex element
  int indices = -1;            ///< the vertex_indices list in a face element
};

struct PlyHeader {
  PlyEncoding encoding = PlyEncoding::Ascii;
  std::vector<PlyElement> elements;
  int vertexElement = -1;
  int faceElement = -1;
  PlyRoles vertexRoles;
  PlyRoles faceRoles;
};

/// "format ascii 1.0", "format binary_little_endian 1.0" or "format binary_big_endian 1.0".
PlyEncoding readPlyFormat(Tokens& tokens, int lineNumber, const SoupBuilder& builder) {
  std::string_view token;
  if (!tokens.next(token)) token = {};
  if (token == "ascii") return PlyEncoding::Ascii;
  if (token == "binary_little_endian") return PlyEncoding::LittleEndian;
  if (token == "binary_big_endian") return PlyEncoding::BigEndian;
  builder.fail("syntax", lineNumber, "unknown PLY format " + shown(token));
}

/// "element NAME COUNT".
PlyElement readPlyElement(Tokens& tokens, int lineNumber, const SoupBuilder& builder) {
  std::string_view name;
  std::string_view countToken;
  long long count = 0;
  if (!tokens.next(name) || !tokens.next(countToken) || !parseInteger(countToken, count) ||
      count < 0 || !tokens.atEnd()) {
    builder.fail("syntax", lineNumber, "expected 'element NAME COUNT'");
  }
  PlyElement element;
  element.name = std::string(name);
  element.count = static_cast<std::uint64_t>(count);
  element.line = lineNumber;
  return element;
}

/// "property TYPE NAME" or "property list COUNTTYPE TYPE NAME".
PlyProperty readPlyProperty(Tokens& tokens, int lineNumber, const SoupBuilder& builder) {
  PlyProperty property;
  std::string_view typeToken;
  std::string_view name;
  bool valid = tokens.next(typeToken);
  if (valid && typeToken == "list") {
    property.isList = true;
    std::string_view countType;
    valid = tokens.next(countType) && parsePlyType(countType, property.countType) &&
            tokens.next(typeToken);
  }
  valid = valid && parsePlyType(typeToken, property.type) && tokens.next(name) && tokens.atEnd();
  if (!valid) {
    builder.fail("syntax", lineNumber,
                 "expected 'property TYPE NAME' or 'property list COUNTTYPE TYPE NAME'");
  }
  property.name = std::string(name);
  return property;
}

/// The header's lines from "ply" to "end_header": its format and its elements with their
/// properties, in file order.
PlyHeader readPlyHeaderLines(LineReader& lines, const SoupBuilder& builder) {
  PlyHeader header;
  std::string_view line;
  std::string_view token;
  if (!lines.next(line) || !Tokens(line).next(token) || token != "ply") {
    builder.fail("syntax", 1, "a PLY file must start with the line 'ply'");
  }
  bool sawFormat = false;
  bool sawEnd = false;
  while (!sawEnd && lines.next(line)) {
    const int lineNumber = lines.lineNumber();
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword) || keyword == "comment" || keyword == "obj_info") continue;
    if (keyword == "end_header") {
      sawEnd = true;
    } else if (keyword == "format") {
      header.encoding = readPlyFormat(tokens, lineNumber, builder);
      sawFormat = true;
    } else if (keyword == "element") {
      header.elements.push_back(readPlyElement(tokens, lineNumber, builder));
    } else if (keyword == "property") {
      if (header.elements.empty()) {
        builder.fail("syntax", lineNumber, "property before any element");
      }
      header.elements.back().properties.push_back(readPlyProperty(tokens, lineNumber, builder));
    } else {
      builder.fail("syntax", lineNumber, shown(keyword) + " is not a PLY header keyword");
    }
  }
  if (!sawEnd) builder.fail("truncated", lines.lineNumber(), "PLY header without 'end_header'");
  if (!sawFormat) builder.fail("syntax", lines.lineNumber(), "PLY header without 'format'");
  return header;
}

/// Finds the one "vertex" and the one "face" element and the properties the soup is built from:
/// the first scalar x, y and z, and the first list named vertex_indices or vertex_index.
/// `endLine` is the header's last line, named when an element is missing.
void findVertexAndFaceElements(PlyHeader& header, int endLine, const SoupBuilder& builder) {
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    const bool isVertex = element.name == "vertex";
    const bool isFace = element.name == "face";
    if (!isVertex && !isFace) continue;
    int& slot = isVertex ? header.vertexElement : header.faceElement;
    if (slot >= 0) builder.fail("syntax", element.line, "second '" + element.name + "' element");
    slot = static_cast<int>(e);
    PlyRoles& roles = isVertex ? header.vertexRoles : header.faceRoles;
    for (std::size_t p = 0; p < element.properties.size(); ++p) {
      const PlyProperty& property = element.properties[p];
      const int position = static_cast<int>(p);
      if (isVertex && !property.isList) {
        if (property.name == "x" && roles.x < 0) roles.x = position;
        if (property.name == "y" && roles.y < 0) roles.y = position;
        if (property.name == "z" && roles.z < 0) roles.z = position;
      }
      if (isFace && property.isList && roles.indices < 0 &&
          (property.name == "vertex_indices" || property.name == "vertex_index")) {
        roles.indices = position;
      }
    }
    if (isVertex && (roles.x < 0 || roles.y < 0 || roles.z < 0)) {
      builder.fail("syntax", element.line, "the vertex element lacks a scalar x, y or z property");
    }
    if (isFace && roles.indices < 0) {
      builder.fail("syntax", element.line,
                   "the face element lacks a list property vertex_indices (or vertex_index)");
    }
  }
  if (header.vertexElement < 0) builder.fail("syntax", endLine, "no vertex element");
  if (header.faceElement < 0) builder.fail("syntax", endLine, "no face element");
  if (header.elements[header.vertexElement].count >= kMaxElements) {
    builder.fail("absurd-count", header.elements[header.vertexElement].line,
                 "the header announces " +
                     std::to_string(header.elements[header.vertexElement].count) +
                     " vertices, more than 32-bit indices can address");
  }
}

PlyHeader parsePlyHeader(LineReader& lines, const SoupBuilder& builder) {
  PlyHeader header = readPlyHeaderLines(lines, builder);
  findVertexAndFaceElements(header, lines.lineNumber(), builder);
  return header;
}

/// Fails unless the data could possibly hold every element the header announces, so that the
/// counts are safe to reserve.
void checkPlyCounts(const PlyHeader& header, std::size_t remainingBytes,
                    const SoupBuilder& builder) {
  // Smallest instance: one byte per scalar and count byte in binary files, "0 " per value in
  // ASCII ones (the last newline may be missing, hence the + 1 below).
  const std::uint64_t budget = remainingBytes + 1;
  std::uint64_t needed = 0;
  for (const PlyElement& element : header.elements) {
    std::uint64_t minBytes = 0;
    for (const PlyProperty& property : element.properties) {
      minBytes += header.encoding == PlyEncoding::Ascii
                      ? 2
                      : plySize(property.isList ? property.countType : property.type);
    }
    if (minBytes == 0) continue;
    if (element.count > budget / minBytes || needed + element.count * minBytes > budget) {
      builder.fail("absurd-count", element.line,
                   "the header announces " + std::to_string(element.count) + " '" +
                       element.name + "' elements, but only " + std::to_string(remainingBytes) +
                       " bytes of data follow");
    }
    needed += element.count * minBytes;
  }
}

void parsePlyAscii(LineReader& lines, const PlyHeader& header, SoupBuilder& builder) {
  std::string_view line;
  std::string_view token;
  std::vector<Index> corners;
  const auto nextDataLine = [&]() {
    while (lines.next(line)) {
      if (!Tokens(line).atEnd()) return true;
    }
    return false;
  };
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    if (element.properties.empty()) continue;  // nothing to read, however many
    const bool isVertex = static_cast<int>(e) == header.vertexElement;
    const bool isFace = static_cast<int>(e) == header.faceElement;
    const PlyRoles& roles = isVertex ? header.vertexRoles : header.faceRoles;
    for (std::uint64_t i = 0; i < element.count; ++i) {
      const auto name = [&] { return element.name + " " + std::to_string(i); };
      if (!nextDataLine()) {
        builder.fail("truncated", lines.lineNumber(),
                     "file ends after " + std::to_string(i) + " of the " +
                         std::to_string(element.count) + " '" + element.name +
                         "' elements announced on line " + std::to_string(element.line));
      }
      const int lineNumber = lines.lineNumber();
      Tokens tokens(line);
      const auto nextValue = [&](const PlyProperty& property) {
        double value = 0.0;
        if (!tokens.next(token)) {
          builder.fail("syntax", lineNumber,
                       name() + ": the line ends before property '" + property.name + "'");
        }
        if (!parseDouble(token, value)) {
          builder.fail("syntax", lineNumber,
                       name() + ": " + shown(token) + " (property '" + property.name +
                           "') is not a number");
        }
        return value;
      };
      double xyz[3] = {0.0, 0.0, 0.0};
      corners.clear();
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        const int position = static_cast<int>(p);
        if (!property.isList) {
          const double value = nextValue(property);
          if (isVertex && position == roles.x) xyz[0] = value;
          if (isVertex && position == roles.y) xyz[1] = value;
          if (isVertex && position == roles.z) xyz[2] = value;
          continue;
        }
        Index length = 0;
        if (!asIndex(nextValue(property), length)) {
          builder.fail("syntax", lineNumber,
                       name() + ": invalid length of list '" + property.name + "'");
        }
        const bool wanted = isFace && position == roles.indices;
        for (Index k = 0; k < length; ++k) {  // each item consumes a token: bounded by the line
          const double value = nextValue(property);
          Index index = 0;
          if (wanted && !asIndex(value, index)) {
            builder.fail("index-out-of-range", lineNumber,
                         name() + ": " + shown(token) + " is not a valid vertex index");
          }
          if (wanted) corners.push_back(index);
        }
      }
      if (!tokens.atEnd()) {
        tokens.next(token);
        builder.fail("count-mismatch", lineNumber,
                     name() + ": unexpected " + shown(token) + " after the last property");
      }
      if (isVertex) builder.addVertex(xyz[0], xyz[1], xyz[2], lineNumber);
      if (isFace) builder.addPolygon(corners, lineNumber);
    }
  }
  if (nextDataLine()) {
    builder.fail("count-mismatch", lines.lineNumber(),
                 "more data after the elements the header announced");
  }
}

void parsePlyBinary(const char* begin, const char* end, const PlyHeader& header,
                    SoupBuilder& builder) {
  PlyBytes bytes(begin, end, header.encoding == PlyEncoding::BigEndian);
  std::vector<Index> corners;
  const auto truncated = [&](const std::string& what) {
    builder.fail("truncated", 0, what + ": file ends at byte " + std::to_string(bytes.offset()) +
                                     " of the binary data");
  };
  for (std::size_t e = 0; e < header.elements.size(); ++e) {
    const PlyElement& element = header.elements[e];
    const bool isVertex = static_cast<int>(e) == header.vertexElement;
    const bool isFace = static_cast<int>(e) == header.faceElement;
    const PlyRoles& roles = isVertex ? header.vertexRoles : header.faceRoles;
    const bool fixedSize = std::none_of(element.properties.begin(), element.properties.end(),
                                        [](const PlyProperty& p) { return p.isList; });
    if (!isVertex && !isFace && fixedSize) {  // skipped in one step, however many
      std::size_t size = 0;
      for (const PlyProperty& property : element.properties) size += plySize(property.type);
      if (size > 0 && element.count > bytes.remaining() / size) truncated(element.name);
      bytes.skip(size * element.count);
      continue;
    }
    for (std::uint64_t i = 0; i < element.count; ++i) {  // each instance consumes ≥ 1 byte
      const std::string_view name = element.name;
      double xyz[3] = {0.0, 0.0, 0.0};
      corners.clear();
      for (std::size_t p = 0; p < element.properties.size(); ++p) {
        const PlyProperty& property = element.properties[p];
        const int position = static_cast<int>(p);
        const auto describe = [&] { return std::string(name) + " " + std::to_string(i); };
        if (!property.isList) {
          if (bytes.remaining() < plySize(property.type)) truncated(describe());
          const double value = bytes.read(property.type);
          if (isVertex && position == roles.x) xyz[0] = value;
          if (isVertex && position == roles.y) xyz[1] = value;
          if (isVertex && position == roles.z) xyz[2] = value;
          continue;
        }
        if (bytes.remaining() < plySize(property.countType)) truncated(describe());
        Index length = 0;
        if (!asIndex(bytes.read(property.countType), length)) {
          builder.fail("syntax", 0,
                       describe() + ": invalid length of list '" + property.name + "'");
        }
        const std::size_t itemSize = plySize(property.type);
        if (length > bytes.remaining() / itemSize) truncated(describe());
        if (!(isFace && position == roles.indices)) {
          bytes.skip(length * itemSize);
          continue;
        }
        for (Index k = 0; k < length; ++k) {
          const double value = bytes.read(property.type);
          Index index = 0;
          if (!asIndex(value, index)) {
            char buffer[32];
            std::snprintf(buffer, sizeof buffer, "%.17g", value);
            builder.fail("index-out-of-range", 0,
                         describe() + ": " + buffer + " is not a valid vertex index");
          }
          corners.push_back(index);
        }
      }
      if (isVertex) builder.addVertex(xyz[0], xyz[1], xyz[2], 0);
      if (isFace) builder.addPolygon(corners, 0);
    }
  }
  // Bytes after the last element are ignored: some writers pad binary files.
}

}  // namespace

void parsePly(std::string_view bytes, SoupBuilder& builder) {
  LineReader lines(bytes);
  const PlyHeader header = parsePlyHeader(lines, builder);
  checkPlyCounts(header, lines.remainingBytes(), builder);
  builder.reserve(header.elements[header.vertexElement].count,
                  header.elements[header.faceElement].count);
  if (header.encoding == PlyEncoding::Ascii) {
    parsePlyAscii(lines, header, builder);
  } else {
    parsePlyBinary(lines.position(), bytes.data() + bytes.size(), header, builder);
  }
}

}  // namespace geodex::detail
