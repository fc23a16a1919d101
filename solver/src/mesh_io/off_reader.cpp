// The OFF reader: an optional header line ("OFF", "COFF", ...), the counts, the vertex lines,
// the face lines, and nothing after them (see readers.h).

#include <algorithm>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

#include "readers.h"
#include "text_input.h"

namespace geodex::detail {
namespace {

/// Counts above one element per remaining byte are refused at once as absurd (every line takes
/// at least two). Counts a little too high for a truncated file instead run into the precise
/// "file ends after ..." error, the common case. Valid vertex ("0 0 0\n") and triangle
/// ("3 0 1 2\n") lines are longer still, which caps reserve() tighter.
constexpr std::uint64_t kMinOffVertexBytes = 6;
constexpr std::uint64_t kMinOffFaceBytes = 8;

/// The lines of an OFF file that hold data, with their '#' comments cut off: blank and
/// comment-only lines may stand anywhere and are skipped.
class OffLines {
 public:
  explicit OffLines(std::string_view bytes) : lines_(bytes) {}

  /// Moves to the next data line; false at the end of the input.
  bool next() {
    while (lines_.next(line_)) {
      line_ = withoutComment(line_);
      if (!Tokens(line_).atEnd()) return true;
    }
    return false;
  }
  std::string_view line() const { return line_; }
  int lineNumber() const { return lines_.lineNumber(); }
  std::size_t remainingBytes() const { return lines_.remainingBytes(); }

 private:
  LineReader lines_;
  std::string_view line_;
};

struct OffHeader {
  /// Vertex lines carry colours, normals or texture coordinates after x y z ("COFF", "NOFF",
  /// "STOFF", ...): those extra numbers are skipped. Plain "OFF" must have exactly three.
  bool extraVertexValues = false;
  std::string_view countsText;  ///< where the counts are: their own line, or the header's rest
};

/// Reads the header keyword off the first data line, if it has one (the header line is
/// optional); the counts may follow it on its line ("OFF 8 6 12").
OffHeader readOffHeader(OffLines& lines, const SoupBuilder& builder) {
  OffHeader result;
  result.countsText = lines.line();
  std::string_view token;
  Tokens header(lines.line());
  header.next(token);
  if (token.size() < 3 || token.substr(token.size() - 3) != "OFF") return result;

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
  result.extraVertexValues = !prefix.empty();
  Tokens afterHeader = header;
  if (afterHeader.next(token) && token == "BINARY") {
    builder.fail("unsupported-format", lines.lineNumber(), "binary OFF is not supported");
  }
  if (!header.atEnd()) {
    result.countsText = lines.line().substr(lines.line().find("OFF") + 3);
  } else if (lines.next()) {
    result.countsText = lines.line();
  } else {
    builder.fail("truncated", lines.lineNumber(), "file ends before the OFF counts line");
  }
  return result;
}

struct OffCounts {
  std::uint64_t vertices = 0;
  std::uint64_t faces = 0;
  int line = 0;  ///< where they were announced
};

/// The counts "vertices faces [edges]" (the edge count is not used), refused when the bytes that
/// follow could not hold that many elements; the soup is then reserved for them.
OffCounts readOffCounts(std::string_view countsText, const OffLines& lines,
                        SoupBuilder& builder) {
  const int countsLine = lines.lineNumber();
  long long counts[3] = {0, 0, 0};
  int numCounts = 0;
  std::string_view token;
  Tokens countTokens(countsText);
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
  return {numVertices, numFaces, countsLine};
}

void readOffVertices(OffLines& lines, const OffCounts& counts, bool extraVertexValues,
                     SoupBuilder& builder) {
  std::string_view token;
  for (std::uint64_t v = 0; v < counts.vertices; ++v) {
    const auto vertex = [&] { return "vertex " + std::to_string(v); };
    if (!lines.next()) {
      builder.fail("truncated", lines.lineNumber(),
                   "file ends after " + std::to_string(v) + " of the " +
                       std::to_string(counts.vertices) + " vertices announced on line " +
                       std::to_string(counts.line));
    }
    Tokens tokens(lines.line());
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
}

/// Face lines "n i1 ... in", optionally followed by a colour.
void readOffFaces(OffLines& lines, const OffCounts& counts, SoupBuilder& builder) {
  std::string_view token;
  std::vector<Index> corners;
  for (std::uint64_t f = 0; f < counts.faces; ++f) {
    const auto face = [&] { return "face " + std::to_string(f); };
    if (!lines.next()) {
      builder.fail("truncated", lines.lineNumber(),
                   "file ends after " + std::to_string(f) + " of the " +
                       std::to_string(counts.faces) + " faces announced on line " +
                       std::to_string(counts.line));
    }
    const int faceLine = lines.lineNumber();
    Tokens tokens(lines.line());
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
    double ignored = 0.0;
    while (tokens.next(token)) {
      if (!parseDouble(token, ignored)) {
        builder.fail("syntax", faceLine,
                     face() + ": " + shown(token) + " after the indices is not a colour value");
      }
    }
    builder.addPolygon(corners, faceLine);
  }
}

}  // namespace

void parseOff(std::string_view bytes, SoupBuilder& builder) {
  OffLines lines(bytes);
  if (!lines.next()) builder.fail("truncated", 0, "empty OFF file");
  const OffHeader header = readOffHeader(lines, builder);
  const OffCounts counts = readOffCounts(header.countsText, lines, builder);
  readOffVertices(lines, counts, header.extraVertexValues, builder);
  readOffFaces(lines, counts, builder);
  if (lines.next()) {
    builder.fail("count-mismatch", lines.lineNumber(),
                 "more data after the " + std::to_string(counts.vertices) + " vertices and " +
                     std::to_string(counts.faces) + " faces announced on line " +
                     std::to_string(counts.line));
  }
}

}  // namespace geodex::detail
