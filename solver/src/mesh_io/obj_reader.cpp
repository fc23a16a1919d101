// The OBJ reader: vertices ("v") and faces ("f"). Statements of other geometry (texture
// coordinates, normals, groups, curves, ...) are skipped; unknown ones too, with one warning.

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <iterator>
#include <string>
#include <string_view>
#include <vector>

#include "readers.h"
#include "text_input.h"

namespace geodex::detail {
namespace {

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
    builder.fail(
        "syntax", line,
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

}  // namespace

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

}  // namespace geodex::detail
