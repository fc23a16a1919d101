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

}  // namespace

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

}  // namespace geodex::detail
