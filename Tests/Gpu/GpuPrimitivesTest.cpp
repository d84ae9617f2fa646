// Primitives on the GPU: the scan the step uses without waiting (the lists'
// offsets, the drips), at sizes around a block's and in place.
#include <gtest/gtest.h>

#include <random>
#include <vector>

#include "Backend/Buffer.h"
#include "Backend/Primitives.h"
#include "Support/TestScenes.h"

using namespace soak;

TEST(GpuPrimitives, ExclusiveScanAsyncMatchesTheHostAtEverySize) {
  SOAK_SKIP_WITHOUT_GPU();
  std::mt19937 rng(11);
  std::uniform_int_distribution<int> value(0, 90);
  for (int n : {1, 2, 31, 1023, 1024, 1025, 14400, 32767, 32768, 32769, 250000}) {
    std::vector<int> host(static_cast<std::size_t>(n));
    for (int& v : host) v = value(rng);
    std::vector<int> expected(host.size());
    int running = 0;
    for (std::size_t k = 0; k < host.size(); ++k) {
      expected[k] = running;
      running += host[k];
    }
    Buffer<int> in(Device::Cuda), out(Device::Cuda);
    in.upload(host);
    out.resize(host.size());
    exclusiveScanAsync(Device::Cuda, in.data(), out.data(), n);
    EXPECT_EQ(out.download(), expected) << n << " items";
    exclusiveScanAsync(Device::Cuda, in.data(), in.data(), n);  // in place
    EXPECT_EQ(in.download(), expected) << n << " items, in place";
  }
}
