// What the six fuzz targets share: the dispatch by target of decode, check, seeds, describe and
// writeSvg, and `geodex repro` (repro.h). Each target's own code is in cases/<target>.cpp.
#include "geodex/verify/repro.h"

#include <algorithm>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

#include "cases/svg.h"
#include "geodex/error.h"

namespace geodex::verify {

// ===  Targets ===================================================================================

std::string_view name(FuzzTarget t) {
  switch (t) {
    case FuzzTarget::MeshIo: return "fuzz_mesh_io";
    case FuzzTarget::Predicates: return "fuzz_predicates";
    case FuzzTarget::EdgeUpdate: return "fuzz_edge_update";
    case FuzzTarget::Propagation: return "fuzz_propagation";
    case FuzzTarget::TwoFaces: return "fuzz_two_faces";
    case FuzzTarget::Solver: return "fuzz_solver";
  }
  return "?";
}

std::optional<FuzzTarget> parseFuzzTarget(std::string_view s) {
  for (FuzzTarget t : kFuzzTargets) {
    const std::string_view full = name(t);
    if (s == full || s == full.substr(5)) return t;
  }
  return std::nullopt;
}

// ===  Decoding and checking ======================================================================

namespace {

template <typename Case>
std::optional<FuzzCase> asFuzzCase(std::optional<Case> c) {
  if (!c) return std::nullopt;
  return FuzzCase(std::move(*c));
}

}  // namespace

std::optional<FuzzCase> decode(FuzzTarget t, std::span<const std::uint8_t> bytes) {
  switch (t) {
    case FuzzTarget::MeshIo: return asFuzzCase(decodeMeshIo(bytes));
    case FuzzTarget::Predicates: return asFuzzCase(decodePredicates(bytes));
    case FuzzTarget::EdgeUpdate: return asFuzzCase(decodeEdgeUpdate(bytes));
    case FuzzTarget::Propagation: return asFuzzCase(decodePropagation(bytes));
    case FuzzTarget::TwoFaces: return asFuzzCase(decodeTwoFaces(bytes));
    case FuzzTarget::Solver: return asFuzzCase(decodeSolver(bytes));
  }
  return std::nullopt;
}

Verdict check(const FuzzCase& c) {
  return std::visit(
      [&](const auto& x) -> Verdict {
        using T = std::decay_t<decltype(x)>;
        if constexpr (std::is_same_v<T, MeshIoCase>) return checkMeshIo(x);
        else if constexpr (std::is_same_v<T, PredicateCase>) return checkPredicates(x);
        else if constexpr (std::is_same_v<T, EdgeUpdateCase>) return checkEdgeUpdate(x);
        else if constexpr (std::is_same_v<T, PropagationCase>) return checkPropagation(x);
        else if constexpr (std::is_same_v<T, TwoFaceCase>) return checkTwoFaces(x);
        else return checkSolver(x);
      },
      c);
}

Verdict replay(FuzzTarget t, std::span<const std::uint8_t> bytes) {
  const auto c = decode(t, bytes);
  if (!c) {
    Verdict v;
    v.summary = "skipped: the target does not test these bytes";
    return v;
  }
  return check(*c);
}

std::vector<Seed> seeds(FuzzTarget t) {
  switch (t) {
    case FuzzTarget::MeshIo: return meshIoSeeds();
    case FuzzTarget::Predicates: return predicateSeeds();
    case FuzzTarget::EdgeUpdate: return edgeUpdateSeeds();
    case FuzzTarget::Propagation: return propagationSeeds();
    case FuzzTarget::TwoFaces: return twoFaceSeeds();
    case FuzzTarget::Solver: return solverSeeds();
  }
  return {};
}

// ===  Files and targets =========================================================================

std::vector<std::uint8_t> readFileBytes(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw InputError("io", path + ": cannot open");
  std::vector<std::uint8_t> bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  if (in.bad()) throw InputError("io", path + ": read error");
  return bytes;
}

namespace {

/// The first non-blank, non-comment token of a text file, or "" for binary content.
std::string firstToken(std::span<const std::uint8_t> bytes) {
  const std::size_t n = std::min<std::size_t>(bytes.size(), 512);
  for (std::size_t i = 0; i < n; ++i) {
    const unsigned char ch = bytes[i];
    if (ch < 9 || (ch > 13 && ch < 32) || ch > 126) return "";
  }
  std::string text(reinterpret_cast<const char*>(bytes.data()), n);
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) {
    std::istringstream ls(line);
    std::string token;
    if (!(ls >> token) || token[0] == '#') continue;
    return token;
  }
  return "";
}

}  // namespace

std::optional<FuzzTarget> detectTarget(const std::string& path, std::span<const std::uint8_t> bytes) {
  // A directory named after a target, nearest first.
  std::vector<std::string> parts;
  std::string part;
  for (char ch : path) {
    if (ch == '/' || ch == '\\') {
      if (!part.empty()) parts.push_back(part);
      part.clear();
    } else {
      part += ch;
    }
  }
  for (auto it = parts.rbegin(); it != parts.rend(); ++it)
    for (FuzzTarget t : kFuzzTargets)
      if (*it == name(t)) return t;
  if (isEdgeUpdateReproducer(bytes)) return FuzzTarget::EdgeUpdate;
  const std::string token = firstToken(bytes);
  if (token == "ply" || token == "v" || token == "f" || token == "o" || token == "g" ||
      (token.size() >= 3 && token.compare(token.size() - 3, 3, "OFF") == 0))
    return FuzzTarget::MeshIo;
  for (const char* ext : {".off", ".obj", ".ply", ".OFF", ".OBJ", ".PLY"})
    if (path.size() > 4 && path.compare(path.size() - 4, 4, ext) == 0) return FuzzTarget::MeshIo;
  return std::nullopt;
}

// ===  Description and picture ===================================================================

namespace {

void describeCounters(const DegeneracyCounters& c, std::ostream& out) {
  bool any = false;
  for (std::size_t k = 0; k < kNumDegeneracyKinds; ++k) {
    if (c.count[k] == 0) continue;
    out << (any ? " " : "") << name(static_cast<DegeneracyKind>(k)) << "×" << c.count[k];
    any = true;
  }
  if (!any) out << "none";
}

}  // namespace

void describe(FuzzTarget t, std::span<const std::uint8_t> bytes, std::ostream& out) {
  out << std::setprecision(17);
  const auto decoded = decode(t, bytes);
  if (!decoded) {
    out << "# " << name(t) << ": " << bytes.size() << " bytes the target skips (too long, or a "
        << "degenerate range, a mesh the validator refuses, an invalid old list)\n";
    if (t == FuzzTarget::EdgeUpdate && isEdgeUpdateReproducer(bytes)) {
      try {
        parseEdgeUpdateReproducer(std::string_view(reinterpret_cast<const char*>(bytes.data()), bytes.size()));
      } catch (const InputError& e) {
        out << "# not a valid reproducer: " << e.what() << "\n";
      }
    }
    return;
  }
  std::visit([&](const auto& c) { describe(c, out); }, *decoded);
}

void writeSvg(FuzzTarget t, std::span<const std::uint8_t> bytes, std::ostream& out) {
  const auto decoded = decode(t, bytes);
  if (!decoded) {
    detail::SvgDoc doc(600, 60);
    doc.labelPx(10, 30, std::string(name(t)) + ": the target skips these bytes", 14);
    doc.write(out);
    return;
  }
  std::visit([&](const auto& c) { writeSvg(c, out); }, *decoded);
}

// ===  geodex repro ==============================================================================

int runRepro(const std::string& path, std::optional<FuzzTarget> target,
             const std::optional<std::string>& svgPath, std::ostream& out) {
  std::vector<std::uint8_t> bytes;
  try {
    bytes = readFileBytes(path);
  } catch (const InputError& e) {
    out << "error: " << e.what() << "\n";
    return 2;
  }
  if (!target) target = detectTarget(path, bytes);
  if (!target) {
    out << "error: " << path << ": cannot tell which fuzz target this file is for; pass --target with one of";
    for (FuzzTarget t : kFuzzTargets) out << " " << name(t);
    out << "\n";
    return 2;
  }
  out << "target: " << name(*target) << "\n";
  describe(*target, bytes, out);
  const Verdict v = replay(*target, bytes);
  if (svgPath) {
    std::ofstream svg(*svgPath);
    writeSvg(*target, bytes, svg);
    out << (svg ? "svg: " : "error: cannot write ") << *svgPath << "\n";
  }
  if (!v.interesting) {
    out << "verdict: skipped (" << v.summary << ")\n";
    return 0;
  }
  out << "exercised: " << v.summary << "; degeneracies ";
  describeCounters(v.degeneracies, out);
  out << "\n";
  if (v.ok()) {
    out << "verdict: pass\n";
    return 0;
  }
  out << "verdict: FAIL: " << v.failed << "\n" << v.message << "\n";
  return 1;
}

}  // namespace geodex::verify
