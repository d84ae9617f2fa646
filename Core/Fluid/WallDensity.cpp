#include "Fluid/WallDensity.h"

#include <cmath>

#include "Fluid/SphKernels.h"

namespace soak {

WallDensityTable makeWallDensityTable(float spacing, float supportRadius, float particleMass) {
  WallDensityTable t;
  const double h = supportRadius, r0 = spacing;
  t.range = float(h);
  t.step = float(h / (WallDensityTable::kSamples - 1));
  // Density of one continuous layer (areal density m / r0^2) at height z:
  // 2 pi m / r0^2 * integral_0^sqrt(h^2 - z^2) W(sqrt(s^2 + z^2)) s ds.
  auto layer = [&](double z) {
    if (std::fabs(z) >= h) return 0.0;
    const int n = 200;
    const double smax = std::sqrt(h * h - z * z);
    double sum = 0.0;
    for (int k = 0; k < n; ++k) {
      const double s = (k + 0.5) * smax / n;
      sum += double(poly6(float(s * s + z * z), float(h))) * s;
    }
    return 2.0 * double(kPi) * particleMass / (r0 * r0) * sum * smax / n;
  };
  for (int i = 0; i < WallDensityTable::kSamples; ++i) {
    const double d = i * double(t.step);
    double rho = 0.0;
    for (double z = d + 0.5 * r0; z < h; z += r0) rho += layer(z);
    t.rho[i] = float(rho);
  }
  for (int i = 0; i < WallDensityTable::kSamples; ++i) {
    const int a = i > 0 ? i - 1 : i, b = i + 1 < WallDensityTable::kSamples ? i + 1 : i;
    t.slope[i] = (t.rho[b] - t.rho[a]) / (float(b - a) * t.step);
  }
  return t;
}

}  // namespace soak
