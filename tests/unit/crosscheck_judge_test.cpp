// Tests of verify/src/crosscheck_judge.cpp: reading another program's output without trusting
// it, and judging it against geodex's checked distances and the oracles. The distances judged
// here are made independently of geodex (Euclidean distances on a flat grid, which are exact
// there, and edge-graph paths), then broken in known ways.

#include "geodex/verify/crosscheck_judge.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

#include "geodex/verify/mesh_generators.h"
#include "geodex/verify/oracles.h"

namespace geodex::verify {
namespace {

CrossCheckCase flatGridCase() {
  CrossCheckCase c;
  c.family = "flat-grid";
  c.soup = gridMesh(4, 3, 2.0, 1.5, DiagonalPattern::Alternating);
  c.source = 6;
  c.planar = PlanarOracle::Convex;
  return c;
}

/// What a correct program writes on a flat convex grid: the straight distances.
ProgramDistances euclidean(const CrossCheckCase& c) {
  return {euclideanDistances(c.soup.positions, c.soup.positions[c.source]), 0, ""};
}

TEST(CrossCheckParse, EveryWayOfSayingUnreachable) {
  const ProgramDistances p = parseDistances("0\n1.5\n inf\nnan\n-1\n1e100\n1e99\n9.9e98\r\nInfinity\n2e-300 \n");
  ASSERT_EQ(p.badLine, 0u);
  const std::vector<double> expected{0, 1.5, INFINITY, INFINITY, INFINITY, INFINITY, INFINITY, 9.9e98, INFINITY, 2e-300};
  EXPECT_EQ(p.values, expected);
}

TEST(CrossCheckParse, LinesAndBadLines) {
  EXPECT_EQ(parseDistances("").values.size(), 0u);
  EXPECT_EQ(parseDistances("1\n2").values.size(), 2u);  // no final newline
  EXPECT_EQ(parseDistances("1\n2\n").values.size(), 2u);
  const ProgramDistances twoNumbers = parseDistances("1\n2 3\n4\n");
  EXPECT_EQ(twoNumbers.badLine, 2u);
  EXPECT_EQ(twoNumbers.badText, "2 3");
  EXPECT_EQ(parseDistances("1\n\n2\n").badLine, 2u);  // an empty line is no distance
  EXPECT_EQ(parseDistances("distance\n").badLine, 1u);
  EXPECT_EQ(parseDistances("0x\n").badLine, 1u);
}

TEST(CrossCheckReference, FlatGridIsEuclideanAndSaysWhatItExercises) {
  const CrossCheckCase c = flatGridCase();
  const Reference r = referenceDistances(c);
  ASSERT_EQ(r.problem, "");
  const ProgramDistances e = euclidean(c);
  ASSERT_EQ(r.distances.size(), e.values.size());
  for (std::size_t v = 0; v < e.values.size(); ++v) EXPECT_NEAR(r.distances[v], e.values[v], 1e-14);
  const auto has = [&](const std::string& prefix) {
    for (const std::string& x : r.exercised)
      if (x.rfind(prefix, 0) == 0) return true;
    return false;
  };
  EXPECT_TRUE(has("flat vertices")) << testing::PrintToString(r.exercised);
  EXPECT_TRUE(has("boundary vertices"));
}

TEST(CrossCheckReference, AMeshGeodexRefusesIsAProblemNotACrash) {
  CrossCheckCase c = flatGridCase();
  c.soup.faces.push_back(c.soup.faces.front());  // a duplicate face: refused
  EXPECT_NE(referenceDistances(c).problem, "");
}

TEST(CrossCheckJudge, AgreementAndEachKindOfDisagreement) {
  const CrossCheckCase c = flatGridCase();
  const Reference r = referenceDistances(c);
  const ProgramDistances right = euclidean(c);
  EXPECT_FALSE(judgeDistances(c, r, right, 1e-9).kind);

  ProgramDistances off = right;
  off.values[11] += 1e-6;
  const Judgement wrong = judgeDistances(c, r, off, 1e-9);
  ASSERT_EQ(wrong.kind, FindingKind::WrongDistance);
  ASSERT_EQ(wrong.worst.size(), 1u);
  EXPECT_EQ(wrong.worst.front().vertex, 11u);
  EXPECT_NEAR(wrong.worst.front().error, 1e-6, 1e-12);
  EXPECT_EQ(wrong.error.size(), c.soup.positions.size());
  EXPECT_FALSE(judgeDistances(c, r, off, 1e-5).kind) << "1e-6 is within 1e-5 of the largest distance";

  ProgramDistances lost = right;
  lost.values[3] = INFINITY;
  const Judgement unreachable = judgeDistances(c, r, lost, 1e-9);
  EXPECT_EQ(unreachable.kind, FindingKind::Reachability);
  EXPECT_EQ(unreachable.worst.front().vertex, 3u);

  ProgramDistances shorter = right;
  shorter.values.pop_back();
  EXPECT_EQ(judgeDistances(c, r, shorter, 1e-9).kind, FindingKind::LineCount);
  EXPECT_EQ(judgeDistances(c, r, parseDistances("0\nzero\n"), 1e-9).kind, FindingKind::BadValue);
}

TEST(CrossCheckJudge, EdgePathsAreTooLongAndTheOraclesSaySoToo) {
  const CrossCheckCase c = flatGridCase();
  const Reference r = referenceDistances(c);
  const ProgramDistances alongEdges{edgeGraphDijkstra(c.soup, {{c.source, 0.0}}), 0, ""};
  const Judgement j = judgeDistances(c, r, alongEdges, 1e-9);
  ASSERT_EQ(j.kind, FindingKind::WrongDistance);
  bool planarFailed = false;
  for (const std::string& line : j.oracles) planarFailed |= line.rfind("planar-euclidean: FAILED", 0) == 0;
  EXPECT_TRUE(planarFailed) << testing::PrintToString(j.oracles);
}

TEST(CrossCheckJudge, UnreachableComponentMustStayUnreachable) {
  CrossCheckCase c = flatGridCase();
  c.planar = PlanarOracle::None;
  const Index offset = static_cast<Index>(c.soup.positions.size());
  for (const Vec3& p : std::vector<Vec3>{{5, 0, 0}, {6, 0, 0}, {5, 1, 0}}) c.soup.positions.push_back(p);
  c.soup.faces.push_back({offset, offset + 1, offset + 2});
  const Reference r = referenceDistances(c);
  ASSERT_EQ(r.problem, "");
  EXPECT_TRUE(std::isinf(r.distances[offset]));
  ProgramDistances zeroThere = euclidean(c);  // finite everywhere: wrong on the second part
  EXPECT_EQ(judgeDistances(c, r, zeroThere, 1e-9).kind, FindingKind::Reachability);
  // As Kirsanov's MMP and VTP write it: 1e100.
  std::string text;
  for (Index v = 0; v < zeroThere.values.size(); ++v) {
    char line[40];
    std::snprintf(line, sizeof line, "%.17g\n", v >= offset ? 1e100 : zeroThere.values[v]);
    text += line;
  }
  const Judgement j = judgeDistances(c, r, parseDistances(text), 1e-9);
  EXPECT_FALSE(j.kind) << j.what << testing::PrintToString(j.oracles);
}

}  // namespace
}  // namespace geodex::verify
