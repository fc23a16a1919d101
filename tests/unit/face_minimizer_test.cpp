// Tests of verify/src/face_minimizer.cpp: delta debugging over faces finds the faces a failure
// needs, keeps the source, stays within its budget and asks the same questions every time.

#include "geodex/verify/face_minimizer.h"

#include <gtest/gtest.h>

#include <algorithm>

#include "geodex/verify/mesh_generators.h"

namespace geodex::verify {
namespace {

/// Whether the soup has a face with these three corner positions.
bool hasFace(const TriangleSoup& soup, const std::array<Vec3, 3>& corners) {
  return std::any_of(soup.faces.begin(), soup.faces.end(), [&](const auto& f) {
    return soup.positions[f[0]] == corners[0] && soup.positions[f[1]] == corners[1] &&
           soup.positions[f[2]] == corners[2];
  });
}

std::array<Vec3, 3> cornersOf(const TriangleSoup& soup, std::size_t f) {
  const auto& t = soup.faces[f];
  return {soup.positions[t[0]], soup.positions[t[1]], soup.positions[t[2]]};
}

TEST(FaceMinimizer, FindsTheTwoFacesAFailureNeeds) {
  const TriangleSoup grid = gridMesh(8, 8, 1.0, 1.0);
  const auto a = cornersOf(grid, 17), b = cornersOf(grid, 101);
  std::size_t asked = 0;
  const auto needsBoth = [&](const TriangleSoup& soup, Index) {
    ++asked;
    return hasFace(soup, a) && hasFace(soup, b);
  };
  const Index source = grid.faces[17][0];
  const MinimizedCase m = minimizeFaces(grid, source, needsBoth);
  EXPECT_EQ(m.soup.faces.size(), 2u);
  EXPECT_TRUE(hasFace(m.soup, a) && hasFace(m.soup, b));
  EXPECT_EQ(m.soup.positions[m.source], grid.positions[source]);
  EXPECT_EQ(m.trials, asked);
  EXPECT_STREQ(m.stoppedBy, "");
  EXPECT_LT(m.trials, 60u);  // far fewer than one per face and pair

  // The same questions give the same answer.
  const MinimizedCase again = minimizeFaces(grid, source, needsBoth);
  EXPECT_EQ(again.soup.faces, m.soup.faces);
  EXPECT_EQ(again.trials, m.trials);
}

TEST(FaceMinimizer, NeverOffersACandidateWithoutTheSource) {
  const TriangleSoup grid = gridMesh(4, 4, 1.0, 1.0);
  const Index source = 12;  // the centre
  const MinimizedCase m = minimizeFaces(grid, source, [&](const TriangleSoup& soup, Index s) {
    EXPECT_LT(s, soup.positions.size());
    EXPECT_EQ(soup.positions[s], grid.positions[source]);
    return true;  // everything fails: down to one face at the source
  });
  EXPECT_EQ(m.soup.faces.size(), 1u);
}

TEST(FaceMinimizer, StopsAtTheTrialBudgetAndSaysSo) {
  const TriangleSoup grid = gridMesh(10, 10, 1.0, 1.0);
  MinimizeBudget budget;
  budget.maxTrials = 5;
  const auto a = cornersOf(grid, 3), b = cornersOf(grid, 150);
  const MinimizedCase m = minimizeFaces(
      grid, grid.faces[3][0], [&](const TriangleSoup& soup, Index) { return hasFace(soup, a) && hasFace(soup, b); },
      budget);
  EXPECT_EQ(m.trials, 5u);
  EXPECT_STREQ(m.stoppedBy, "trials");
  EXPECT_TRUE(hasFace(m.soup, a) && hasFace(m.soup, b));
}

TEST(FaceMinimizer, TriesTheCallersSubsetFirst) {
  const TriangleSoup grid = gridMesh(6, 6, 1.0, 1.0);
  std::vector<bool> subset(grid.faces.size(), false);
  subset[0] = subset[1] = true;
  std::size_t firstSize = 0;
  const MinimizedCase m = minimizeFaces(
      grid, 0,
      [&](const TriangleSoup& soup, Index) {
        if (firstSize == 0) firstSize = soup.faces.size();
        return true;
      },
      {}, subset);
  EXPECT_EQ(firstSize, 2u);
  EXPECT_EQ(m.soup.faces.size(), 1u);
}

}  // namespace
}  // namespace geodex::verify
