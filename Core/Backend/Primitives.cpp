#include "Backend/Primitives.h"

#include <algorithm>
#include <numeric>
#include <vector>

#include "Backend/CudaBackend.h"

namespace soak {

namespace {
constexpr int kChunk = 4096;

template <class Partial, class Combine>
Partial chunkedReduce(int n, Partial init, Partial (*chunkFn)(const float*, int, int), const float* x, Combine combine) {
  int chunks = (n + kChunk - 1) / kChunk;
  std::vector<Partial> partial(chunks, init);
#pragma omp parallel for schedule(static)
  for (int c = 0; c < chunks; ++c) partial[c] = chunkFn(x, c * kChunk, std::min(n, (c + 1) * kChunk));
  Partial r = init;
  for (const Partial& p : partial) r = combine(r, p);
  return r;
}
double sumChunk(const float* x, int b, int e) {
  double s = 0.0;
  for (int i = b; i < e; ++i) s += x[i];
  return s;
}
float maxChunk(const float* x, int b, int e) {
  float m = -3.0e38f;
  for (int i = b; i < e; ++i) m = std::max(m, x[i]);
  return m;
}
float maxOnCpu(const float* x, int n) {
  return chunkedReduce<float>(n, -3.0e38f, maxChunk, x, [](float a, float b) { return std::max(a, b); });
}
float minChunk(const float* x, int b, int e) {
  float m = 3.0e38f;
  for (int i = b; i < e; ++i) m = std::min(m, x[i]);
  return m;
}
}  // namespace

double reduceSum(Device d, const float* x, int n) {
  countLaunch();
  countHostWait();
  if (d == Device::Cuda) return cuda::reduceSum(x, n);
  return chunkedReduce<double>(n, 0.0, sumChunk, x, [](double a, double b) { return a + b; });
}
float reduceMax(Device d, const float* x, int n) {
  countLaunch();
  countHostWait();
  if (d == Device::Cuda) return cuda::reduceMax(x, n);
  return maxOnCpu(x, n);
}
void reduceMaxInto(Device d, const float* x, int n, float* out) {
  countLaunch();
  if (d == Device::Cuda) return cuda::reduceMaxInto(x, n, out);
  *out = maxOnCpu(x, n);
}
float reduceMin(Device d, const float* x, int n) {
  countLaunch();
  countHostWait();
  if (d == Device::Cuda) return cuda::reduceMin(x, n);
  return chunkedReduce<float>(n, 3.0e38f, minChunk, x, [](float a, float b) { return std::min(a, b); });
}

namespace {
int exclusiveScanCpu(const int* in, int* out, int n) {
  int total = 0;
  for (int i = 0; i < n; ++i) {
    int v = in[i];
    out[i] = total;
    total += v;
  }
  return total;
}
}  // namespace

int exclusiveScan(Device d, const int* in, int* out, int n) {
  countLaunch();
  countHostWait();
  if (d == Device::Cuda) return cuda::exclusiveScan(in, out, n);
  return exclusiveScanCpu(in, out, n);
}

void exclusiveScanAsync(Device d, const int* in, int* out, int n) {
  countLaunch();
  if (d == Device::Cuda) return cuda::exclusiveScanAsync(in, out, n);
  exclusiveScanCpu(in, out, n);
}

void sortPairs(Device d, std::uint32_t* keys, std::uint32_t* values, int n, int keyBits) {
  countLaunch();
  if (d == Device::Cuda) return cuda::sortPairs(keys, values, n, keyBits);
  if (n <= 1) return;
  std::uint32_t mask = keyBits >= 32 ? 0xffffffffu : ((1u << keyBits) - 1u);
  std::vector<std::uint32_t> order(n);
  std::iota(order.begin(), order.end(), 0u);
  std::stable_sort(order.begin(), order.end(),
                   [&](std::uint32_t a, std::uint32_t b) { return (keys[a] & mask) < (keys[b] & mask); });
  std::vector<std::uint32_t> k(n), v(n);
  for (int i = 0; i < n; ++i) {
    k[i] = keys[order[i]];
    v[i] = values[order[i]];
  }
  std::copy(k.begin(), k.end(), keys);
  std::copy(v.begin(), v.end(), values);
}

}  // namespace soak
