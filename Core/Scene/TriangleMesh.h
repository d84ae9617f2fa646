#pragma once
#include <array>
#include <string>
#include <vector>

#include "Base/Vec3.h"

namespace soak {

struct TriangleMesh {
  std::vector<Vec3> vertices;
  std::vector<std::array<int, 3>> triangles;
  // Line of the source file each triangle comes from (empty if none), so
  // that errors name file:line.
  std::vector<int> triangleLines;
  // The same for each vertex.
  std::vector<int> vertexLines;
  // Material coordinates per vertex (m, or the OBJ's vt): the fabric's warp
  // runs along u and its weft along v. Empty where the source has none.
  std::vector<std::array<float, 2>> uv;
};

// Loads an OBJ file through tinyobjloader (polygons are split into fans).
// Throws InputError naming the file for: a file that cannot be read or
// parsed, a NaN or infinite coordinate, a face index out of range, no
// triangles, a face of fewer than 3 vertices, a degenerate triangle (repeated vertex or zero area), a
// triangle that repeats another's three vertices, a vertex no triangle uses
// (it would fall as a lone particle), or an edge shared by more than two
// triangles (the paper's one restriction on cloth meshes, Section 3.2).
TriangleMesh loadObjMesh(const std::string& path);

// The checks above on a mesh from any source; `name` is used in messages.
void validateClothMesh(const TriangleMesh& mesh, const std::string& name);

}  // namespace soak
