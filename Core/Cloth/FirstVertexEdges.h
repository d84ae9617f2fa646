#pragma once
// The edges the crossing guard tests (CrossingGuard.h), per vertex, built
// once from the cloths' triangles: the edges whose first (lower) vertex it
// is, so that a pass over the vertices visits each edge once.
#include <vector>

#include "Cloth/ClothSystem.h"

namespace soak {

struct FirstVertexEdges {
  std::vector<int> start;  // CSR over vertices
  std::vector<int> other;  // each edge's second vertex, increasing within a vertex
};

FirstVertexEdges buildFirstVertexEdges(const std::vector<ClothTriangle>& triangles, int vertexCount);

}  // namespace soak
