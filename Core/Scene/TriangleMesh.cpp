#include "Scene/TriangleMesh.h"

#include <tiny_obj_loader.h>

#include <algorithm>
#include <cmath>
#include <map>
#include <sstream>

#include "Base/Error.h"
#include "Base/ReadInput.h"

namespace soak {

namespace {
bool startsWith(const std::string& line, char c) {
  return line.size() >= 2 && line[0] == c && (line[1] == ' ' || line[1] == '\t');
}

// What tinyobjloader lets pass without a word, checked here so that the
// file is refused with its line number: "nan" or "inf" coordinates (read as
// 0) and faces of one or two vertices (dropped). Records the line of every
// face and every vertex, in order, for messages about them.
struct ObjLines {
  std::vector<int> faces, vertices;
};
ObjLines scanObjLines(const std::string& text, const std::string& path) {
  std::istringstream in(text);
  std::string line;
  ObjLines lines;
  std::vector<int>& faceLines = lines.faces;
  for (int lineNo = 1; std::getline(in, line); ++lineNo) {
    if (startsWith(line, 'f')) {
      std::istringstream tokens(line.substr(0, line.find('#')).substr(2));  // the corners, up to a comment
      int corners = 0;
      for (std::string tok; tokens >> tok;) ++corners;
      if (corners < 3)
        throw InputError("face has " + std::to_string(corners) + " vertices; a face needs at least 3",
                         path + ":" + std::to_string(lineNo));
      faceLines.push_back(lineNo);
    }
    if (!startsWith(line, 'v')) continue;
    lines.vertices.push_back(lineNo);
    std::istringstream tokens(line.substr(2));
    std::string tok;
    for (int c = 0; c < 3 && tokens >> tok; ++c) {
      char* end = nullptr;
      double v = std::strtod(tok.c_str(), &end);
      if (*end || !std::isfinite(v))
        throw InputError("vertex coordinate '" + tok + "' is not a finite number", path + ":" + std::to_string(lineNo));
    }
  }
  return lines;
}

std::string lineOf(const std::vector<int>& lines, std::size_t i) {
  return i < lines.size() && lines[i] > 0 ? " (line " + std::to_string(lines[i]) + ")" : std::string();
}
}  // namespace

TriangleMesh loadObjMesh(const std::string& path) {
  const std::string text = readInputFile(path, kMaxMeshBytes, "OBJ mesh");
  const ObjLines lines = scanObjLines(text, path);
  const std::vector<int>& faceLines = lines.faces;
  tinyobj::ObjReaderConfig config;
  config.triangulate = false;
  config.vertex_color = false;
  tinyobj::ObjReader reader;
  // From the text already read: materials (mtllib) are not read, so an OBJ
  // cannot send the reader to another file.
  if (!reader.ParseFromString(text, std::string(), config)) {
    std::string why = reader.Error();
    while (!why.empty() && (why.back() == '\n' || why.back() == '\r')) why.pop_back();
    throw InputError("cannot read OBJ mesh: " + (why.empty() ? std::string("unknown error") : why), path);
  }
  const tinyobj::attrib_t& attrib = reader.GetAttrib();
  TriangleMesh mesh;
  const std::size_t nv = attrib.vertices.size() / 3;
  mesh.vertices.resize(nv);
  if (lines.vertices.size() == nv) mesh.vertexLines = lines.vertices;
  for (std::size_t i = 0; i < nv; ++i)
    mesh.vertices[i] = Vec3(attrib.vertices[3 * i], attrib.vertices[3 * i + 1], attrib.vertices[3 * i + 2]);
  // Faces in file order (shapes are too), so face k is on faceLines[k]
  // when tinyobjloader kept every face line.
  std::size_t face = 0;
  for (const tinyobj::shape_t& shape : reader.GetShapes()) {
    std::size_t offset = 0;
    for (std::size_t f = 0; f < shape.mesh.num_face_vertices.size(); ++f, ++face) {
      const int k = shape.mesh.num_face_vertices[f];
      const int line = face < faceLines.size() ? faceLines[face] : 0;
      const std::string where = line > 0 ? path + ":" + std::to_string(line) : path;
      if (k < 3) throw InputError("face has " + std::to_string(k) + " vertices; a face needs at least 3", where);
      // A vertex's material coordinates: the first vt a face gives it.
      for (int c = 0; c < k && !attrib.texcoords.empty(); ++c) {
        const tinyobj::index_t ix = shape.mesh.indices[offset + std::size_t(c)];
        if (ix.texcoord_index < 0 || std::size_t(ix.vertex_index) >= nv ||
            2 * std::size_t(ix.texcoord_index) + 1 >= attrib.texcoords.size())
          continue;
        if (mesh.uv.empty()) mesh.uv.assign(nv, {std::nanf(""), std::nanf("")});
        auto& uv = mesh.uv[std::size_t(ix.vertex_index)];
        if (std::isnan(uv[0]))
          uv = {attrib.texcoords[2 * std::size_t(ix.texcoord_index)], attrib.texcoords[2 * std::size_t(ix.texcoord_index) + 1]};
      }
      for (int c = 1; c + 1 < k; ++c) {  // a fan: (0, c, c+1)
        mesh.triangles.push_back({shape.mesh.indices[offset].vertex_index, shape.mesh.indices[offset + c].vertex_index,
                                  shape.mesh.indices[offset + c + 1].vertex_index});
        mesh.triangleLines.push_back(line);
      }
      offset += std::size_t(k);
    }
  }
  // Material coordinates only where every vertex has them.
  for (const auto& uv : mesh.uv)
    if (!std::isfinite(uv[0]) || !std::isfinite(uv[1])) {
      mesh.uv.clear();
      break;
    }
  validateClothMesh(mesh, path);
  return mesh;
}

void validateClothMesh(const TriangleMesh& mesh, const std::string& name) {
  const int nv = static_cast<int>(mesh.vertices.size());
  for (int i = 0; i < nv; ++i)
    if (!isFinite(mesh.vertices[i]))
      throw InputError("vertex " + std::to_string(i + 1) + " has a NaN or infinite coordinate", name);
  if (mesh.triangles.empty()) throw InputError("mesh has no triangles", name);
  std::map<std::pair<int, int>, int> edgeUse;
  std::map<std::array<int, 3>, std::size_t> firstWithCorners;  // sorted corners -> first triangle
  std::vector<bool> used(std::size_t(nv), false);
  for (std::size_t f = 0; f < mesh.triangles.size(); ++f) {
    const auto& t = mesh.triangles[f];
    const bool hasLine = f < mesh.triangleLines.size() && mesh.triangleLines[f] > 0;
    const std::string where = hasLine ? name + ":" + std::to_string(mesh.triangleLines[f]) : name;
    for (int c = 0; c < 3; ++c)
      if (t[c] < 0 || t[c] >= nv)
        throw InputError("triangle " + std::to_string(f + 1) + " uses vertex index " + std::to_string(t[c] + 1) +
                             ", out of range 1.." + std::to_string(nv), where);
    if (t[0] == t[1] || t[1] == t[2] || t[0] == t[2])
      throw InputError("triangle " + std::to_string(f + 1) + " is degenerate (a vertex repeats)", where);
    const Vec3 a = mesh.vertices[t[0]], b = mesh.vertices[t[1]], c = mesh.vertices[t[2]];
    const float area2 = length(cross(b - a, c - a));
    const float scale = std::max({lengthSquared(b - a), lengthSquared(c - a), lengthSquared(c - b)});
    if (!(area2 > 1e-7f * scale))
      throw InputError("triangle " + std::to_string(f + 1) + " is degenerate (zero area)", where);
    // The same three vertices twice, in either winding: each edge looks
    // shared by two triangles, and the pair would fold the cloth onto itself.
    std::array<int, 3> corners = t;
    std::sort(corners.begin(), corners.end());
    const auto [first, fresh] = firstWithCorners.emplace(corners, f);
    if (!fresh)
      throw InputError("triangle " + std::to_string(f + 1) + " repeats triangle " + std::to_string(first->second + 1) +
                           lineOf(mesh.triangleLines, first->second) + ": the same three vertices; remove one",
                       where);
    for (int k : t) used[std::size_t(k)] = true;
    for (int c2 = 0; c2 < 3; ++c2) {
      int u = t[c2], v = t[(c2 + 1) % 3];
      if (++edgeUse[{std::min(u, v), std::max(u, v)}] > 2)
        throw InputError("edge between vertices " + std::to_string(std::min(u, v) + 1) + " and " +
                             std::to_string(std::max(u, v) + 1) +
                             " is shared by more than two triangles (non-manifold; cloth meshes allow at most two, "
                             "paper Section 3.2)",
                         where);
    }
  }
  for (int i = 0; i < nv; ++i)
    if (!used[std::size_t(i)]) {
      const bool hasLine = std::size_t(i) < mesh.vertexLines.size() && mesh.vertexLines[std::size_t(i)] > 0;
      throw InputError("vertex " + std::to_string(i + 1) +
                           " is used by no triangle: it would fall as a lone particle; remove it",
                       hasLine ? name + ":" + std::to_string(mesh.vertexLines[std::size_t(i)]) : name);
    }
}

}  // namespace soak
