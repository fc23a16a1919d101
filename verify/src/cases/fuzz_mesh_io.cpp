// fuzz_mesh_io: a file through the readers, the validator and Mesh (fuzz_mesh_io.h).
#include "geodex/verify/cases/fuzz_mesh_io.h"

#include <cmath>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <numbers>
#include <optional>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "check_support.h"
#include "geodex/error.h"
#include "geodex/mesh.h"
#include "geodex/mesh_io.h"
#include "geodex/verify/repro.h"  // FuzzCase, which the seeds' expectations take
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

// ===  Seeds =====================================================================================

namespace {

/// A seed of the file `text` (after the format byte `hint` when it is not 0) whose reader and
/// validator verdict must be `expected`: "ok", "rejected:<kind>", "error:<kind>" or
/// "warning:<kind>".
Seed meshIo(const std::string& name, const std::string& text, const std::string& expected, std::uint8_t hint = 0) {
  std::vector<std::uint8_t> bytes;
  if (hint != 0) bytes.push_back(hint);
  bytes.insert(bytes.end(), text.begin(), text.end());
  return {name, bytes, [expected](const FuzzCase& c, const Verdict&) {
            const auto& m = std::get<MeshIoCase>(c);
            std::string got;
            try {
              MeshReadResult r = readMeshFromMemory(m.bytes, "seed", m.formatHint);
              validateMesh(r.soup, r.issues);
              got = "ok";
              for (const MeshIssue& i : r.issues)
                if (expected == (i.severity == Severity::Error ? "error:" : "warning:") + i.kind) got = expected;
            } catch (const InputError& e) {
              got = "rejected:" + e.kind();
            }
            return got == expected ? "" : "gives " + got + ", not " + expected;
          }};
}

/// A tetrahedron as a binary PLY file of either byte order.
std::string plyBinary(bool bigEndian) {
  std::string s = std::string("ply\nformat ") + (bigEndian ? "binary_big_endian" : "binary_little_endian") +
                  " 1.0\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
                  "element face 4\nproperty list uchar int vertex_indices\nend_header\n";
  auto put = [&](const void* p, std::size_t size) {
    const auto* b = static_cast<const char*>(p);
    for (std::size_t i = 0; i < size; ++i) s += b[bigEndian ? size - 1 - i : i];
  };
  const float v[4][3] = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {0, 0, 1}};
  for (const auto& p : v)
    for (float x : p) put(&x, 4);
  const int f[4][3] = {{0, 2, 1}, {0, 1, 3}, {1, 2, 3}, {2, 0, 3}};
  for (const auto& t : f) {
    s += static_cast<char>(3);
    for (int i : t) put(&i, 4);
  }
  return s;
}

}  // namespace

std::vector<Seed> meshIoSeeds() {
  const std::string tetra = "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n";
  return {
    meshIo("off-tetrahedron.off", tetra, "ok"),
    meshIo("off-counts-on-header-line-and-comments.off",
           "# a comment\nOFF 4 2 0\n0 0 0 # origin\n1 0 0\n1 1 0\n0 1 0\n\n3 0 1 2\n3 0 2 3\n", "ok"),
    meshIo("off-cube-quads-fan-triangulated.off",
           "OFF\n8 6 12\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n0 0 1\n1 0 1\n1 1 1\n0 1 1\n4 0 3 2 1\n4 4 5 6 7\n4 0 1 5 4\n"
           "4 1 2 6 5\n4 2 3 7 6\n4 3 0 4 7\n",
           "warning:polygon-triangulated"),
    meshIo("coff-with-colours.off", "COFF\n3 1 0\n0 0 0 255 0 0 255\n1 0 0 0 255 0 255\n0 1 0 0 0 255 255\n3 0 1 2 1 1 1\n", "ok"),
    meshIo("off-without-header-line", "3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "ok"),
    meshIo("obj-tetrahedron.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 2 3 4\nf 3 1 4\n", "ok"),
    meshIo("obj-negative-indices-slashes-and-groups.obj",
           "o thing\nv 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\ng part\nusemtl m\ns off\n"
           "f -4/1/1 -3/1/1 -2/1/1\nf 1//1 3//1 4//1\n",
           "ok"),
    meshIo("obj-hint-byte-forces-obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n", "ok", 2),
    meshIo("ply-ascii-tetrahedron.ply",
           "ply\nformat ascii 1.0\ncomment seed\nelement vertex 4\nproperty float x\nproperty float y\nproperty float z\n"
           "element face 4\nproperty list uchar int vertex_indices\nend_header\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n"
           "3 0 2 1\n3 0 1 3\n3 1 2 3\n3 2 0 3\n",
           "ok"),
    meshIo("ply-binary-little-endian.ply", plyBinary(false), "ok"),
    meshIo("ply-binary-big-endian.ply", plyBinary(true), "ok"),
    // What the reader refuses (InputError), and what the validator reports.
    meshIo("off-truncated.off", "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n", "rejected:truncated"),
    meshIo("off-absurd-count.off", "OFF\n99999999 1 0\n0 0 0\n", "rejected:absurd-count"),
    meshIo("off-bad-number.off", "OFF\n3 1 0\n0 0 0\n1 zero 0\n0 1 0\n3 0 1 2\n", "rejected:syntax"),
    meshIo("off-face-too-small.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "rejected:face-too-small"),
    meshIo("obj-index-zero.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "rejected:index-out-of-range"),
    meshIo("ply-unknown-format.ply", "ply\nformat binary_middle_endian 1.0\nend_header\n", "rejected:syntax"),
    meshIo("empty-file", "", "rejected:unknown-format"),
    meshIo("off-nan-coordinate.off", "OFF\n3 1 0\n0 0 0\nnan 0 0\n0 1 0\n3 0 1 2\n", "error:non-finite-coordinate"),
    meshIo("off-index-out-of-range.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 7\n", "error:index-out-of-range"),
    meshIo("off-repeated-index.off", "OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 1\n", "error:repeated-index"),
    meshIo("off-zero-length-edge.off", "OFF\n3 1 0\n0 0 0\n0 0 0\n0 1 0\n3 0 1 2\n", "error:zero-length-edge"),
    meshIo("off-duplicate-face.off", "OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 1 2 0\n", "error:duplicate-face"),
    meshIo("off-non-manifold-edge.off",
           "OFF\n5 3 0\n0 0 0\n1 0 0\n0 1 0\n0 -1 0\n0 0 1\n3 0 1 2\n3 0 1 3\n3 0 1 4\n", "error:non-manifold-edge"),
    meshIo("off-zero-area-face.off", "OFF\n4 2 0\n0 0 0\n2 0 0\n1 0 0\n1 1 0\n3 0 1 3\n3 0 2 1\n", "warning:zero-area-face"),
    meshIo("off-unreferenced-vertex.off", "OFF\n4 1 0\n0 0 0\n1 0 0\n0 1 0\n5 5 5\n3 0 1 2\n", "warning:unreferenced-vertex"),
    meshIo("off-non-manifold-vertex-bowtie.off", "OFF\n5 2 0\n0 0 0\n1 1 0\n1 -1 0\n-1 1 0\n-1 -1 0\n3 0 1 2\n3 0 3 4\n",
           "warning:non-manifold-vertex"),
    meshIo("off-inconsistent-winding.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 1 0\n0 1 0\n3 0 1 2\n3 2 0 3\n",
           "warning:inconsistent-winding"),
    meshIo("off-duplicated-position.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n1 0 0\n0 1 0\n1 1 0\n3 0 1 2\n3 3 5 4\n",
           "warning:duplicate-position"),
    meshIo("off-two-components.off", "OFF\n6 2 0\n0 0 0\n1 0 0\n0 1 0\n5 0 0\n6 0 0\n5 1 0\n3 0 1 2\n3 3 4 5\n",
           "warning:components"),
    // An edge between distinct positions whose length underflows to 0 (a denormal coordinate):
    // the validator refuses it by name ('edge-length-out-of-range'), so no Mesh is built with a
    // zero-length edge.
    {.name = "mesh-geometry-denormal-edge-length-underflows-to-zero.off",
     .bytes = [] {
       const std::string t = "OFF\n3 1 0\n0 0 0\n1e-320 0 0\n0 1 0\n3 0 1 2\n";
       return std::vector<std::uint8_t>(t.begin(), t.end());
     }(),
     .expect = {},
     .dir = "regress"},
  };
}

}  // namespace geodex::verify
