// fuzz_mesh_io: a file through the readers, the validator and Mesh (fuzz_mesh_io.h).
#include "geodex/verify/cases/fuzz_mesh_io.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <numbers>
#include <optional>
#include <sstream>
#include <vector>

#include "check_support.h"
#include "geodex/error.h"
#include "geodex/mesh.h"
#include "geodex/mesh_io.h"
#include "svg.h"

namespace geodex::verify {

using namespace detail;

// ===  Decoding ==================================================================================

std::optional<MeshIoCase> decodeMeshIo(std::span<const std::uint8_t> bytes) {
  if (bytes.size() > kMaxMeshIoInputBytes) return std::nullopt;
  MeshIoCase c;
  std::size_t skip = 0;
  if (!bytes.empty() && bytes[0] >= 1 && bytes[0] <= 3) {
    static const char* const kHints[] = {"off", "obj", "ply"};
    c.formatHint = kHints[bytes[0] - 1];
    skip = 1;
  }
  c.bytes.assign(reinterpret_cast<const char*>(bytes.data()) + skip, bytes.size() - skip);
  return c;
}

// ===  Check =====================================================================================

Verdict checkMeshIo(const MeshIoCase& c) {
  Verdict v;
  v.interesting = true;
  MeshReadResult result;
  try {
    result = readMeshFromMemory(c.bytes, "fuzz-input", c.formatHint);
  } catch (const InputError& e) {
    v.summary = "rejected (" + e.kind() + "): " + e.what();
    return v;
  } catch (const std::exception& e) {
    return fail(v, "unexpected-exception", std::string("the reader threw a non-InputError: ") + e.what());
  }
  const TriangleSoup& soup = result.soup;
  if (soup.faces.empty() || (!soup.faceLines.empty() && soup.faceLines.size() != soup.faces.size()) ||
      (!soup.vertexLines.empty() && soup.vertexLines.size() != soup.positions.size()))
    return fail(v, "soup-shape", "the reader returned no faces or line lists of the wrong length");
  std::vector<MeshIssue> issues = result.issues;
  try {
    validateMesh(soup, issues);
  } catch (const std::exception& e) {
    return fail(v, "unexpected-exception", std::string("validateMesh threw: ") + e.what());
  }
  bool errors = false;
  for (const MeshIssue& i : issues) errors = errors || i.severity == Severity::Error;
  v.summary = std::to_string(soup.positions.size()) + " vertices, " + std::to_string(soup.faces.size()) +
              " faces, " + std::to_string(issues.size()) + " issue(s)" + (errors ? " incl. errors" : "");
  if (errors) {
    try {
      Mesh m(soup);  // may refuse, with InputError only
    } catch (const InputError&) {
    } catch (const std::exception& e) {
      return fail(v, "unexpected-exception", std::string("Mesh threw a non-InputError: ") + e.what());
    }
    return v;
  }
  std::optional<Mesh> mesh;
  try {
    mesh.emplace(soup);
  } catch (const std::exception& e) {
    return fail(v, "validated-mesh-refused", std::string("validateMesh found no error but Mesh threw: ") + e.what());
  }
  for (Index f = 0; f < mesh->numFaces(); ++f) {
    double sum = 0.0;
    for (int k = 0; k < 3; ++k) {
      const double a = mesh->cornerAngle(f, k);
      if (!(a >= 0.0 && a <= std::numbers::pi)) return fail(v, "mesh-geometry", "face " + std::to_string(f) + " has corner angle " + fmt(a));
      sum += a;
    }
    if (!(std::abs(sum - std::numbers::pi) <= 1e-9)) return fail(v, "mesh-geometry", "face " + std::to_string(f) + "'s corner angles sum to " + fmt(sum));
  }
  for (Index e = 0; e < mesh->numEdges(); ++e) {
    if (!(mesh->edge(e).length > 0.0)) return fail(v, "mesh-geometry", "edge " + std::to_string(e) + " has length " + fmt(mesh->edge(e).length));
  }
  // Round trip: written as OFF with 17 digits and read back, the soup is the same.
  std::ostringstream off;
  off << std::setprecision(17) << "OFF\n" << soup.positions.size() << " " << soup.faces.size() << " 0\n";
  for (const Vec3& p : soup.positions) off << p.x() << " " << p.y() << " " << p.z() << "\n";
  for (const auto& f : soup.faces) off << "3 " << f[0] << " " << f[1] << " " << f[2] << "\n";
  try {
    const MeshReadResult again = readMeshFromMemory(off.str(), "round-trip.off", "off");
    bool same = again.soup.faces == soup.faces && again.soup.positions.size() == soup.positions.size();
    for (std::size_t i = 0; same && i < soup.positions.size(); ++i)
      same = std::memcmp(again.soup.positions[i].data(), soup.positions[i].data(), 3 * sizeof(double)) == 0;
    if (!same) return fail(v, "round-trip", "the soup written as OFF reads back differently:\n" + off.str());
  } catch (const std::exception& e) {
    return fail(v, "round-trip", std::string("the soup written as OFF does not read back: ") + e.what() + "\n" + off.str());
  }
  return v;
}

// ===  Description and picture ===================================================================

void describe(const MeshIoCase& c, std::ostream& out) {
  out << std::setprecision(17);
  out << "# fuzz_mesh_io: " << c.bytes.size() << " bytes, format "
      << (c.formatHint.empty() ? "detected from the content" : c.formatHint) << "\n";
  int lines = 0;
  std::string line;
  for (std::size_t i = 0; i <= c.bytes.size() && lines < 40; ++i) {
    if (i == c.bytes.size() || c.bytes[i] == '\n') {
      out << "| " << line << "\n";
      line.clear();
      ++lines;
      continue;
    }
    const unsigned char ch = c.bytes[i];
    if (ch >= 32 && ch < 127) {
      line += static_cast<char>(ch);
    } else {
      char buf[8];
      std::snprintf(buf, sizeof buf, "\\x%02x", ch);
      line += buf;
    }
  }
  if (lines == 40) out << "| ...\n";
}

void writeSvg(const MeshIoCase& c, std::ostream& out) {
  try {
    const MeshReadResult r = readMeshFromMemory(c.bytes, "fuzz-input", c.formatHint);
    svgMesh(r.soup, {}, {}, "fuzz_mesh_io: the mesh read", out);
  } catch (const std::exception& e) {
    SvgDoc doc(900, 60);
    doc.labelPx(10, 30, std::string("fuzz_mesh_io: not a mesh: ") + e.what(), 12);
    doc.write(out);
  }
}

}  // namespace geodex::verify
