// Neighbour search on the GPU: the same brute-force checks as on the CPU.
#include <gtest/gtest.h>

#include "Support/NeighbourChecks.h"
#include "Support/TestScenes.h"

using namespace soak;

TEST(GpuNeighbourSearch, MatchesBruteForceOnCuda) {
  SOAK_SKIP_WITHOUT_GPU();
  for (const test::PointCase& c : test::neighbourCases()) test::expectNeighboursMatchBruteForce(Device::Cuda, c);
}
