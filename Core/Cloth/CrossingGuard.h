#pragma once
// The last word of a cloth sub-step on self-intersection: an edge that ends
// the sub-step through a triangle it did not pass through at the start
// (neither sharing a vertex) puts its two vertices and the triangle's three
// back where the sub-step started them, and the test runs again, for
// `rounds` rounds.
//
// Why: the contact passes hold each pair on its side only where they see
// it: particle contact before the solve, the vertex-triangle test after
// it. Two free edges that pass each other like the blades of scissors
// bring no vertex near a triangle or another vertex, so neither sees them
// (fig9's four corners meeting under the ball at 6-9 m/s relative), and a
// sheet that has passed through itself stays tangled: every test then
// holds it on its wrong side (Doc/design.md, "Tangles and the crossing
// guard"). Put back at the start of the sub-step, the five vertices
// are where they were not crossed; they lose that sub-step's motion, as an
// inelastic impact would (the simplest of the fail-safes of Bridson,
// Fedkiw and Anderson 2002, who stop the vertices of an impact zone
// together). A vertex put back can push its edges into new crossings, hence
// the rounds; each round can only put back more vertices, so the rounds
// converge on the sub-step's start, which had no new crossing.
#include "Cloth/ClothContactLists.h"
#include "Cloth/ClothSystem.h"

namespace soak {

// Whether segment p0 p1 passes through triangle (a, b, c): its ends lie
// strictly on both sides of the triangle's plane and the crossing point lies
// inside (the test of Demos/scripts/cloth_intersections.py).
SOAK_INLINE bool segmentCrossesTriangle(Vec3 p0, Vec3 p1, Vec3 a, Vec3 b, Vec3 c) {
  const Vec3 n = cross(b - a, c - a);
  const float s0 = dot(p0 - a, n), s1 = dot(p1 - a, n);
  if (!(s0 * s1 < 0.f)) return false;
  const Vec3 q = p0 + (p1 - p0) * (s0 / (s0 - s1));
  return dot(cross(b - a, q - a), n) >= 0.f && dot(cross(c - b, q - b), n) >= 0.f &&
         dot(cross(a - c, q - c), n) >= 0.f;
}

// `rounds` rounds over the view's x* (`position`: the sub-step's start).
// `flag`: p.count + rounds ints, all 0 (left 0): one per particle slot, then
// one per round. onlyIf (device memory): no round unless *onlyIf is 1.
void revertNewCrossings(Device d, ParticleView p, ClothContactView n, int* flag, int rounds,
                        const int* onlyIf = nullptr);

}  // namespace soak
