#pragma once
// The faces' sides sorted by the vertex pair they join, which Mesh::buildEdges and validateMesh
// each need: sides of one edge side by side. Counted out by their smaller vertex first (a
// counting sort), then each vertex's few sides (about six on a closed mesh) sorted in place. One
// std::sort over all of them, 2.6 M sides on the 871K-face dragon, was a twelfth of `geodex info`'s
// time there in each of the two, most of it waiting on memory.

#include <algorithm>
#include <cstddef>
#include <utility>
#include <vector>

namespace geodex::detail {

/// Sorts `sides` by `less`, a strict weak order whose first key is smallerVertex(side), a vertex
/// index below numVertices. The result is std::sort's with `less`, up to the order of sides equal
/// under it.
template <class Side, class SmallerVertex, class Less>
void sortSidesByVertexPair(std::vector<Side>& sides, std::size_t numVertices,
                           SmallerVertex smallerVertex, Less less) {
  // start[v] is where vertex v's sides begin once counted out; next[v] where its next one goes.
  std::vector<std::size_t> start(numVertices + 1, 0);
  for (const Side& s : sides) ++start[smallerVertex(s) + 1];
  for (std::size_t v = 0; v < numVertices; ++v) start[v + 1] += start[v];
  std::vector<std::size_t> next(start.begin(), start.end() - 1);
  std::vector<Side> counted(sides.size());
  for (const Side& s : sides) counted[next[smallerVertex(s)]++] = s;
  for (std::size_t v = 0; v < numVertices; ++v) {
    const auto first = counted.begin() + static_cast<std::ptrdiff_t>(start[v]);
    const auto last = counted.begin() + static_cast<std::ptrdiff_t>(start[v + 1]);
    if (last - first > 1) std::sort(first, last, less);
  }
  sides = std::move(counted);
}

}  // namespace geodex::detail
