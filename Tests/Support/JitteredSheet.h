#pragma once
// An irregular square sheet, as a modeller's mesh: (cells + 1)^2 vertices
// in the plane y = height over [-size/2, size/2]^2, the interior ones moved
// by up to `jitter` cells along x and z, each quad split along a diagonal
// chosen at random (both ways occur), u and v the rest x and z. For tests
// on either device.
#include <string>

#include "Scene/TriangleMesh.h"

namespace soak::test {

TriangleMesh jitteredSheet(int cells, float size, float jitter, float height, unsigned seed);

// Writes `mesh` as an OBJ (v, vt when it has UVs, f v/vt).
void writeObjFile(const TriangleMesh& mesh, const std::string& path);

}  // namespace soak::test
