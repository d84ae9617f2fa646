#include "Support/JitteredSheet.h"

#include <cstdio>
#include <fstream>
#include <random>

namespace soak::test {

TriangleMesh jitteredSheet(int cells, float size, float jitter, float height, unsigned seed) {
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> offset(-jitter, jitter);
  std::bernoulli_distribution flip(0.5);
  const float h = size / float(cells);
  TriangleMesh m;
  for (int j = 0; j <= cells; ++j)
    for (int i = 0; i <= cells; ++i) {
      float x = -0.5f * size + h * float(i), z = -0.5f * size + h * float(j);
      if (i > 0 && i < cells && j > 0 && j < cells) {
        x += h * offset(rng);
        z += h * offset(rng);
      }
      m.vertices.push_back(Vec3(x, height, z));
      m.uv.push_back({x + 0.5f * size, z + 0.5f * size});
    }
  auto id = [&](int i, int j) { return j * (cells + 1) + i; };
  for (int j = 0; j < cells; ++j)
    for (int i = 0; i < cells; ++i) {
      const int a = id(i, j), b = id(i + 1, j), c = id(i + 1, j + 1), d = id(i, j + 1);
      if (flip(rng)) {
        m.triangles.push_back({a, b, c});
        m.triangles.push_back({a, c, d});
      } else {
        m.triangles.push_back({a, b, d});
        m.triangles.push_back({b, c, d});
      }
    }
  return m;
}

void writeObjFile(const TriangleMesh& mesh, const std::string& path) {
  std::ofstream f(path);
  char line[128];
  for (const Vec3& v : mesh.vertices) {
    std::snprintf(line, sizeof line, "v %.7g %.7g %.7g\n", double(v.x), double(v.y), double(v.z));
    f << line;
  }
  for (const auto& t : mesh.uv) {
    std::snprintf(line, sizeof line, "vt %.7g %.7g\n", double(t[0]), double(t[1]));
    f << line;
  }
  const bool uv = mesh.uv.size() == mesh.vertices.size();
  for (const auto& t : mesh.triangles) {
    f << "f";
    for (int c = 0; c < 3; ++c) f << " " << t[c] + 1 << (uv ? "/" + std::to_string(t[c] + 1) : std::string());
    f << "\n";
  }
}

}  // namespace soak::test
