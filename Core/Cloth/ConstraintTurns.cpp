#include "Cloth/ConstraintTurns.h"

namespace soak {

ConstraintTurns constraintTurns(int vertexCount, const std::vector<char>& tethered,
                                const std::vector<int>& edgeVertices, const std::vector<int>& bendVertices) {
  // Constraints per vertex in one iteration, then each use's place among them
  // in phase order. Within a colour no two constraints share a vertex, so the
  // uses counted so far are those of the earlier phases.
  std::vector<int> uses(std::size_t(vertexCount), 0), taken(std::size_t(vertexCount), 0);
  for (int v = 0; v < vertexCount; ++v) uses[v] += tethered[v] ? 1 : 0;
  for (int v : edgeVertices) ++uses[v];
  for (int v : bendVertices) ++uses[v];
  ConstraintTurns t;
  for (int u : uses) t.fits = t.fits && u < kTurnsPerRound;
  auto take = [&](int v) {
    const std::uint32_t turn = std::uint32_t(taken[v]) & 0x7fffu;
    const bool last = ++taken[v] == uses[v];
    return turn | (last ? 0x8000u : 0u);
  };
  t.tether.assign(std::size_t(vertexCount), 0u);
  for (int v = 0; v < vertexCount; ++v)
    if (tethered[v]) t.tether[v] = take(v);
  t.edge.resize(edgeVertices.size() / 2);
  for (std::size_t e = 0; e < t.edge.size(); ++e) {
    const std::uint32_t a = take(edgeVertices[2 * e]);
    t.edge[e] = a | take(edgeVertices[2 * e + 1]) << 16;
  }
  t.bend.resize(bendVertices.size() / 4);
  for (std::size_t b = 0; b < t.bend.size(); ++b)
    for (int w = 0; w < 2; ++w) {
      const std::uint32_t lo = take(bendVertices[4 * b + 2 * w]);
      t.bend[b].word[w] = lo | take(bendVertices[4 * b + 2 * w + 1]) << 16;
    }
  return t;
}

}  // namespace soak
