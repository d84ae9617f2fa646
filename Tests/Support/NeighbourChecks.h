#pragma once
#include <string>
#include <vector>

#include "Backend/Device.h"
#include "Base/Vec3.h"

namespace soak::test {

// Named point sets for neighbour-search tests.
struct PointCase {
  std::string name;
  std::vector<Vec3> points;
  std::vector<float> radii;
};
std::vector<PointCase> neighbourCases();

// Builds the grid on `device` and checks, for every particle, that the
// neighbour set found equals brute force (|xi - xj| < max(hi, hj)), that the
// particle arrays were reordered consistently, and that no pair is visited
// twice. Reports failures through gtest.
void expectNeighboursMatchBruteForce(Device device, const PointCase& c);

}  // namespace soak::test
