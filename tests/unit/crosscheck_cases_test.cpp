// Tests of verify/src/crosscheck_cases.cpp: the cases `geodex crosscheck` runs are deterministic
// for a seed, cover every family early, grow, put the source on a used vertex and are meshes
// the validator accepts; keepFaces renumbers what it keeps.

#include "geodex/verify/crosscheck_cases.h"

#include <gtest/gtest.h>

#include <set>
#include <sstream>

#include "geodex/mesh_io.h"

namespace geodex::verify {
namespace {

bool usesVertex(const TriangleSoup& soup, Index v) {
  for (const auto& f : soup.faces)
    if (f[0] == v || f[1] == v || f[2] == v) return true;
  return false;
}

TEST(CrossCheckCases, SameSeedSameCasesInTheSameOrder) {
  for (std::size_t i = 0; i < 60; ++i) {
    const CrossCheckCase a = crossCheckCase(7, i), b = crossCheckCase(7, i);
    EXPECT_EQ(a.recipe, b.recipe) << i;
    EXPECT_EQ(a.soup.positions, b.soup.positions) << i;
    EXPECT_EQ(a.soup.faces, b.soup.faces) << i;
    EXPECT_EQ(a.source, b.source) << i;
  }
  // Another seed changes the free parameters (the corpus families cycle the same seeds).
  std::size_t differ = 0;
  for (std::size_t i = 0; i < 60; ++i) differ += crossCheckCase(7, i).recipe != crossCheckCase(8, i).recipe;
  EXPECT_GT(differ, 20u);
}

TEST(CrossCheckCases, EveryFamilyWithinTheFirstRoundAndSmallOnesFirst) {
  const auto& families = crossCheckFamilies();
  const std::size_t n = families.size();
  std::set<std::string> seen;
  std::size_t firstRoundFaces = 0, laterFaces = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const CrossCheckCase c = crossCheckCase(1, i);
    EXPECT_EQ(c.family, families[i]);
    seen.insert(c.family);
    firstRoundFaces += c.soup.faces.size();
    laterFaces += crossCheckCase(1, i + 8 * n).soup.faces.size();
  }
  EXPECT_EQ(seen.size(), n);
  EXPECT_LT(3 * firstRoundFaces, laterFaces);
}

TEST(CrossCheckCases, ValidMeshesWithTheSourceOnAUsedVertex) {
  for (std::size_t i = 0; i < 200; ++i) {
    const CrossCheckCase c = crossCheckCase(3, i);
    SCOPED_TRACE(c.family + ": " + c.recipe);
    std::vector<MeshIssue> issues;
    validateMesh(c.soup, issues);
    for (const MeshIssue& issue : issues) EXPECT_NE(issue.severity, Severity::Error) << issue.message;
    ASSERT_LT(c.source, c.soup.positions.size());
    EXPECT_TRUE(usesVertex(c.soup, c.source));
    if (c.planar != PlanarOracle::None)
      for (const Vec3& p : c.soup.positions) EXPECT_EQ(p.z(), c.soup.positions.front().z());
  }
}

TEST(CrossCheckCases, KeepFacesDropsUnusedVerticesAndRenumbers) {
  TriangleSoup soup;
  soup.positions = {{0, 0, 0}, {1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 2, 0}};
  soup.faces = {{0, 1, 2}, {1, 3, 2}, {3, 4, 2}};
  Index source = 3;
  const TriangleSoup kept = keepFaces(soup, {false, true, true}, source);
  EXPECT_EQ(kept.positions, (std::vector<Vec3>{{1, 0, 0}, {0, 1, 0}, {1, 1, 0}, {2, 2, 0}}));
  EXPECT_EQ(kept.faces, (std::vector<std::array<Index, 3>>{{0, 2, 1}, {2, 3, 1}}));
  EXPECT_EQ(source, 2u);
  Index gone = 0;
  keepFaces(soup, {false, true, true}, gone);
  EXPECT_EQ(gone, kNoIndex);
}

TEST(CrossCheckCases, OffTextReadsBackExactly) {
  const CrossCheckCase c = crossCheckCase(1, 3);  // jittered: full-mantissa coordinates
  const MeshReadResult back = readMeshFromMemory(offText(c.soup), "case.off", "off");
  ASSERT_TRUE(back.ok());
  EXPECT_EQ(back.soup.positions, c.soup.positions);
  EXPECT_EQ(back.soup.faces, c.soup.faces);
}

}  // namespace
}  // namespace geodex::verify
