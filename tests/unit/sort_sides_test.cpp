// The faces' sides sorted by vertex pair (solver/src/sort_sides.h), which Mesh::buildEdges and
// validateMesh turn into edges and findings: the same order as std::sort with the same
// comparison, or an edge would get other faces and a finding would name other elements.

#include "../../solver/src/sort_sides.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <random>
#include <vector>

namespace geodex {
namespace {

struct TestSide {
  std::uint32_t a, b, face;
  bool operator==(const TestSide&) const = default;
};

bool lessByPairThenFace(const TestSide& x, const TestSide& y) {
  return x.a != y.a ? x.a < y.a : (x.b != y.b ? x.b < y.b : x.face < y.face);
}

// Random sides over few vertices (many per vertex, repeated pairs) and over many (vertices with
// none, the first and the last vertex used or not), and no sides at all.
TEST(SortSides, GivesStdSortsOrderWhateverTheVerticesAndTheirSides) {
  std::mt19937 random(11);
  for (int trial = 0; trial < 2000; ++trial) {
    const std::size_t numVertices = 1 + random() % (trial % 2 == 0 ? 4 : 200);
    const std::size_t numSides = random() % 60;
    std::vector<TestSide> sides;
    for (std::size_t i = 0; i < numSides; ++i) {
      auto u = static_cast<std::uint32_t>(random() % numVertices);
      auto v = static_cast<std::uint32_t>(random() % numVertices);
      if (u > v) std::swap(u, v);
      sides.push_back({u, v, static_cast<std::uint32_t>(random() % 1000)});
    }
    std::vector<TestSide> expected = sides;
    std::sort(expected.begin(), expected.end(), lessByPairThenFace);
    detail::sortSidesByVertexPair(
        sides, numVertices, [](const TestSide& s) { return s.a; }, lessByPairThenFace);
    ASSERT_EQ(sides, expected) << "trial " << trial;
  }
}

}  // namespace
}  // namespace geodex
