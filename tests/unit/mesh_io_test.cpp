// Tests for solver/src/mesh_io/: OFF, OBJ and PLY readers (from memory), every reader error
// and every validation finding, robustness against damaged bytes, and the shared real meshes.

#include "geodex/mesh_io.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <limits>
#include <numbers>
#include <string>
#include <vector>

#include "geodex/error.h"

namespace geodex {
namespace {

// ===  Helpers  ==================================================================================

MeshReadResult read(std::string_view bytes, const std::string& format,
                    const std::string& name = "mem.obj") {
  return readMeshFromMemory(bytes, name, format);
}

/// Runs `f`, which must throw InputError, and returns that error.
template <class F>
InputError expectInputError(F&& f) {
  try {
    f();
  } catch (const InputError& error) {
    return error;
  }
  ADD_FAILURE() << "expected an InputError";
  return InputError("none", "");
}

std::vector<MeshIssue> validated(const std::string& obj, const std::string& name = "mem.obj") {
  MeshReadResult result = read(obj, "obj", name);
  std::vector<MeshIssue> issues;
  validateMesh(result.soup, issues);
  return issues;
}

const MeshIssue* findIssue(const std::vector<MeshIssue>& issues, const std::string& kind) {
  const auto it = std::find_if(issues.begin(), issues.end(),
                               [&](const MeshIssue& issue) { return issue.kind == kind; });
  return it == issues.end() ? nullptr : &*it;
}

std::string kinds(const std::vector<MeshIssue>& issues) {
  std::string out;
  for (const MeshIssue& issue : issues) out += issue.kind + " ";
  return out;
}

/// Expects exactly one issue of `kind` with `severity`, whose message contains every `parts`.
void expectIssue(const std::vector<MeshIssue>& issues, const std::string& kind, Severity severity,
                 std::initializer_list<std::string> parts) {
  const auto count = std::count_if(issues.begin(), issues.end(),
                                   [&](const MeshIssue& issue) { return issue.kind == kind; });
  ASSERT_EQ(count, 1) << "kinds: " << kinds(issues);
  const MeshIssue* issue = findIssue(issues, kind);
  EXPECT_EQ(issue->severity, severity) << issue->message;
  for (const std::string& part : parts) {
    EXPECT_NE(issue->message.find(part), std::string::npos)
        << "'" << part << "' missing from: " << issue->message;
  }
}

void expectMessageHas(const InputError& error, std::initializer_list<std::string> parts) {
  for (const std::string& part : parts) {
    EXPECT_NE(std::string(error.what()).find(part), std::string::npos)
        << "'" << part << "' missing from: " << error.what();
  }
}

/// A regular tetrahedron-like closed mesh, consistently oriented: no findings at all.
const char* const kTetrahedronObj =
    "v 0 0 0\n"
    "v 1 0 0\n"
    "v 0 1 0\n"
    "v 0 0 1\n"
    "f 1 3 2\n"
    "f 1 2 4\n"
    "f 1 4 3\n"
    "f 2 3 4\n";

/// Binary PLY bytes, written value by value in the chosen byte order.
class BinaryWriter {
 public:
  explicit BinaryWriter(bool bigEndian) : bigEndian_(bigEndian) {}
  void text(const std::string& s) { bytes_ += s; }
  template <class T>
  void put(T value) {
    char raw[sizeof(T)];
    std::memcpy(raw, &value, sizeof(T));
    if (bigEndian_ != (std::endian::native == std::endian::big)) std::reverse(raw, raw + sizeof(T));
    bytes_.append(raw, sizeof(T));
  }
  const std::string& bytes() const { return bytes_; }

 private:
  bool bigEndian_;
  std::string bytes_;
};

/// Four vertices with mixed coordinate types and extra properties, a triangle and a quad with an
/// unrelated second list, and an unrelated element at the end.
std::string binaryPly(bool bigEndian) {
  BinaryWriter w(bigEndian);
  w.text(std::string("ply\nformat ") +
         (bigEndian ? "binary_big_endian" : "binary_little_endian") +
         " 1.0\n"
         "comment built by mesh_io_test\n"
         "element vertex 4\n"
         "property double x\n"
         "property float y\n"
         "property short z\n"
         "property list uchar float normal\n"
         "property uchar alpha\n"
         "element face 2\n"
         "property list ushort uint other\n"
         "property list uint int vertex_indices\n"
         "element extra 3\n"
         "property int a\n"
         "property double b\n"
         "end_header\n");
  const double xyz[4][3] = {{0.5, 0, 0}, {1, 0, 0}, {1, 1, -2}, {0, 1, 7}};
  for (const auto& p : xyz) {
    w.put<double>(p[0]);
    w.put<float>(static_cast<float>(p[1]));
    w.put<std::int16_t>(static_cast<std::int16_t>(p[2]));
    w.put<std::uint8_t>(2);
    w.put<float>(0.25f);
    w.put<float>(0.75f);
    w.put<std::uint8_t>(255);
  }
  w.put<std::uint16_t>(1);
  w.put<std::uint32_t>(99);
  w.put<std::uint32_t>(3);
  for (const std::int32_t i : {0, 1, 2}) w.put<std::int32_t>(i);
  w.put<std::uint16_t>(0);
  w.put<std::uint32_t>(4);
  for (const std::int32_t i : {0, 1, 2, 3}) w.put<std::int32_t>(i);
  for (int i = 0; i < 3; ++i) {
    w.put<std::int32_t>(i);
    w.put<double>(1.5);
  }
  return w.bytes();
}

// ===  OBJ  ======================================================================================

TEST(MeshIoObj, ParsesEveryCornerFormAndIgnoresOtherStatements) {
  const std::string obj =
      "# a comment\n"        // 1
      "v 0 0 0\n"            // 2
      "v 1 0 0\n"            // 3
      "v 0 1 0 1.0\n"        // 4 (with w)
      "vt 0 0\n"             // 5
      "vn 0 0 1\n"           // 6
      "g group\n"            // 7
      "o object\n"           // 8
      "s off\n"              // 9
      "usemtl m\n"           // 10
      "mtllib m.mtl\n"       // 11
      "l 1 2\n"              // 12
      "f 1 2 3\n"            // 13
      "f 1/1 2/1 3/1\n"      // 14
      "f 1/1/1 2/1/1 3/1/1\n"  // 15
      "f 1//1 2//1 3//1\r\n"   // 16 (CRLF)
      "f -3 -2 -1\n"         // 17
      "v\t+2.5e0  -1E-1 3\n"   // 18
      "f 4 -2 1";            // 19, no final newline
  const MeshReadResult result = read(obj, "obj");
  EXPECT_TRUE(result.ok());
  EXPECT_TRUE(result.issues.empty());
  const TriangleSoup& soup = result.soup;
  EXPECT_EQ(soup.fileName, "mem.obj");
  ASSERT_EQ(soup.positions.size(), 4u);
  EXPECT_EQ(soup.positions[3], Vec3(2.5, -0.1, 3));
  EXPECT_EQ(soup.vertexLines, (std::vector<int>{2, 3, 4, 18}));
  ASSERT_EQ(soup.faces.size(), 6u);
  for (int f = 0; f < 5; ++f) EXPECT_EQ(soup.faces[f], (std::array<Index, 3>{0, 1, 2}));
  EXPECT_EQ(soup.faces[5], (std::array<Index, 3>{3, 2, 0}));
  EXPECT_EQ(soup.faceLines, (std::vector<int>{13, 14, 15, 16, 17, 19}));
}

TEST(MeshIoObj, FanTriangulatesPolygonsWithOneWarning) {
  const std::string obj =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv -1 0.5 0\n"  // lines 1-5
      "f 1 2 3\n"                                          // 6
      "f 1 2 3 4\n"                                        // 7
      "f 1 2 3 4 5\n";                                     // 8
  const MeshReadResult result = read(obj, "obj");
  const TriangleSoup& soup = result.soup;
  ASSERT_EQ(soup.faces.size(), 6u);
  EXPECT_EQ(soup.faces[1], (std::array<Index, 3>{0, 1, 2}));
  EXPECT_EQ(soup.faces[2], (std::array<Index, 3>{0, 2, 3}));
  EXPECT_EQ(soup.faces[5], (std::array<Index, 3>{0, 3, 4}));
  EXPECT_EQ(soup.faceLines, (std::vector<int>{6, 7, 7, 8, 8, 8}));
  ASSERT_EQ(result.issues.size(), 1u);
  EXPECT_TRUE(result.ok());
  expectIssue(result.issues, "polygon-triangulated", Severity::Warning,
              {"mem.obj:7:", "face 1 has 4 corners", "triangles 1..2", "2 polygon(s)",
               "5 triangles"});
}

TEST(MeshIoObj, FaceWithTwoCornersNamesItsLine) {
  const InputError error =
      expectInputError([] { read("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2\n", "obj"); });
  EXPECT_EQ(error.kind(), "face-too-small");
  expectMessageHas(error, {"mem.obj:5:", "face 1", "2 corner"});
}

TEST(MeshIoObj, SyntaxErrorsNameLineAndElement) {
  struct Case {
    const char* obj;
    const char* kind;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {"v 0 0 0\nv 1 zz 0\n", "syntax", {"mem.obj:2:", "vertex 1", "'zz'"}},
      {"v 0 0\n", "syntax", {"mem.obj:1:", "vertex 0", "expected 3 coordinates"}},
      {"v 0 0 0 q\n", "syntax", {"mem.obj:1:", "'q'"}},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2/x 3\n", "syntax", {"mem.obj:4:", "face 0", "'2/x'"}},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 three\n", "syntax", {"mem.obj:4:", "'three'"}},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 0 1 2\n", "index-out-of-range", {"mem.obj:4:", "index 0"}},
      {"v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf -4 1 2\n",
       "index-out-of-range",
       {"mem.obj:5:", "face 1", "-4"}},
      {"v 0 0 0\nf 1 2 99999999999\n", "index-out-of-range", {"mem.obj:2:", "too large"}},
      {"v 0 0 0\n@@ 1 2\n", "syntax", {"mem.obj:2:", "'@@'"}},
      {"v 0 0 0\n", "empty-mesh", {"no faces", "1 vertices"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.obj);
    const InputError error = expectInputError([&] { read(c.obj, "obj"); });
    EXPECT_EQ(error.kind(), c.kind) << error.what();
    for (const std::string& part : c.parts) {
      EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
    }
  }
}

TEST(MeshIoObj, UnknownStatementsAreOneWarning) {
  const MeshReadResult result =
      read("v 0 0 0\nv 1 0 0\nfoo 1\nv 0 1 0\nbar\nf 1 2 3\n", "obj");
  EXPECT_EQ(result.soup.faces.size(), 1u);
  expectIssue(result.issues, "unknown-statement", Severity::Warning,
              {"mem.obj:3:", "2 line(s)", "'foo'"});
}

TEST(MeshIoObj, OverflowingCoordinatesBecomeInfiniteAndAreRefused) {
  const MeshReadResult result = read("v 1e999 0 0\nv 1e-999 0 0\nv 0 1 0\nf 1 2 3\n", "obj");
  EXPECT_TRUE(std::isinf(result.soup.positions[0].x()));
  EXPECT_EQ(result.soup.positions[1].x(), 0.0);
  std::vector<MeshIssue> issues;
  validateMesh(result.soup, issues);
  expectIssue(issues, "non-finite-coordinate", Severity::Error, {"mem.obj:1:", "vertex 0", "inf"});
}

// ===  OFF  ======================================================================================

TEST(MeshIoOff, ParsesCommentsAndFaceColours) {
  const std::string off =
      "OFF\n"                        // 1
      "# a comment\n"                // 2
      "4 4 6   # counts\n"           // 3
      "0 0 0\n"                      // 4
      "1 0 0\n"                      // 5
      "\n"                           // 6
      "0 1 0\n"                      // 7
      "0 0 1\n"                      // 8
      "3 0 2 1 255 0 0\n"            // 9 (colour)
      "3 0 1 3 0.5 0.5 0.5 1.0\n"    // 10
      "3 0 3 2\n"                    // 11
      "3 1 2 3 # last\n";            // 12
  const MeshReadResult result = read(off, "off", "mem.off");
  EXPECT_TRUE(result.issues.empty());
  EXPECT_EQ(result.soup.vertexLines, (std::vector<int>{4, 5, 7, 8}));
  EXPECT_EQ(result.soup.faceLines, (std::vector<int>{9, 10, 11, 12}));
  EXPECT_EQ(result.soup.faces[0], (std::array<Index, 3>{0, 2, 1}));
  EXPECT_EQ(result.soup.positions[3], Vec3(0, 0, 1));
  std::vector<MeshIssue> issues;
  validateMesh(result.soup, issues);
  EXPECT_TRUE(issues.empty()) << kinds(issues);
}

TEST(MeshIoOff, AcceptsHeaderVariants) {
  // Counts on the header line, no final newline.
  EXPECT_EQ(read("OFF 3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2", "off").soup.faces.size(), 1u);
  // No header line at all (the extension or the hint says OFF).
  EXPECT_EQ(read("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "off").soup.faces.size(), 1u);
  // COFF: colours after each vertex; a quad.
  const MeshReadResult coff =
      read("COFF\n4 1 0\n0 0 0 1 0 0 1\n1 0 0 1 0 0 1\n1 1 0 1 0 0 1\n0 1 0 1 0 0 1\n4 0 1 2 3\n",
           "off", "mem.off");
  EXPECT_EQ(coff.soup.faces.size(), 2u);
  expectIssue(coff.issues, "polygon-triangulated", Severity::Warning, {"mem.off:7:", "face 0"});
  // Variants that are not 3-D text OFF are refused clearly.
  EXPECT_EQ(expectInputError([] { read("4OFF\n1 1 0\n", "off"); }).kind(), "unsupported-format");
  EXPECT_EQ(expectInputError([] { read("OFF BINARY\n", "off"); }).kind(), "unsupported-format");
}

TEST(MeshIoOff, ErrorsNameLineAndElement) {
  struct Case {
    const char* off;
    const char* kind;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {"OFF\n3 1 0\n0.000000 0.000000 0.000000\n1.000000 0.000000 0.000000\n",
       "truncated",
       {"mem.off:4:", "2 of the 3 vertices", "line 2"}},
      {"OFF\n3 2 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 # with a long comment to fill\n",
       "truncated",
       {"1 of the 2 faces"}},
      // A file cut inside the vertex list: the precise error, not "absurd count".
      {"OFF\n4 2 0\n0 0 0\n1 0", "syntax", {"mem.off:4:", "vertex 1", "found 2"}},
      {"OFF\n4 2 0\n0 0 0\n", "truncated", {"mem.off:3:", "1 of the 4 vertices"}},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n3 0 2 1\n",
       "count-mismatch",
       {"mem.off:7:", "more data"}},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n2 0 1\n", "face-too-small", {"mem.off:6:", "face 0"}},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1\n", "syntax", {"mem.off:6:", "face 0", "only 2"}},
      {"OFF\n3 1 0\n0 0 0\n1 x 0\n0 1 0\n3 0 1 2\n", "syntax", {"mem.off:4:", "vertex 1", "'x'"}},
      {"OFF\n3 1 0\n0 0 0\n1 0 0 5\n0 1 0\n3 0 1 2\n",
       "syntax",
       {"mem.off:4:", "vertex 1", "found 4"}},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 -2\n", "index-out-of-range", {"mem.off:6:"}},
      {"OFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2 red\n", "syntax", {"mem.off:6:", "'red'"}},
      {"OFF\nthree 1 0\n", "syntax", {"mem.off:2:", "'three'"}},
      {"OFF\n3\n", "syntax", {"mem.off:2:", "counts"}},
      {"OFF\n1000000000000 1 0\n0 0 0\n", "absurd-count", {"mem.off:2:", "1000000000000"}},
      {"OFF\n3 1000000000000000000 0\n0 0 0\n1 0 0\n0 1 0\n", "absurd-count", {"mem.off:2:"}},
      {"# only a comment\n", "truncated", {"empty"}},
      {"OFF\n0 0 0\n", "empty-mesh", {"no faces"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.off);
    const InputError error = expectInputError([&] { read(c.off, "off", "mem.off"); });
    EXPECT_EQ(error.kind(), c.kind) << error.what();
    for (const std::string& part : c.parts) {
      EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
    }
  }
}

// ===  PLY  ======================================================================================

const char* const kAsciiPly =
    "ply\n"                                        // 1
    "format ascii 1.0\n"                           // 2
    "comment made by hand\n"                       // 3
    "element vertex 4\n"                           // 4
    "property float x\n"                           // 5
    "property float y\n"                           // 6
    "property float z\n"                           // 7
    "property uchar red\n"                         // 8
    "property list uchar float texcoord\n"         // 9
    "element face 2\n"                             // 10
    "property uchar flags\n"                       // 11
    "property list uchar int vertex_index\n"       // 12
    "element edge 1\n"                             // 13
    "property int vertex1\n"                       // 14
    "property int vertex2\n"                       // 15
    "end_header\n"                                 // 16
    "0 0 0 255 2 0.5 0.5\n"                        // 17
    "1 0 0 255 0\n"                                // 18
    "0 1 0 255 0\n"                                // 19
    "1 1 0.5 255 0\n"                              // 20
    "7 4 0 1 3 2\n"                                // 21
    "0 3 0 1 2\n"                                  // 22
    "0 1\n";                                       // 23

TEST(MeshIoPly, ParsesAsciiWithOtherPropertiesAndElements) {
  const MeshReadResult result = read(kAsciiPly, "ply", "mem.ply");
  const TriangleSoup& soup = result.soup;
  ASSERT_EQ(soup.positions.size(), 4u);
  EXPECT_EQ(soup.positions[3], Vec3(1, 1, 0.5));
  EXPECT_EQ(soup.vertexLines, (std::vector<int>{17, 18, 19, 20}));
  ASSERT_EQ(soup.faces.size(), 3u);
  EXPECT_EQ(soup.faces[0], (std::array<Index, 3>{0, 1, 3}));
  EXPECT_EQ(soup.faces[1], (std::array<Index, 3>{0, 3, 2}));
  EXPECT_EQ(soup.faces[2], (std::array<Index, 3>{0, 1, 2}));
  EXPECT_EQ(soup.faceLines, (std::vector<int>{21, 21, 22}));
  expectIssue(result.issues, "polygon-triangulated", Severity::Warning, {"mem.ply:21:", "face 0"});
}

TEST(MeshIoPly, AsciiErrorsNameLineAndElement) {
  const std::string ply(kAsciiPly);
  const auto replaced = [&](const std::string& from, const std::string& to) {
    std::string s = ply;
    s.replace(s.find(from), from.size(), to);
    return s;
  };
  struct Case {
    std::string ply;
    const char* kind;
    std::vector<std::string> parts;
  };
  const std::vector<Case> cases = {
      {replaced("1 0 0 255 0\n", "1 zero 0 255 0\n"), "syntax", {"mem.ply:18:", "vertex 1", "'zero'"}},
      {replaced("1 0 0 255 0\n", "1 0\n"), "syntax", {"mem.ply:18:", "vertex 1", "'z'"}},
      {replaced("0 3 0 1 2\n", "0 3 0 1\n"), "syntax", {"mem.ply:22:", "face 1"}},
      {replaced("0 3 0 1 2\n", "0 3 0 1 2 9\n"), "count-mismatch", {"mem.ply:22:", "face 1"}},
      {replaced("0 3 0 1 2\n", "0 2 0 1\n"), "face-too-small", {"mem.ply:22:", "face 1"}},
      {replaced("0 3 0 1 2\n", "0 3 0 -1 2\n"), "index-out-of-range", {"mem.ply:22:", "face 1"}},
      {replaced("0 1\n", "0 1\n5 5\n"), "count-mismatch", {"mem.ply:24:"}},
      {ply.substr(0, ply.find("0 3 0 1 2")), "truncated", {"1 of the 2 'face'", "line 10"}},
      {replaced("element vertex 4", "element vertex 1000000000000"),
       "absurd-count",
       {"mem.ply:4:", "1000000000000"}},
      {replaced("format ascii", "format utf8"), "syntax", {"mem.ply:2:", "'utf8'"}},
      {replaced("property float z", "property float w"), "syntax", {"mem.ply:4:", "x, y or z"}},
      {replaced("vertex_index", "corners"), "syntax", {"mem.ply:10:", "vertex_indices"}},
      {replaced("property float y", "property quaternion y"), "syntax", {"mem.ply:6:"}},
      {replaced("end_header", "end_head"), "syntax", {"mem.ply:16:", "'end_head'"}},
      {ply.substr(0, ply.find("end_header")), "truncated", {"end_header"}},
      {"plyx\n", "syntax", {"mem.ply:1:"}},
  };
  for (const Case& c : cases) {
    SCOPED_TRACE(c.ply);
    const InputError error = expectInputError([&] { read(c.ply, "ply", "mem.ply"); });
    EXPECT_EQ(error.kind(), c.kind) << error.what();
    for (const std::string& part : c.parts) {
      EXPECT_NE(std::string(error.what()).find(part), std::string::npos) << error.what();
    }
  }
}

TEST(MeshIoPly, ParsesBinaryInBothByteOrders) {
  for (const bool bigEndian : {false, true}) {
    SCOPED_TRACE(bigEndian ? "big endian" : "little endian");
    const MeshReadResult result = read(binaryPly(bigEndian), "ply", "mem.ply");
    const TriangleSoup& soup = result.soup;
    ASSERT_EQ(soup.positions.size(), 4u);
    EXPECT_EQ(soup.positions[0], Vec3(0.5, 0, 0));
    EXPECT_EQ(soup.positions[2], Vec3(1, 1, -2));
    EXPECT_EQ(soup.positions[3], Vec3(0, 1, 7));
    ASSERT_EQ(soup.faces.size(), 3u);
    EXPECT_EQ(soup.faces[0], (std::array<Index, 3>{0, 1, 2}));
    EXPECT_EQ(soup.faces[1], (std::array<Index, 3>{0, 1, 2}));
    EXPECT_EQ(soup.faces[2], (std::array<Index, 3>{0, 2, 3}));
    EXPECT_EQ(soup.vertexLines, std::vector<int>(4, 0));  // binary: no lines
    EXPECT_EQ(soup.faceLines, std::vector<int>(3, 0));
    expectIssue(result.issues, "polygon-triangulated", Severity::Warning, {"mem.ply: face 1"});
  }
}

TEST(MeshIoPly, TruncatedBinaryThrowsAtEveryLength) {
  for (const bool bigEndian : {false, true}) {
    const std::string bytes = binaryPly(bigEndian);
    const std::size_t dataStart = bytes.find("end_header\n") + 11;
    // The last element ("extra", 3 × 12 bytes) is not needed for the soup, but is announced.
    for (std::size_t length = 0; length < bytes.size(); ++length) {
      SCOPED_TRACE(length);
      const InputError error =
          expectInputError([&] { read(std::string_view(bytes).substr(0, length), "ply"); });
      if (length > dataStart) {
        EXPECT_TRUE(error.kind() == "truncated" || error.kind() == "absurd-count") << error.what();
      }
    }
  }
}

TEST(MeshIoPly, BinaryHugeCountsAreErrorsNotAllocations) {
  std::string header =
      "ply\nformat binary_little_endian 1.0\nelement vertex 1000000000000\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uint int vertex_indices\n"
      "end_header\n";
  const InputError counts = expectInputError([&] { read(header + "0123456789", "ply"); });
  EXPECT_EQ(counts.kind(), "absurd-count");
  expectMessageHas(counts, {"1000000000000"});

  // A list claiming 2^32 - 2 items in a few bytes.
  BinaryWriter w(false);
  w.text(
      "ply\nformat binary_little_endian 1.0\nelement vertex 3\nproperty float x\n"
      "property float y\nproperty float z\nelement face 1\nproperty list uint int vertex_indices\n"
      "end_header\n");
  for (int i = 0; i < 9; ++i) w.put<float>(static_cast<float>(i));
  w.put<std::uint32_t>(0xfffffffeu);
  w.put<std::int32_t>(0);
  const InputError list = expectInputError([&] { read(w.bytes(), "ply", "mem.ply"); });
  EXPECT_EQ(list.kind(), "truncated");
  expectMessageHas(list, {"mem.ply: face 0"});
}

// ===  Format detection and damaged input  =======================================================

TEST(MeshIo, DetectsFormatFromContent) {
  EXPECT_EQ(read(kTetrahedronObj, "").soup.faces.size(), 4u);
  EXPECT_EQ(read("# c\nOFF\n3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "").soup.faces.size(), 1u);
  EXPECT_EQ(read("3 1 0\n0 0 0\n1 0 0\n0 1 0\n3 0 1 2\n", "").soup.faces.size(), 1u);
  EXPECT_EQ(read(kAsciiPly, "").soup.faces.size(), 3u);
  EXPECT_EQ(read(binaryPly(true), "").soup.faces.size(), 3u);
  EXPECT_EQ(read(kTetrahedronObj, "OBJ").soup.faces.size(), 4u);
  EXPECT_EQ(expectInputError([] { read("hello world\n", ""); }).kind(), "unknown-format");
  EXPECT_EQ(expectInputError([] { read("", ""); }).kind(), "unknown-format");
  EXPECT_EQ(expectInputError([] { read(kTetrahedronObj, "stl"); }).kind(), "unknown-format");
}

TEST(MeshIo, DamagedInputThrowsInputErrorOrReadsNeverAnythingElse) {
  const std::vector<std::string> seeds = {
      kTetrahedronObj, kAsciiPly, binaryPly(false), binaryPly(true),
      "OFF\n4 4 6\n0 0 0\n1 0 0\n0 1 0\n0 0 1\n3 0 2 1\n3 0 1 3\n3 0 3 2\n3 1 2 3\n"};
  std::uint64_t state = 0x9e3779b97f4a7c15ull;  // fixed seed: the same inputs every run
  const auto random = [&](std::uint64_t bound) {
    state = state * 6364136223846793005ull + 1442695040888963407ull;
    return bound == 0 ? 0 : (state >> 33) % bound;
  };
  const char* const formats[] = {"", "obj", "off", "ply"};
  int parsed = 0;
  for (int round = 0; round < 4000; ++round) {
    std::string bytes = seeds[random(seeds.size())];
    const int mutations = 1 + static_cast<int>(random(4));
    for (int m = 0; m < mutations && !bytes.empty(); ++m) {
      const std::size_t at = random(bytes.size());
      switch (random(5)) {
        case 0: bytes[at] = static_cast<char>(random(256)); break;
        case 1: bytes.resize(at); break;
        case 2: bytes.insert(at, 1, "0123456789 -.e\n#/fvOFply"[random(24)]); break;
        case 3: bytes.erase(at, 1 + random(8)); break;
        case 4: bytes.insert(at, bytes.substr(at, random(16))); break;
      }
    }
    const std::string format = formats[random(4)];
    try {
      MeshReadResult result = readMeshFromMemory(bytes, "fuzz", format);
      std::vector<MeshIssue> issues;
      validateMesh(result.soup, issues);
      ++parsed;
    } catch (const InputError& error) {
      EXPECT_NE(std::string(error.what()), "");
    } catch (const std::exception& error) {
      ADD_FAILURE() << "not an InputError: " << error.what() << " (round " << round << ")";
    }
  }
  EXPECT_GT(parsed, 0);  // some damage is harmless: the valid paths ran too
}

// ===  Validation  ===============================================================================

TEST(MeshIoValidate, CleanMeshHasNoIssues) {
  const std::vector<MeshIssue> issues = validated(kTetrahedronObj);
  EXPECT_TRUE(issues.empty()) << kinds(issues);
}

TEST(MeshIoValidate, NonFiniteCoordinate) {
  const auto issues = validated("v 0 0 0\nv nan 0 0\nv 0 1 0\nf 1 2 3\n");
  expectIssue(issues, "non-finite-coordinate", Severity::Error, {"mem.obj:2:", "vertex 1", "nan"});
}

TEST(MeshIoValidate, IndexOutOfRange) {
  const auto issues = validated("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 2 9\n");
  expectIssue(issues, "index-out-of-range", Severity::Error,
              {"mem.obj:5:", "face 1", "vertex 8", "only 3 vertices"});
}

TEST(MeshIoValidate, RepeatedIndex) {
  const auto issues = validated("v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\nf 1 3 3\n");
  expectIssue(issues, "repeated-index", Severity::Error, {"mem.obj:5:", "face 1", "vertex 2 twice"});
}

TEST(MeshIoValidate, ZeroLengthEdge) {
  const auto issues = validated("v 0 0 0\nv 1 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\nf 2 3 4\n");
  expectIssue(issues, "zero-length-edge", Severity::Error,
              {"mem.obj:6:", "face 1", "vertices 1 and 2"});
  EXPECT_EQ(findIssue(issues, "zero-area-face"), nullptr);  // reported once, as the error
}

TEST(MeshIoValidate, NegativeZeroIsTheSamePosition) {
  const auto issues = validated("v 0 0 0\nv -0 0 0\nv 0 1 0\nf 1 2 3\n");
  expectIssue(issues, "zero-length-edge", Severity::Error, {"face 0", "vertices 0 and 1"});
}

// What geodex cannot compute with is refused by name, by Mesh and by the validator alike: an edge
// whose length (in the file's units) is not a normal double, and one so much shorter than the
// mesh's extent that products of its lengths with the tolerances would underflow (tol::
// kMinEdgeLengthRel). Anything else is accepted, at any scale.
void expectMeshRefused(const TriangleSoup& soup, const std::string& kind, const std::string& edge) {
  try {
    const Mesh mesh(soup);
    ADD_FAILURE() << "accepted; expected " << kind;
  } catch (const InputError& e) {
    EXPECT_EQ(e.kind(), kind) << e.what();
    EXPECT_NE(std::string(e.what()).find(edge), std::string::npos) << e.what();
  }
}

TEST(MeshIoValidate, AnEdgeBelowTheSpreadGeodexComputesWithIsRefusedByName) {
  // Distinct positions 1e-320 apart (found by fuzz_mesh_io: the length underflowed to 0 and the
  // face's angles summed to 0): 1e-320 of the mesh's extent, far below kMinEdgeLengthRel.
  const auto tiny = validated("v 0 0 0\nv 1e-320 0 0\nv 0 1 0\nf 1 2 3\n");
  expectIssue(tiny, "edge-length-spread", Severity::Error,
              {"mem.obj:4:", "face 0", "edge 0-1", "weld the tiny edge"});
  // 1e-120 and 1e-101 of the extent: still refused; 1e-99 and 1e-90: computed.
  for (const char* tooShort : {"1e-120", "1e-101"})
    expectIssue(validated(std::string("v 0 0 0\nv ") + tooShort + " 0 0\nv 0 1 0\nf 1 2 3\n"),
                "edge-length-spread", Severity::Error, {"face 0", "edge 0-1"});
  for (const char* shortEnough : {"1e-99", "1e-90"})
    for (const MeshIssue& i :
         validated(std::string("v 0 0 0\nv ") + shortEnough + " 0 0\nv 0 1 0\nf 1 2 3\n"))
      EXPECT_NE(i.severity, Severity::Error) << shortEnough << ": " << i.message;
  TriangleSoup soup;
  soup.positions = {Vec3(0, 0, 0), Vec3(1e-320, 0, 0), Vec3(0, 1, 0)};
  soup.faces = {{0, 1, 2}};
  expectMeshRefused(soup, "edge-length-spread", "edge 0-1");
}

TEST(MeshIoValidate, AMeshWhoseEdgesAreNotNormalDoublesIsRefusedByName) {
  // The whole mesh at 1e-310: its lengths are subnormal, good to a few bits only.
  expectIssue(validated("v 0 0 0\nv 1e-310 0 0\nv 0 1e-310 0\nf 1 2 3\n"),
              "edge-length-out-of-range", Severity::Error,
              {"mem.obj:4:", "face 0", "edge 0-1", "smallest normal double", "scale the mesh up"});
  // Coordinates of 1.5e308 are finite, but the edge between two of them is 2.1e308 long.
  expectIssue(validated("v 0 0 0\nv 1.5e308 0 0\nv 0 1.5e308 0\nf 1 2 3\n"),
              "edge-length-out-of-range", Severity::Error,
              {"face 0", "edge 1-2", "largest double", "scale the mesh down"});
  TriangleSoup soup;
  soup.positions = {Vec3(0, 0, 0), Vec3(1e-310, 0, 0), Vec3(0, 1e-310, 0)};
  soup.faces = {{0, 1, 2}};
  expectMeshRefused(soup, "edge-length-out-of-range", "edge 0-1");
  soup.positions = {Vec3(0, 0, 0), Vec3(1.5e308, 0, 0), Vec3(0, 1.5e308, 0)};
  expectMeshRefused(soup, "edge-length-out-of-range", "edge 1-2");
}

TEST(MeshIoValidate, MeshesAtTheEndsOfTheRangeOfDoublesAreAccepted) {
  for (const double s : {1e-300, 0x1p-1000, 1e300, 0x1p1000}) {
    TriangleSoup soup;
    soup.positions = {Vec3(0, 0, 0), Vec3(s, 0, 0), Vec3(0, s, 0), Vec3(0, 0, s)};
    soup.faces = {{0, 1, 2}, {0, 2, 3}, {0, 3, 1}, {1, 3, 2}};
    std::vector<MeshIssue> issues;
    validateMesh(soup, issues);
    for (const MeshIssue& i : issues) EXPECT_NE(i.severity, Severity::Error) << s << ": " << i.message;
    const Mesh mesh(soup);
    EXPECT_EQ(mesh.unit(), std::ldexp(1.0, std::ilogb(s))) << s;
    for (Index e = 0; e < mesh.numEdges(); ++e) {  // the axes (s) and the diagonals (√2 s)
      const double ratio = mesh.edge(e).length * mesh.unit() / s;
      EXPECT_TRUE(ratio == 1.0 || std::abs(ratio - std::sqrt(2.0)) < 1e-15) << s << " edge " << e;
    }
  }
}

TEST(MeshIoValidate, CornerAnglesOfAFaceWithLongEdgesSumToPi) {
  // Regression (corpus/fuzz_mesh_io/regress/*corner-angle-cross-product-overflows-on-long-edges):
  // |u × v| of the unnormalized sides squared a product of two lengths, overflowed to inf, and
  // the sharp corner came out as π/2 (the face's angles summed to 3π/2).
  TriangleSoup soup;
  soup.positions = {Vec3(0, 0, 1.1e132), Vec3(0, 1, 0), Vec3(0, 1.1e64, 0)};
  soup.faces = {{0, 1, 2}};
  const Mesh mesh(soup);
  EXPECT_NEAR(mesh.cornerAngle(0, 0) + mesh.cornerAngle(0, 1) + mesh.cornerAngle(0, 2),
              std::numbers::pi, 1e-12);
  EXPECT_LT(mesh.cornerAngle(0, 0), 1e-60);  // the needle's tip: about 1.1e64 / 1.1e132
}

TEST(MeshIoValidate, DuplicateFace) {
  const auto issues = validated(std::string(kTetrahedronObj) + "f 3 2 1\n");
  expectIssue(issues, "duplicate-face", Severity::Error, {"mem.obj:9:", "face 4", "face 0"});
}

TEST(MeshIoValidate, NonManifoldEdge) {
  const auto issues = validated(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\n"  // 1-5
      "f 1 2 3\nf 2 1 4\nf 1 2 5\n");                    // 6-8
  expectIssue(issues, "non-manifold-edge", Severity::Error,
              {"mem.obj:6:", "edge 0-1", "3 faces", "face 0", "face 1 (line 7)", "face 2 (line 8)"});
}

TEST(MeshIoValidate, ZeroAreaFace) {
  const auto issues = validated("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n");
  expectIssue(issues, "zero-area-face", Severity::Warning, {"mem.obj:4:", "face 0", "collinear"});
  EXPECT_TRUE(read("v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n", "obj").ok());
}

TEST(MeshIoValidate, NonManifoldVertex) {
  // Two triangles touching only at vertex 0 (a bowtie).
  const auto issues = validated(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv -1 0 0\nv 0 -1 0\n"
      "f 1 2 3\nf 1 4 5\n");
  expectIssue(issues, "non-manifold-vertex", Severity::Warning,
              {"mem.obj:1:", "vertex 0", "face 0", "face 1"});
  EXPECT_EQ(findIssue(issues, "components"), nullptr);  // joined through the vertex
}

TEST(MeshIoValidate, UnreferencedVertex) {
  const auto issues = validated("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 5 5\nf 1 2 3\n");
  expectIssue(issues, "unreferenced-vertex", Severity::Warning, {"mem.obj:4:", "vertex 3", "+inf"});
}

TEST(MeshIoValidate, DuplicatePosition) {
  const auto issues = validated(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\n"
      "v 1 0 0\nv 2 0 0\nv 1 1 0\n"
      "f 1 2 3\nf 4 5 6\n");
  expectIssue(issues, "duplicate-position", Severity::Warning,
              {"mem.obj:4:", "vertex 3", "vertex 1 (line 2)"});
  expectIssue(issues, "components", Severity::Warning, {"2 connected components"});
}

TEST(MeshIoValidate, InconsistentWinding) {
  const auto issues = validated("v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nf 1 2 3\nf 1 2 4\n");
  expectIssue(issues, "inconsistent-winding", Severity::Warning,
              {"mem.obj:5:", "face 0", "face 1 (line 6)", "edge 0-1"});
}

TEST(MeshIoValidate, Components) {
  const auto issues = validated(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 5 0 0\nv 6 0 0\nv 5 1 0\n"
      "f 1 2 3\nf 4 5 6\n");
  expectIssue(issues, "components", Severity::Warning,
              {"mem.obj:8:", "face 1", "face 0", "2 connected components", "+inf"});
}

TEST(MeshIoValidate, ManyOccurrencesAreOneIssueWithCount) {
  std::string obj = "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n";
  for (int i = 0; i < 100; ++i) obj += "v 9 9 " + std::to_string(i) + "\n";
  const auto issues = validated(obj);
  expectIssue(issues, "unreferenced-vertex", Severity::Warning,
              {"mem.obj:5:", "vertex 3", "100 vertices in all", "vertex 4 (line 6)", "..."});
  EXPECT_LT(findIssue(issues, "unreferenced-vertex")->message.size(), 400u);
}

TEST(MeshIoValidate, SoupWithoutLinesOrNameStillNamesElements) {
  TriangleSoup soup;
  soup.positions = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0)};
  soup.faces = {{0, 1, 2}, {0, 1, kNoIndex}, {2, 2, 1}};
  soup.faceLines = {1};  // wrong length: ignored
  std::vector<MeshIssue> issues;
  validateMesh(soup, issues);
  expectIssue(issues, "index-out-of-range", Severity::Error, {"face 1 refers"});
  expectIssue(issues, "repeated-index", Severity::Error, {"face 2 uses vertex 2"});
  EXPECT_EQ(findIssue(issues, "index-out-of-range")->message.rfind("face 1", 0), 0u);
  // Errors come before warnings, in the documented order.
  ASSERT_GE(issues.size(), 2u);
  EXPECT_EQ(issues[0].kind, "index-out-of-range");
  EXPECT_EQ(issues[1].kind, "repeated-index");
}

TEST(MeshIoValidate, ReadResultOk) {
  MeshReadResult result;
  EXPECT_TRUE(result.ok());
  result.issues.push_back({Severity::Warning, "w", "m"});
  EXPECT_TRUE(result.ok());
  result.issues.push_back({Severity::Error, "e", "m"});
  EXPECT_FALSE(result.ok());
}

// ===  Files  ====================================================================================

std::string writeTemporary(const std::string& name, const std::string& bytes) {
  const std::string path = ::testing::TempDir() + "geodex_mesh_io_test_" + name;
  std::ofstream(path, std::ios::binary) << bytes;
  return path;
}

TEST(MeshIoFiles, LoadMeshBuildsMeshAndReturnsWarnings) {
  const std::string path =
      writeTemporary("warn.OBJ", std::string(kTetrahedronObj) + "v 7 7 7\n");
  std::vector<MeshIssue> warnings;
  const Mesh mesh = loadMesh(path, &warnings);
  EXPECT_EQ(mesh.numFaces(), 4u);
  EXPECT_EQ(mesh.numVertices(), 5u);
  ASSERT_EQ(warnings.size(), 1u);
  expectIssue(warnings, "unreferenced-vertex", Severity::Warning, {path + ":9:", "vertex 4"});
  std::filesystem::remove(path);
}

TEST(MeshIoFiles, LoadMeshThrowsTheFirstError) {
  const std::string path = writeTemporary(
      "bad.off", "OFF\n4 2 0\n0 0 0\n1 0 0\n1 0 0\n0 1 0\n3 0 1 3\n3 1 2 3\n");
  const InputError error = expectInputError([&] { loadMesh(path); });
  EXPECT_EQ(error.kind(), "zero-length-edge");
  expectMessageHas(error, {path + ":8:", "face 1", "vertices 1 and 2"});
  std::filesystem::remove(path);
}

TEST(MeshIoFiles, ExtensionChoosesTheFormatAndMissingFilesAreInputErrors) {
  // Content is PLY but the extension says OFF: the extension wins, and the error says why.
  const std::string path = writeTemporary("really_ply.off", kAsciiPly);
  EXPECT_EQ(expectInputError([&] { readMesh(path); }).kind(), "syntax");
  std::filesystem::remove(path);
  const std::string unknown = writeTemporary("mesh.data", kAsciiPly);
  EXPECT_EQ(readMesh(unknown).soup.faces.size(), 3u);  // detected from content
  std::filesystem::remove(unknown);
  EXPECT_EQ(expectInputError([] { readMesh("/nonexistent/geodex/mesh.obj"); }).kind(), "io");
  EXPECT_EQ(expectInputError([] { readMesh(::testing::TempDir()); }).kind(), "io");
}

#ifdef GEODEX_SOURCE_DIR
TEST(MeshIoFiles, SmallDataFilesReadClean) {
  const std::filesystem::path dir = std::filesystem::path(GEODEX_SOURCE_DIR) / "tests/data/meshes";
  for (const char* name : {"tetrahedron.off", "square_pyramid_quads.obj", "tetrahedron_ascii.ply"}) {
    SCOPED_TRACE(name);
    const std::filesystem::path path = dir / name;
    if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is missing";
    MeshReadResult result = readMesh(path.string());
    validateMesh(result.soup, result.issues);
    for (const MeshIssue& issue : result.issues) {
      EXPECT_EQ(issue.kind, "polygon-triangulated") << issue.message;
    }
    EXPECT_GE(result.soup.faces.size(), 4u);
  }
}
#endif

// ===  Shared real meshes  =======================================================================

#ifdef GEODEX_SHARED_MESH_DIR
std::filesystem::path sharedMesh(const char* name) {
  return std::filesystem::path(GEODEX_SHARED_MESH_DIR) / name;
}
#endif

TEST(MeshIoSharedMeshes, OgreValidatesWithWarningsOnly) {
#ifdef GEODEX_SHARED_MESH_DIR
  const std::filesystem::path path = sharedMesh("ogre.obj");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
  MeshReadResult result = readMesh(path.string());
  EXPECT_EQ(result.soup.positions.size(), 62194u);
  EXPECT_EQ(result.soup.faces.size(), 124008u);
  validateMesh(result.soup, result.issues);
  EXPECT_TRUE(result.ok()) << kinds(result.issues);
  // Counts from /work/shared/meshes/README.md.
  expectIssue(result.issues, "zero-area-face", Severity::Warning, {"4 faces in all"});
  expectIssue(result.issues, "duplicate-position", Severity::Warning, {"9 vertices in all"});
  expectIssue(result.issues, "non-manifold-vertex", Severity::Warning, {"3 vertices in all"});
  expectIssue(result.issues, "components", Severity::Warning, {"ogre.obj:"});
  EXPECT_EQ(result.issues.size(), 4u) << kinds(result.issues);
#else
  GTEST_SKIP() << "GEODEX_SHARED_MESH_DIR is not defined";
#endif
}

TEST(MeshIoSharedMeshes, DragonIsRefusedForZeroLengthEdges) {
#ifdef GEODEX_SHARED_MESH_DIR
  const std::filesystem::path path = sharedMesh("dragon_vrip.obj");
  if (!std::filesystem::exists(path)) GTEST_SKIP() << path << " is absent";
  const InputError error = expectInputError([&] { loadMesh(path.string()); });
  EXPECT_EQ(error.kind(), "zero-length-edge");
  expectMessageHas(error, {"dragon_vrip.obj:", "108 faces in all"});
#else
  GTEST_SKIP() << "GEODEX_SHARED_MESH_DIR is not defined";
#endif
}

}  // namespace
}  // namespace geodex
