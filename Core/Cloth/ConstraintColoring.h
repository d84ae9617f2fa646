#pragma once
// Greedy graph colouring of constraints so that no two constraints of one
// colour share a vertex. Each colour can then be projected in parallel with
// plain writes (Gauss-Seidel between colours, no atomics, the same result
// for any thread count or device).
#include <vector>

namespace soak {

struct ColouredOrder {
  // Constraint indices grouped by colour: colour c holds
  // order[colourStart[c] .. colourStart[c + 1]).
  std::vector<int> order;
  std::vector<int> colourStart;
  int colours() const { return colourStart.empty() ? 0 : int(colourStart.size()) - 1; }
};

// `vertices[k * arity + a]` is vertex a of constraint k; vertexCount bounds them.
ColouredOrder colourConstraints(const std::vector<int>& vertices, int arity, int vertexCount);

}  // namespace soak
