#pragma once
// Stretch limits of the chebyshev cloth solve (Doc/model.md, "Stretch
// limits"): unilateral distance constraints that keep vertex `a` within
// `rest` of vertex `b`, between vertices 2, 4, 8, ... edges apart along a
// line of the mesh. `rest` is the rest length of the path of edges between
// them, a curve on the cloth, so it is at least their geodesic distance,
// which no isometric motion (bending, folding, draping) lengthens: a limit
// never resists those. It only resists stretch, and carries that
// resistance 2^m edges in one Jacobi iteration instead of m, as the long-range
// attachments of Kim, Chentanez and Müller (2012) carry it from the pins.
// Host side, built once at set-up from the rest mesh (nothing to checkpoint).
#include <vector>

#include "Base/Vec3.h"
#include "Cloth/ClothTopology.h"

namespace soak {

struct StretchLimit {
  int a = 0, b = 0;  // `a` is kept within `rest` of `b` (a's view; the solve gathers per vertex)
  float rest = 0.f;
};

// A generated sheet of `rows` rows of `columns` vertices: its rows and
// columns are the lines; rest is the straight rest distance (the sheet is cut
// flat). Both views of each pair.
std::vector<StretchLimit> sheetStretchLimits(const std::vector<Vec3>& rest, int columns, int rows);

// Any triangle mesh: the lines are the straightest chains of edges. Every
// edge lies on exactly one line; a line goes on from a vertex along the
// edge best aligned with its direction over its last two edges, while that
// edge is within kLineTurn of it, is on no line yet, and leads to a vertex
// not on the line. Both views of each pair.
std::vector<StretchLimit> meshStretchLimits(const std::vector<Vec3>& rest, const ClothTopology& topo);

// Cosine of the largest turn a line takes at a vertex (35 degrees): a
// quad-dominant or Delaunay-like mesh has an edge within 30 degrees of any
// direction, so lines cross the mesh; a turn onto a diagonal (45 degrees)
// ends the line.
constexpr float kLineTurn = 0.82f;

}  // namespace soak
