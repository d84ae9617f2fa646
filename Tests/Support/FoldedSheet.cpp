#include "Support/FoldedSheet.h"

#include <algorithm>
#include <fstream>

#include "Support/TestScenes.h"

namespace soak::test {

void FoldedSheet::write(const std::string& path) const {
  std::ofstream f(path);
  for (int j = 0; j <= n; ++j)
    for (int i = 0; i <= 2 * n; ++i) {
      const float u = float(i) / n * size;  // 0 .. 2 size; fold at u = size
      Vec3 p(u, y0, float(j) / n * size);
      if (i > n) p = Vec3(2.f * size - u, y0 + gap, p.z);
      else if (i == n) p = Vec3(size + 0.5f * gap, y0 + 0.5f * gap, p.z);
      f << "v " << p.x << " " << p.y << " " << p.z << "\n";
    }
  const int row = 2 * n + 1;
  for (int j = 0; j < n; ++j)
    for (int i = 0; i < 2 * n; ++i) {
      const int a = j * row + i, b = a + 1, c = a + row, d = c + 1;
      f << "f " << a + 1 << " " << b + 1 << " " << d + 1 << "\n";
      f << "f " << a + 1 << " " << d + 1 << " " << c + 1 << "\n";
    }
}

float FoldedSheet::smallestLayerGap(const std::vector<Vec3>& x) const {
  const int row = 2 * n + 1;
  float worst = 1e9f;
  for (int j = 2; j <= n - 2; ++j)
    for (int i = 2; i <= n - 4; ++i) {
      const Vec3 lower = x[std::size_t(j * row + i)], upper = x[std::size_t(j * row + (2 * n - i))];
      worst = std::min(worst, upper.y - lower.y);
    }
  return worst;
}

float FoldedSheet::smallestGapWhenDropped(Device device, const std::string& obj, const std::string& simulation,
                                          const std::string& cloth, int steps) const {
  write(obj);
  TestRegistry reg;
  auto sim = makeSimulation("<Scene><Simulation " + simulation + "/><Cloth name='folded' mesh='" + obj +
                                "' bendStiffness='0' " + cloth + "/><Plane point='0 0 0' normal='0 1 0'/></Scene>",
                            device, reg);
  float worst = 1e9f;
  for (int s = 0; s < steps; ++s) {
    sim->step();
    worst = std::min(worst, smallestLayerGap(sim->cloth.downloadVertexPositions(sim->particles, 0)));
  }
  return worst;
}

}  // namespace soak::test
