// Reading OFF, OBJ and PLY into a TriangleSoup, and validating soups (see mesh_io.h).
//
// The readers never trust a count from the file: every reserve() is capped by what the bytes left
// could hold and every loop consumes input, so any bytes (the fuzzers feed readMeshFromMemory
// random ones) end in a soup or an InputError, never in a crash, a bad_alloc or a hang.

#include "geodex/mesh_io.h"

#include <algorithm>
#include <array>
#include <bit>
#include <cctype>
#include <cerrno>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numeric>
#include <span>
#include <sstream>
#include <string_view>
#include <system_error>
#include <utility>

#include <Eigen/Geometry>

#include "geodex/error.h"
#include "geodex/tolerance.h"
#include "from_chars_double.h"

namespace geodex {

bool MeshReadResult::ok() const {
  return std::none_of(issues.begin(), issues.end(),
                      [](const MeshIssue& issue) { return issue.severity == Severity::Error; });
}

namespace {

// ===  Messages  =================================================================================

/// The start of a message: "FILE:LINE: ", "line LINE: " (no file name), "FILE: " (line unknown,
/// e.g. binary PLY) or "".
std::string where(const std::string& file, int line) {
  if (line > 0) {
    return file.empty() ? "line " + std::to_string(line) + ": "
                        : file + ":" + std::to_string(line) + ": ";
  }
  return file.empty() ? std::string() : file + ": ";
}

/// A token of the input for a message: quoted, cut after a few bytes, unprintable bytes escaped
/// (fuzzed input must not put control characters into a terminal).
std::string shown(std::string_view token) {
  constexpr std::size_t kMaxShown = 24;
  std::string out = "'";
  for (std::size_t i = 0; i < token.size() && i < kMaxShown; ++i) {
    const auto c = static_cast<unsigned char>(token[i]);
    if (c >= 0x20 && c < 0x7f) {
      out += static_cast<char>(c);
    } else {
      char buffer[8];
      std::snprintf(buffer, sizeof buffer, "\\x%02x", c);
      out += buffer;
    }
  }
  if (token.size() > kMaxShown) out += "...";
  return out + "'";
}

std::string formatPosition(const Vec3& p) {
  char buffer[96];
  std::snprintf(buffer, sizeof buffer, "(%.17g, %.17g, %.17g)", p.x(), p.y(), p.z());
  return buffer;
}

// ===  Lines, tokens and numbers  ================================================================

inline bool isBlank(char c) {
  return c == ' ' || c == '\t' || c == '\r' || c == '\v' || c == '\f';
}

/// Splits bytes into lines ('\n' or "\r\n"), counting them from 1.
class LineReader {
 public:
  explicit LineReader(std::string_view bytes)
      : next_(bytes.data()), end_(bytes.data() + bytes.size()) {}

  /// The next line without its end-of-line bytes; false at the end of the input.
  bool next(std::string_view& line) {
    if (next_ == end_) return false;
    const auto* newline =
        static_cast<const char*>(std::memchr(next_, '\n', static_cast<std::size_t>(end_ - next_)));
    const char* lineEnd = newline ? newline : end_;
    line = std::string_view(next_, static_cast<std::size_t>(lineEnd - next_));
    if (!line.empty() && line.back() == '\r') line.remove_suffix(1);
    next_ = newline ? newline + 1 : end_;
    if (lineNumber_ < std::numeric_limits<int>::max()) ++lineNumber_;
    return true;
  }
  int lineNumber() const { return lineNumber_; }
  /// Bytes after the line last returned.
  std::size_t remainingBytes() const { return static_cast<std::size_t>(end_ - next_); }
  const char* position() const { return next_; }

 private:
  const char* next_;
  const char* end_;
  int lineNumber_ = 0;
};

/// Whitespace-separated tokens of one line.
class Tokens {
 public:
  explicit Tokens(std::string_view line) : rest_(line) {}

  bool next(std::string_view& token) {
    skipBlanks();
    if (rest_.empty()) return false;
    std::size_t end = 0;
    while (end < rest_.size() && !isBlank(rest_[end])) ++end;
    token = rest_.substr(0, end);
    rest_.remove_prefix(end);
    return true;
  }
  bool atEnd() {
    skipBlanks();
    return rest_.empty();
  }

 private:
  void skipBlanks() {
    std::size_t i = 0;
    while (i < rest_.size() && isBlank(rest_[i])) ++i;
    rest_.remove_prefix(i);
  }
  std::string_view rest_;
};

/// Cuts a '#' comment off a line (OFF and OBJ).
std::string_view withoutComment(std::string_view line) {
  const std::size_t hash = line.find('#');
  return hash == std::string_view::npos ? line : line.substr(0, hash);
}

/// from_chars rejects a leading '+', which some writers emit; "+-1" stays invalid.
const char* skipPlus(const char* begin, const char* end) {
  if (end - begin >= 2 && begin[0] == '+' && begin[1] != '-' && begin[1] != '+') return begin + 1;
  return begin;
}

/// The whole token as a double (from_chars: locale-independent, correctly rounded). Values beyond
/// the double range become ±inf (validateMesh then reports them) or ±0, as strtod would give.
bool parseDouble(std::string_view token, double& out) {
  const char* end = token.data() + token.size();
  const char* begin = skipPlus(token.data(), end);
  if (begin == end) return false;
  const auto [stop, error] = detail::fromCharsDouble(begin, end, out);
  if (stop != end) return false;
  if (error == std::errc()) return true;
  if (error != std::errc::result_out_of_range) return false;
  // Out of range: a negative decimal exponent means too small, anything else too large. (A
  // mantissa like 0.000…1e+5 with hundreds of zeros would be misjudged; no writer emits that.)
  const bool negative = *begin == '-';
  const char* exponent = std::find_if(begin, end, [](char c) { return c == 'e' || c == 'E'; });
  const bool tiny = exponent + 1 < end && exponent[1] == '-';
  const double magnitude = tiny ? 0.0 : std::numeric_limits<double>::infinity();
  out = negative ? -magnitude : magnitude;
  return true;
}

/// The whole token as an integer.
bool parseInteger(std::string_view token, long long& out) {
  const char* end = token.data() + token.size();
  const char* begin = skipPlus(token.data(), end);
  if (begin == end) return false;
  const auto [stop, error] = std::from_chars(begin, end, out);
  return error == std::errc() && stop == end;
}

bool equalsIgnoringCase(std::string_view a, std::string_view b) {
  return a.size() == b.size() &&
         std::equal(a.begin(), a.end(), b.begin(), [](char x, char y) {
           return std::tolower(static_cast<unsigned char>(x)) ==
                  std::tolower(static_cast<unsigned char>(y));
         });
}

// ===  Building the soup  ========================================================================

/// Highest element count a soup can hold: indices are 32-bit and kNoIndex is reserved.
constexpr std::uint64_t kMaxElements = kNoIndex;

/// Collects what a parser reads: vertices and polygons with their lines, fan triangulation and
/// its one warning, and the error thrown for anything malformed.
class SoupBuilder {
 public:
  explicit SoupBuilder(std::string fileName) { soup_.fileName = std::move(fileName); }

  [[noreturn]] void fail(const char* kind, int line, const std::string& what) const {
    throw InputError(kind, where(soup_.fileName, line) + what);
  }

  /// Call only with counts already checked against the bytes that remain.
  void reserve(std::uint64_t vertices, std::uint64_t faces) {
    soup_.positions.reserve(vertices);
    soup_.vertexLines.reserve(vertices);
    soup_.faces.reserve(faces);
    soup_.faceLines.reserve(faces);
  }

  void addVertex(double x, double y, double z, int line) {
    if (soup_.positions.size() + 1 >= kMaxElements) {
      fail("absurd-count", line, "more vertices than 32-bit indices can address");
    }
    soup_.positions.emplace_back(x, y, z);
    soup_.vertexLines.push_back(line);
  }

  std::size_t numVertices() const { return soup_.positions.size(); }
  /// Faces read so far, counting a polygon once (the index used in reader messages).
  std::size_t numSourceFaces() const { return sourceFaces_; }

  /// A face with corners `corners` (vertex indices, not yet checked against the vertex count),
  /// fan-triangulated when it has more than three: each triangle keeps the polygon's line.
  void addPolygon(std::span<const Index> corners, int line) {
    if (corners.size() < 3) {
      fail("face-too-small", line,
           "face " + std::to_string(sourceFaces_) + " has " + std::to_string(corners.size()) +
               " corner(s); a face needs at least 3");
    }
    if (soup_.faces.size() + corners.size() - 2 >= kMaxElements) {
      fail("absurd-count", line, "more faces than 32-bit indices can address");
    }
    if (corners.size() > 3) {
      if (polygons_ == 0) {
        firstPolygonLine_ = line;
        firstPolygonSource_ = sourceFaces_;
        firstPolygonTriangle_ = soup_.faces.size();
        firstPolygonCorners_ = corners.size();
      }
      ++polygons_;
      polygonTriangles_ += corners.size() - 2;
    }
    for (std::size_t k = 1; k + 1 < corners.size(); ++k) {
      soup_.faces.push_back({corners[0], corners[k], corners[k + 1]});
      soup_.faceLines.push_back(line);
    }
    ++sourceFaces_;
  }

  void warn(const char* kind, int line, const std::string& what) {
    issues_.push_back({Severity::Warning, kind, where(soup_.fileName, line) + what});
  }

  MeshReadResult finish() {
    if (soup_.faces.empty()) {
      fail("empty-mesh", 0,
           "no faces found (" + std::to_string(soup_.positions.size()) + " vertices)");
    }
    if (polygons_ > 0) {
      warn("polygon-triangulated", firstPolygonLine_,
           "face " + std::to_string(firstPolygonSource_) + " has " +
               std::to_string(firstPolygonCorners_) + " corners and became triangles " +
               std::to_string(firstPolygonTriangle_) + ".." +
               std::to_string(firstPolygonTriangle_ + firstPolygonCorners_ - 3) + "; " +
               std::to_string(polygons_) +
               " polygon(s) with more than 3 corners were fan-triangulated into " +
               std::to_string(polygonTriangles_) + " triangles");
    }
    return {std::move(soup_), std::move(issues_)};
  }

 private:
  TriangleSoup soup_;
  std::vector<MeshIssue> issues_;
  std::size_t sourceFaces_ = 0;
  std::size_t polygons_ = 0;
  std::size_t polygonTriangles_ = 0;
  int firstPolygonLine_ = 0;
  std::size_t firstPolygonSource_ = 0;
  std::size_t firstPolygonTriangle_ = 0;
  std::size_t firstPolygonCorners_ = 0;
};

// ===  OBJ  ======================================================================================

/// OBJ statements that do not describe triangle geometry: skipped silently.
bool isIgnoredObjStatement(std::string_view keyword) {
  static constexpr std::string_view kIgnored[] = {
      "vt",     "vn",       "vp",       "g",      "o",          "s",         "usemtl", "mtllib",
      "l",      "p",        "cstype",   "deg",    "bmat",       "step",      "curv",   "curv2",
      "surf",   "parm",     "trim",     "hole",   "scrv",       "sp",        "end",    "con",
      "mg",     "lod",      "usemap",   "maplib", "shadow_obj", "trace_obj", "ctech",  "stech",
      "bevel",  "c_interp", "d_interp", "call",   "csh"};
  return std::find(std::begin(kIgnored), std::end(kIgnored), keyword) != std::end(kIgnored);
}

/// The vertex of an OBJ face corner "i", "i/t", "i/t/n" or "i//n" (t and n are checked for syntax
/// and dropped); negative i counts back from the last vertex read so far.
Index objCornerVertex(std::string_view token, const SoupBuilder& builder, int line) {
  const auto face = [&] { return "face " + std::to_string(builder.numSourceFaces()); };
  const auto bad = [&] {
    builder.fail("syntax", line,
                 face() + ": " + shown(token) + " is not a vertex reference (i, i/t, i/t/n or i//n)");
  };
  const std::size_t slash = token.find('/');
  long long index = 0;
  if (!parseInteger(token.substr(0, slash), index)) bad();
  if (slash != std::string_view::npos) {
    std::string_view rest = token.substr(slash + 1);
    const std::size_t second = rest.find('/');
    long long ignored = 0;
    const std::string_view texture = rest.substr(0, second);
    if (!texture.empty() && !parseInteger(texture, ignored)) bad();
    if (second != std::string_view::npos) {
      const std::string_view normal = rest.substr(second + 1);
      if (normal.empty() || !parseInteger(normal, ignored)) bad();
    }
  }
  if (index == 0) {
    builder.fail("index-out-of-range", line, face() + ": vertex index 0 (OBJ indices start at 1)");
  }
  if (index < 0) {
    const long long resolved = static_cast<long long>(builder.numVertices()) + index;
    if (resolved < 0) {
      builder.fail("index-out-of-range", line,
                   face() + ": relative vertex index " + std::to_string(index) +
                       " points before the first vertex (" +
                       std::to_string(builder.numVertices()) + " vertices so far)");
    }
    return static_cast<Index>(resolved);
  }
  if (static_cast<std::uint64_t>(index - 1) >= kMaxElements) {
    builder.fail("index-out-of-range", line,
                 face() + ": vertex index " + std::to_string(index) + " is too large");
  }
  return static_cast<Index>(index - 1);
}

void parseObj(std::string_view bytes, SoupBuilder& builder) {
  LineReader lines(bytes);
  std::string_view line;
  std::string_view token;
  std::vector<Index> corners;
  std::size_t unknownStatements = 0;
  int firstUnknownLine = 0;
  std::string firstUnknown;
  while (lines.next(line)) {
    const int lineNumber = lines.lineNumber();
    Tokens tokens(line);
    std::string_view keyword;
    if (!tokens.next(keyword) || keyword[0] == '#') continue;
    if (keyword == "v") {
      const auto vertex = [&] { return "vertex " + std::to_string(builder.numVertices()); };
      double xyz[3];
      for (int k = 0; k < 3; ++k) {
        if (!tokens.next(token)) {
          builder.fail("syntax", lineNumber,
                       vertex() + ": expected 3 coordinates 'v x y z', found " + std::to_string(k));
        }
        if (!parseDouble(token, xyz[k])) {
          builder.fail("syntax", lineNumber, vertex() + ": " + shown(token) + " is not a number");
        }
      }
      // An optional weight w, or the r g b colours some writers append: numbers, ignored.
      double ignored = 0.0;
      while (tokens.next(token) && token[0] != '#') {
        if (!parseDouble(token, ignored)) {
          builder.fail("syntax", lineNumber, vertex() + ": " + shown(token) + " is not a number");
        }
      }
      builder.addVertex(xyz[0], xyz[1], xyz[2], lineNumber);
    } else if (keyword == "f") {
      corners.clear();
      while (tokens.next(token) && token[0] != '#') {
        corners.push_back(objCornerVertex(token, builder, lineNumber));
      }
      builder.addPolygon(corners, lineNumber);
    } else if (isIgnoredObjStatement(keyword)) {
      continue;
    } else if (std::isalpha(static_cast<unsigned char>(keyword[0]))) {
      // Perhaps a vendor extension: worth a warning, not a refusal.
      if (unknownStatements++ == 0) {
        firstUnknownLine = lineNumber;
        firstUnknown = shown(keyword);
      }
    } else {
      builder.fail("syntax", lineNumber,
                   shown(keyword) + " does not start an OBJ statement (v, f, vt, vn, ...)");
    }
  }
  if (unknownStatements > 0) {
    builder.warn("unknown-statement", firstUnknownLine,
                 "ignored " + std::to_string(unknownStatements) +
                     " line(s) with unknown OBJ statements, the first being " + firstUnknown);
  }
}

// ===  OFF  ======================================================================================

/// Counts above one element per remaining byte are refused at once as absurd (every line takes
/// at least two). Counts a little too high for a truncated file instead run into the precise
/// "file ends after ..." error, the common case. Valid vertex ("0 0 0\n") and triangle
/// ("3 0 1 2\n") lines are longer still, which caps reserve() tighter.
constexpr std::uint64_t kMinOffVertexBytes = 6;
constexpr std::uint64_t kMinOffFaceBytes = 8;

void parseOff(std::string_view bytes, SoupBuilder& builder) {
  LineReader lines(bytes);
  std::string_view line;
  std::string_view token;
  // The next line with something other than blanks and a comment.
  const auto nextDataLine = [&]() {
    while (lines.next(line)) {
      line = withoutComment(line);
      if (!Tokens(line).atEnd()) return true;
    }
    return false;
  };

  if (!nextDataLine()) builder.fail("truncated", 0, "empty OFF file");
  Tokens header(line);
  header.next(token);
  // Vertex lines carry colours, normals or texture coordinates after x y z ("COFF", "NOFF",
  // "STOFF", ...): those extra numbers are skipped. Plain "OFF" must have exactly three.
  bool extraVertexValues = false;
  if (token.size() >= 3 && token.substr(token.size() - 3) == "OFF") {
    const std::string_view prefix = token.substr(0, token.size() - 3);
    for (const char c : prefix) {
      if (c == '4' || c == 'n') {
        builder.fail("unsupported-format", lines.lineNumber(),
                     shown(token) + ": only 3-D OFF is supported (not 4OFF or nOFF)");
      }
      if (c != 'S' && c != 'T' && c != 'C' && c != 'N') {
        builder.fail("syntax", lines.lineNumber(), shown(token) + " is not an OFF header");
      }
    }
    extraVertexValues = !prefix.empty();
    Tokens afterHeader = header;
    if (afterHeader.next(token) && token == "BINARY") {
      builder.fail("unsupported-format", lines.lineNumber(), "binary OFF is not supported");
    }
    // The counts may follow the header on its line ("OFF 8 6 12").
    if (header.atEnd() && !nextDataLine()) {
      builder.fail("truncated", lines.lineNumber(), "file ends before the OFF counts line");
    }
    if (!header.atEnd()) line = line.substr(line.find("OFF") + 3);
  }

  const int countsLine = lines.lineNumber();
  long long counts[3] = {0, 0, 0};
  int numCounts = 0;
  Tokens countTokens(line);
  while (countTokens.next(token)) {
    if (numCounts == 3 || !parseInteger(token, counts[numCounts]) || counts[numCounts] < 0) {
      builder.fail("syntax", countsLine,
                   "expected the OFF counts 'vertices faces edges', found " + shown(token));
    }
    ++numCounts;
  }
  if (numCounts < 2) {
    builder.fail("syntax", countsLine, "expected the OFF counts 'vertices faces edges'");
  }
  const auto numVertices = static_cast<std::uint64_t>(counts[0]);
  const auto numFaces = static_cast<std::uint64_t>(counts[1]);
  const std::uint64_t budget = lines.remainingBytes() + 1;  // the last newline may be missing
  if (numVertices > budget || numFaces > budget - numVertices) {
    builder.fail("absurd-count", countsLine,
                 "the counts announce " + std::to_string(numVertices) + " vertices and " +
                     std::to_string(numFaces) + " faces, but only " +
                     std::to_string(lines.remainingBytes()) + " bytes follow");
  }
  builder.reserve(std::min(numVertices, budget / kMinOffVertexBytes),
                  std::min(numFaces, budget / kMinOffFaceBytes));

  for (std::uint64_t v = 0; v < numVertices; ++v) {
    const auto vertex = [&] { return "vertex " + std::to_string(v); };
    if (!nextDataLine()) {
      builder.fail("truncated", lines.lineNumber(),
                   "file ends after " + std::to_string(v) + " of the " +
                       std::to_string(numVertices) + " vertices announced on line " +
                       std::to_string(countsLine));
    }
    Tokens tokens(line);
    double xyz[3];
    int found = 0;
    double ignored = 0.0;
    while (tokens.next(token)) {
      if (!parseDouble(token, found < 3 ? xyz[found] : ignored)) {
        builder.fail("syntax", lines.lineNumber(),
                     vertex() + ": " + shown(token) + " is not a number");
      }
      ++found;
    }
    if (found < 3 || (found > 3 && !extraVertexValues)) {
      builder.fail("syntax", lines.lineNumber(),
                   vertex() + ": expected 3 coordinates, found " + std::to_string(found) +
                       " numbers");
    }
    builder.addVertex(xyz[0], xyz[1], xyz[2], lines.lineNumber());
  }

  std::vector<Index> corners;
  for (std::uint64_t f = 0; f < numFaces; ++f) {
    const auto face = [&] { return "face " + std::to_string(f); };
    if (!nextDataLine()) {
      builder.fail("truncated", lines.lineNumber(),
                   "file ends after " + std::to_string(f) + " of the " +
                       std::to_string(numFaces) + " faces announced on line " +
                       std::to_string(countsLine));
    }
    const int faceLine = lines.lineNumber();
    Tokens tokens(line);
    long long numCorners = 0;
    tokens.next(token);
    if (!parseInteger(token, numCorners) || numCorners < 0) {
      builder.fail("syntax", faceLine,
                   face() + ": expected the number of corners, found " + shown(token));
    }
    corners.clear();
    for (long long k = 0; k < numCorners; ++k) {
      long long index = 0;
      if (!tokens.next(token)) {
        builder.fail("syntax", faceLine,
                     face() + ": announces " + std::to_string(numCorners) +
                         " corners but the line has only " + std::to_string(k) + " indices");
      }
      if (!parseInteger(token, index)) {
        builder.fail("syntax", faceLine,
                     face() + ": " + shown(token) + " is not a vertex index");
      }
      if (index < 0 || static_cast<std::uint64_t>(index) >= kMaxElements) {
        builder.fail("index-out-of-range", faceLine,
                     face() + ": vertex index " + std::to_string(index) + " is out of range");
      }
      corners.push_back(static_cast<Index>(index));
    }
    // Optional colour after the indices: numbers, ignored.
    double ignored = 0.0;
    while (tokens.next(token)) {
      if (!parseDouble(token, ignored)) {
        builder.fail("syntax", faceLine,
                     face() + ": " + shown(token) + " after the indices is not a colour value");
      }
    }
    builder.addPolygon(corners, faceLine);
  }

  if (nextDataLine()) {
    builder.fail("count-mismatch", lines.lineNumber(),
                 "more data after the " + std::to_string(numVertices) + " vertices and " +
                     std::to_string(numFaces) + " faces announced on line " +
                     std::to_string(countsLine));
  }
}

// ===  PLY  ======================================================================================

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

PlyHeader parsePlyHeader(LineReader& lines, const SoupBuilder& builder) {
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
      if (!tokens.next(token)) token = {};
      if (token == "ascii") {
        header.encoding = PlyEncoding::Ascii;
      } else if (token == "binary_little_endian") {
        header.encoding = PlyEncoding::LittleEndian;
      } else if (token == "binary_big_endian") {
        header.encoding = PlyEncoding::BigEndian;
      } else {
        builder.fail("syntax", lineNumber, "unknown PLY format " + shown(token));
      }
      sawFormat = true;
    } else if (keyword == "element") {
      PlyElement element;
      std::string_view countToken;
      long long count = 0;
      if (!tokens.next(token) || !tokens.next(countToken) || !parseInteger(countToken, count) ||
          count < 0 || !tokens.atEnd()) {
        builder.fail("syntax", lineNumber, "expected 'element NAME COUNT'");
      }
      element.name = std::string(token);
      element.count = static_cast<std::uint64_t>(count);
      element.line = lineNumber;
      header.elements.push_back(std::move(element));
    } else if (keyword == "property") {
      if (header.elements.empty()) {
        builder.fail("syntax", lineNumber, "property before any element");
      }
      PlyProperty property;
      std::string_view typeToken;
      bool valid = tokens.next(typeToken);
      if (valid && typeToken == "list") {
        property.isList = true;
        std::string_view countType;
        valid = tokens.next(countType) && parsePlyType(countType, property.countType) &&
                tokens.next(typeToken);
      }
      valid = valid && parsePlyType(typeToken, property.type) && tokens.next(token) &&
              tokens.atEnd();
      if (!valid) {
        builder.fail("syntax", lineNumber,
                     "expected 'property TYPE NAME' or 'property list COUNTTYPE TYPE NAME'");
      }
      property.name = std::string(token);
      header.elements.back().properties.push_back(std::move(property));
    } else {
      builder.fail("syntax", lineNumber, shown(keyword) + " is not a PLY header keyword");
    }
  }
  if (!sawEnd) builder.fail("truncated", lines.lineNumber(), "PLY header without 'end_header'");
  if (!sawFormat) builder.fail("syntax", lines.lineNumber(), "PLY header without 'format'");

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
  if (header.vertexElement < 0) builder.fail("syntax", lines.lineNumber(), "no vertex element");
  if (header.faceElement < 0) builder.fail("syntax", lines.lineNumber(), "no face element");
  if (header.elements[header.vertexElement].count >= kMaxElements) {
    builder.fail("absurd-count", header.elements[header.vertexElement].line,
                 "the header announces " +
                     std::to_string(header.elements[header.vertexElement].count) +
                     " vertices, more than 32-bit indices can address");
  }
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

// ===  Format detection  =========================================================================

/// "off", "obj", "ply" from the first bytes, or "" when they do not tell.
std::string detectFormat(std::string_view bytes) {
  LineReader lines(bytes);
  std::string_view line;
  std::string_view token;
  while (lines.next(line)) {
    Tokens tokens(withoutComment(line));
    if (!tokens.next(token)) continue;
    if (token == "ply" && lines.lineNumber() == 1) return "ply";
    if (token.size() >= 3 && token.substr(token.size() - 3) == "OFF") return "off";
    static constexpr std::string_view kObjStarts[] = {"v", "vt", "vn", "vp", "f", "g",
                                                      "o", "s",  "l",  "usemtl", "mtllib"};
    if (std::find(std::begin(kObjStarts), std::end(kObjStarts), token) != std::end(kObjStarts)) {
      return "obj";
    }
    long long count = 0;
    if (parseInteger(token, count)) return "off";  // OFF without its optional header line
    return "";
  }
  return "";
}

// ===  Validation  ===============================================================================

class UnionFind {
 public:
  explicit UnionFind(std::size_t size) : parent_(size) {
    std::iota(parent_.begin(), parent_.end(), std::size_t{0});
  }
  std::size_t find(std::size_t x) {
    while (parent_[x] != x) {
      parent_[x] = parent_[parent_[x]];  // path halving
      x = parent_[x];
    }
    return x;
  }
  void unite(std::size_t a, std::size_t b) {
    a = find(a);
    b = find(b);
    if (a < b) parent_[b] = a;
    if (b < a) parent_[a] = b;
  }

 private:
  std::vector<std::size_t> parent_;
};

/// Names elements of a soup in messages, with their file lines when the soup has them.
class Namer {
 public:
  explicit Namer(const TriangleSoup& soup)
      : soup_(soup),
        hasFaceLines_(soup.faceLines.size() == soup.faces.size()),
        hasVertexLines_(soup.vertexLines.size() == soup.positions.size()) {}

  /// "FILE:LINE: " for the start of a message about face f.
  std::string atFace(std::size_t f) const {
    return where(soup_.fileName, hasFaceLines_ ? soup_.faceLines[f] : 0);
  }
  std::string atVertex(std::size_t v) const {
    return where(soup_.fileName, hasVertexLines_ ? soup_.vertexLines[v] : 0);
  }
  /// "face 12 (line 34)", or "face 12" when the line is unknown.
  std::string face(std::size_t f) const {
    return "face " + std::to_string(f) + lineNote(hasFaceLines_ ? soup_.faceLines[f] : 0);
  }
  std::string vertex(std::size_t v) const {
    return "vertex " + std::to_string(v) +
           lineNote(hasVertexLines_ ? soup_.vertexLines[v] : 0);
  }

 private:
  static std::string lineNote(int line) {
    return line > 0 ? " (line " + std::to_string(line) + ")" : std::string();
  }
  const TriangleSoup& soup_;
  bool hasFaceLines_;
  bool hasVertexLines_;
};

/// Every occurrence of one kind of problem, reported as one issue: the first in a full sentence,
/// a few more by name, and the count (a dirty scan has thousands of some kinds).
class Finding {
 public:
  static constexpr std::size_t kExamples = 5;

  /// `describe(true)` gives the full first sentence, `describe(false)` a short example; neither
  /// is called once enough examples are known, so counting stays cheap.
  template <class Describe>
  void add(Describe&& describe) {
    if (count_ == 0) {
      first_ = describe(true);
    } else if (count_ < kExamples) {
      more_.push_back(describe(false));
    }
    ++count_;
  }
  std::size_t count() const { return count_; }

  void report(std::vector<MeshIssue>& issues, Severity severity, const char* kind,
              const char* noun) const {
    if (count_ == 0) return;
    std::string message = first_;
    if (count_ > 1) {
      message += " [" + std::to_string(count_) + " " + noun + " in all; also ";
      for (std::size_t i = 0; i < more_.size(); ++i) message += (i ? ", " : "") + more_[i];
      if (count_ > kExamples) message += ", ...";
      message += "]";
    }
    issues.push_back({severity, kind, message});
  }

 private:
  std::size_t count_ = 0;
  std::string first_;
  std::vector<std::string> more_;
};

/// One side of an edge in a face: the edge from face[local] to face[(local+1)%3].
struct HalfEdge {
  std::uint64_t key;  ///< smaller vertex << 32 | larger vertex
  Index face;
  std::uint8_t local;
  bool forward;  ///< runs from the smaller vertex to the larger
};

/// Positions compare with -0 == +0, like the zero-length-edge test.
bool positionLess(const Vec3& a, const Vec3& b) {
  if (a.x() != b.x()) return a.x() < b.x();
  if (a.y() != b.y()) return a.y() < b.y();
  return a.z() < b.z();
}

}  // namespace

// ===  Public functions  =========================================================================

MeshReadResult readMeshFromMemory(std::string_view bytes, const std::string& nameForMessages,
                                  const std::string& formatHint) {
  SoupBuilder builder(nameForMessages);
  std::string format = formatHint;
  std::transform(format.begin(), format.end(), format.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  if (format.empty()) format = detectFormat(bytes);
  if (format == "obj") {
    parseObj(bytes, builder);
  } else if (format == "off") {
    parseOff(bytes, builder);
  } else if (format == "ply") {
    parsePly(bytes, builder);
  } else if (formatHint.empty()) {
    builder.fail("unknown-format", 0, "cannot tell the mesh format (OFF, OBJ or PLY expected)");
  } else {
    builder.fail("unknown-format", 0,
                 "unknown mesh format " + shown(formatHint) + " (off, obj or ply expected)");
  }
  return builder.finish();
}

MeshReadResult readMesh(const std::string& path) {
  std::error_code error;
  if (!std::filesystem::is_regular_file(path, error)) {
    throw InputError("io", path + ": cannot read: " +
                               (error ? error.message() : std::string("not a regular file")));
  }
  std::ifstream file(path, std::ios::binary);
  if (!file) {
    throw InputError("io", path + ": cannot open: " + std::strerror(errno));
  }
  file.seekg(0, std::ios::end);
  const std::streamoff size = file.tellg();
  file.seekg(0, std::ios::beg);
  if (size < 0) throw InputError("io", path + ": cannot read (not a regular file?)");
  std::string bytes(static_cast<std::size_t>(size), '\0');
  if (!file.read(bytes.data(), size)) throw InputError("io", path + ": read error");

  std::string format;
  const std::size_t dot = path.find_last_of('.');
  const std::size_t slash = path.find_last_of("/\\");
  if (dot != std::string::npos && (slash == std::string::npos || dot > slash)) {
    const std::string_view extension = std::string_view(path).substr(dot + 1);
    for (const char* known : {"off", "obj", "ply"}) {
      if (equalsIgnoringCase(extension, known)) format = known;
    }
  }
  return readMeshFromMemory(bytes, path, format);
}

void validateMesh(const TriangleSoup& soup, std::vector<MeshIssue>& issues) {
  const Namer name(soup);
  const std::size_t numVertices = soup.positions.size();
  const std::size_t numFaces = soup.faces.size();
  const auto& positions = soup.positions;
  const auto& faces = soup.faces;

  // --- Per vertex and per face ---
  Finding nonFinite;
  std::vector<std::uint8_t> finite(numVertices, 0);
  for (std::size_t v = 0; v < numVertices; ++v) {
    finite[v] = isFinite(positions[v]) ? 1 : 0;
    if (finite[v]) continue;
    nonFinite.add([&](bool full) {
      return full ? name.atVertex(v) + "vertex " + std::to_string(v) +
                        " has a non-finite coordinate " + formatPosition(positions[v])
                  : name.vertex(v);
    });
  }

  // Mesh units (MeshUnit), from the vertices of faces whose indices are in range, as Mesh has it.
  double largestCoordinate = 0.0;
  for (const auto& t : faces) {
    if (t[0] >= numVertices || t[1] >= numVertices || t[2] >= numVertices) continue;
    for (const Index v : t)
      if (finite[v]) largestCoordinate = std::max(largestCoordinate, positions[v].cwiseAbs().maxCoeff());
  }
  const MeshUnit unit = meshUnitOf(largestCoordinate);

  Finding outOfRange, repeatedIndex, zeroLengthEdge, edgeLengthRange, edgeLengthSpread, zeroArea;
  // usable: indices in range and distinct, so everything below may index with them.
  std::vector<std::uint8_t> usable(numFaces, 0);
  std::vector<std::uint8_t> referenced(numVertices, 0);
  for (std::size_t f = 0; f < numFaces; ++f) {
    const auto& t = faces[f];
    const auto bad = std::find_if(t.begin(), t.end(), [&](Index v) { return v >= numVertices; });
    for (const Index v : t) {
      if (v < numVertices) referenced[v] = 1;
    }
    if (bad != t.end()) {
      outOfRange.add([&](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) + " refers to vertex " +
                          std::to_string(*bad) + ", but there are only " +
                          std::to_string(numVertices) + " vertices"
                    : name.face(f) + " -> vertex " + std::to_string(*bad);
      });
      continue;
    }
    if (t[0] == t[1] || t[1] == t[2] || t[2] == t[0]) {
      const Index twice = t[0] == t[1] || t[0] == t[2] ? t[0] : t[1];
      repeatedIndex.add([&](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) + " uses vertex " +
                          std::to_string(twice) + " twice (" + std::to_string(t[0]) + ", " +
                          std::to_string(t[1]) + ", " + std::to_string(t[2]) + ")"
                    : name.face(f) + " repeating vertex " + std::to_string(twice);
      });
      continue;
    }
    usable[f] = 1;
    if (!finite[t[0]] || !finite[t[1]] || !finite[t[2]]) continue;
    const auto sharedPosition = [&](int k) { return positions[t[k]] == positions[t[(k + 1) % 3]]; };
    if (sharedPosition(0) || sharedPosition(1) || sharedPosition(2)) {
      const int k = sharedPosition(0) ? 0 : sharedPosition(1) ? 1 : 2;
      const Index a = t[k];
      const Index b = t[(k + 1) % 3];
      zeroLengthEdge.add([&](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) +
                          " has a zero-length edge: its vertices " + std::to_string(a) + " and " +
                          std::to_string(b) + " have the same position " +
                          formatPosition(positions[a])
                    : name.face(f) + " with edge " + std::to_string(a) + "-" +
                          std::to_string(b);
      });
      continue;
    }
    bool lengthsInRange = true;
    for (int k = 0; k < 3 && lengthsInRange; ++k) {
      const Index a = t[k];
      const Index b = t[(k + 1) % 3];
      const double length = ((positions[b] - positions[a]) * unit.inverse).norm();
      const EdgeLengthProblem problem = edgeLengthProblem(length, unit);
      if (problem == EdgeLengthProblem::None) continue;
      lengthsInRange = false;
      Finding& finding = problem == EdgeLengthProblem::Spread ? edgeLengthSpread : edgeLengthRange;
      finding.add([&, a, b, length, problem](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) + ": edge " + std::to_string(a) +
                          "-" + std::to_string(b) + " " +
                          describeEdgeLengthProblem(problem, length, unit)
                    : name.face(f) + " with edge " + std::to_string(a) + "-" + std::to_string(b);
      });
    }
    if (!lengthsInRange) continue;
    const auto at = [&](int k) -> Vec3 { return positions[t[k]] * unit.inverse; };  // mesh units
    const Vec3 normal = (at(1) - at(0)).cross(at(2) - at(0));
    if (normal.x() == 0.0 && normal.y() == 0.0 && normal.z() == 0.0) {
      zeroArea.add([&](bool full) {
        return full ? name.atFace(f) + "face " + std::to_string(f) +
                          " has zero area: its three distinct corners " + std::to_string(t[0]) +
                          ", " + std::to_string(t[1]) + ", " + std::to_string(t[2]) +
                          " are collinear"
                    : name.face(f);
      });
    }
  }

  // --- Edges: sorted half-edges, equal keys are the sides of one edge ---
  std::vector<HalfEdge> halfEdges;
  halfEdges.reserve(3 * numFaces);
  for (std::size_t f = 0; f < numFaces; ++f) {
    if (!usable[f]) continue;
    for (int k = 0; k < 3; ++k) {
      const Index a = faces[f][k];
      const Index b = faces[f][(k + 1) % 3];
      const std::uint64_t key = (std::uint64_t{std::min(a, b)} << 32) | std::max(a, b);
      halfEdges.push_back({key, static_cast<Index>(f), static_cast<std::uint8_t>(k), a < b});
    }
  }
  std::sort(halfEdges.begin(), halfEdges.end(), [](const HalfEdge& x, const HalfEdge& y) {
    return x.key != y.key ? x.key < y.key : x.face < y.face;
  });

  // Corners 3f + k are merged across every shared edge at both of its ends: afterwards the
  // corners at a vertex form one set per edge-connected fan.
  UnionFind fans(3 * numFaces);
  const auto cornerAt = [&](Index f, Index v) {
    const auto& t = faces[f];
    return 3 * std::size_t{f} + (t[0] == v ? 0 : t[1] == v ? 1 : 2);
  };
  Finding nonManifoldEdge, inconsistentWinding;
  for (std::size_t begin = 0, end = 0; begin < halfEdges.size(); begin = end) {
    end = begin + 1;
    while (end < halfEdges.size() && halfEdges[end].key == halfEdges[begin].key) ++end;
    const auto a = static_cast<Index>(halfEdges[begin].key >> 32);
    const auto b = static_cast<Index>(halfEdges[begin].key & 0xffffffffu);
    const std::size_t numSides = end - begin;
    if (numSides > 2) {
      nonManifoldEdge.add([&](bool full) {
        std::string text = full ? name.atFace(halfEdges[begin].face) : std::string();
        text += "edge " + std::to_string(a) + "-" + std::to_string(b);
        if (!full) return text;
        text += " has " + std::to_string(numSides) + " faces: ";
        for (std::size_t i = begin; i < end && i < begin + 6; ++i) {
          text += (i > begin ? ", " : "") + name.face(halfEdges[i].face);
        }
        return text + (numSides > 6 ? ", ..." : "");
      });
    }
    if (numSides == 2 && halfEdges[begin].forward == halfEdges[begin + 1].forward) {
      inconsistentWinding.add([&](bool full) {
        const Index f = halfEdges[begin].face;
        const Index g = halfEdges[begin + 1].face;
        return full ? name.atFace(f) + name.face(f) + " and " + name.face(g) +
                          " traverse their shared edge " + std::to_string(a) + "-" +
                          std::to_string(b) +
                          " in the same direction (inconsistent winding; the solver does not"
                          " need a consistent one)"
                    : "faces " + std::to_string(f) + " and " + std::to_string(g);
      });
    }
    for (std::size_t i = begin + 1; i < end; ++i) {
      for (const Index v : {a, b}) {
        fans.unite(cornerAt(halfEdges[begin].face, v), cornerAt(halfEdges[i].face, v));
      }
    }
  }
  halfEdges = {};

  // --- Duplicate faces: equal sorted vertex triples ---
  Finding duplicateFace;
  {
    std::vector<std::pair<std::array<Index, 3>, Index>> sorted;
    sorted.reserve(numFaces);
    for (std::size_t f = 0; f < numFaces; ++f) {
      if (!usable[f]) continue;
      std::array<Index, 3> t = faces[f];
      std::sort(t.begin(), t.end());
      sorted.push_back({t, static_cast<Index>(f)});
    }
    std::sort(sorted.begin(), sorted.end());
    for (std::size_t i = 1, first = 0; i < sorted.size(); ++i) {
      if (sorted[i].first != sorted[first].first) {
        first = i;
        continue;
      }
      const Index f = sorted[i].second;
      const Index g = sorted[first].second;
      duplicateFace.add([&](bool full) {
        const auto& t = faces[f];
        return full ? name.atFace(f) + "face " + std::to_string(f) + " has the same vertices {" +
                          std::to_string(t[0]) + ", " + std::to_string(t[1]) + ", " +
                          std::to_string(t[2]) + "} as " + name.face(g)
                    : "faces " + std::to_string(g) + " and " + std::to_string(f);
      });
    }
  }

  // --- Non-manifold vertices: corners in more than one fan ---
  Finding nonManifoldVertex;
  {
    constexpr std::size_t kNone = std::numeric_limits<std::size_t>::max();
    std::vector<std::size_t> firstFan(numVertices, kNone);
    std::vector<std::uint8_t> flagged(numVertices, 0);
    for (std::size_t f = 0; f < numFaces; ++f) {
      if (!usable[f]) continue;
      for (int k = 0; k < 3; ++k) {
        const Index v = faces[f][k];
        const std::size_t fan = fans.find(3 * f + k);
        if (firstFan[v] == kNone) firstFan[v] = fan;
        if (firstFan[v] == fan || flagged[v]) continue;
        flagged[v] = 1;
        const std::size_t other = firstFan[v] / 3;
        nonManifoldVertex.add([&](bool full) {
          return full ? name.atVertex(v) + "vertex " + std::to_string(v) +
                            " is non-manifold: its faces form more than one fan (" +
                            name.face(other) + " and " + name.face(f) +
                            " meet at it but are not linked through its edges)"
                      : name.vertex(v);
        });
      }
    }
  }

  // --- Unreferenced vertices ---
  Finding unreferenced;
  for (std::size_t v = 0; v < numVertices; ++v) {
    if (referenced[v]) continue;
    unreferenced.add([&](bool full) {
      return full ? name.atVertex(v) + "vertex " + std::to_string(v) +
                        " is used by no face (its distance will be +inf)"
                  : name.vertex(v);
    });
  }

  // --- Duplicated positions: equal neighbours after sorting ---
  Finding duplicatePosition;
  {
    std::vector<Index> order;
    order.reserve(numVertices);
    for (std::size_t v = 0; v < numVertices; ++v) {
      if (finite[v]) order.push_back(static_cast<Index>(v));
    }
    std::sort(order.begin(), order.end(), [&](Index x, Index y) {
      if (positionLess(positions[x], positions[y])) return true;
      if (positionLess(positions[y], positions[x])) return false;
      return x < y;
    });
    for (std::size_t i = 1, first = 0; i < order.size(); ++i) {
      if (positions[order[i]] != positions[order[first]]) {
        first = i;
        continue;
      }
      const Index v = order[i];
      const Index original = order[first];
      duplicatePosition.add([&](bool full) {
        return full ? name.atVertex(v) + "vertex " + std::to_string(v) + " has the same position " +
                          formatPosition(positions[v]) + " as " + name.vertex(original)
                    : name.vertex(v);
      });
    }
  }

  // --- Connected components, through shared vertices (as Mesh counts them) ---
  std::string componentsMessage;
  {
    UnionFind parts(numVertices);
    for (std::size_t f = 0; f < numFaces; ++f) {
      if (!usable[f]) continue;
      parts.unite(faces[f][0], faces[f][1]);
      parts.unite(faces[f][0], faces[f][2]);
    }
    std::vector<std::uint8_t> seen(numVertices, 0);
    std::size_t firstFace = 0;
    std::size_t count = 0;
    std::vector<std::size_t> startFaces;  // first face of each component after the first
    for (std::size_t f = 0; f < numFaces; ++f) {
      if (!usable[f]) continue;
      const std::size_t root = parts.find(faces[f][0]);
      if (seen[root]) continue;
      seen[root] = 1;
      if (count++ == 0) {
        firstFace = f;
      } else if (startFaces.size() < Finding::kExamples) {
        startFaces.push_back(f);
      }
    }
    if (count > 1) {
      std::string& message = componentsMessage;
      message = name.atFace(startFaces[0]) + name.face(startFaces[0]) +
                            " is not connected to " + name.face(firstFace) + ": the mesh has " +
                            std::to_string(count) +
                            " connected components (through shared vertices), and distances "
                            "between them are +inf; components start at faces " +
                            std::to_string(firstFace);
      for (const std::size_t f : startFaces) message += ", " + std::to_string(f);
      if (count > startFaces.size() + 1) message += ", ...";
    }
  }

  // Errors first, in the order loadMesh should report them; then warnings.
  nonFinite.report(issues, Severity::Error, "non-finite-coordinate", "vertices");
  outOfRange.report(issues, Severity::Error, "index-out-of-range", "faces");
  repeatedIndex.report(issues, Severity::Error, "repeated-index", "faces");
  zeroLengthEdge.report(issues, Severity::Error, "zero-length-edge", "faces");
  edgeLengthRange.report(issues, Severity::Error, "edge-length-out-of-range", "faces");
  edgeLengthSpread.report(issues, Severity::Error, "edge-length-spread", "faces");
  duplicateFace.report(issues, Severity::Error, "duplicate-face", "duplicates");
  nonManifoldEdge.report(issues, Severity::Error, "non-manifold-edge", "edges");
  zeroArea.report(issues, Severity::Warning, "zero-area-face", "faces");
  nonManifoldVertex.report(issues, Severity::Warning, "non-manifold-vertex", "vertices");
  unreferenced.report(issues, Severity::Warning, "unreferenced-vertex", "vertices");
  duplicatePosition.report(issues, Severity::Warning, "duplicate-position", "vertices");
  inconsistentWinding.report(issues, Severity::Warning, "inconsistent-winding", "edges");
  if (!componentsMessage.empty()) {
    issues.push_back({Severity::Warning, "components", std::move(componentsMessage)});
  }
}

Mesh loadMesh(const std::string& path, std::vector<MeshIssue>* warnings) {
  MeshReadResult result = readMesh(path);
  validateMesh(result.soup, result.issues);
  for (const MeshIssue& issue : result.issues) {
    if (issue.severity == Severity::Error) throw InputError(issue.kind, issue.message);
  }
  if (warnings) warnings->insert(warnings->end(), result.issues.begin(), result.issues.end());
  return Mesh(std::move(result.soup));
}

}  // namespace geodex
