#include "LaneSums.h"

#include "Backend/Buffer.h"
#include "Backend/ForEach.h"

namespace soak::test {

ListSums laneListSums(Device d, const std::vector<int>& start, const std::vector<float>& values, float threshold) {
  const int n = int(start.size()) - 1;
  Buffer<int> startBuffer(d), countBuffer(d, std::size_t(n)), anyBuffer(d, std::size_t(n));
  Buffer<float> valueBuffer(d), sumBuffer(d, std::size_t(n));
  startBuffer.upload(start);
  valueBuffer.upload(values);
  const int* s = startBuffer.data();
  const float* v = valueBuffer.data();
  float* sum = sumBuffer.data();
  int* count = countBuffer.data();
  int* any = anyBuffer.data();
  forEachLanes(d, n, SOAK_LAMBDA(int i, Lanes lanes) {
    float total = 0.f;
    int above = 0;
    for (int k = s[i] + lanes.index; k < s[i + 1]; k += lanes.size) {
      total += v[k];
      above += v[k] > threshold ? 1 : 0;
    }
    total = laneSum(lanes, total);
    above = laneSum(lanes, above);
    const bool found = laneAny(lanes, above > 0);
    if (!lanes.leader()) return;
    sum[i] = total;
    count[i] = above;
    any[i] = found ? 1 : 0;
  }, "test.laneListSums");
  return {sumBuffer.download(), countBuffer.download(), anyBuffer.download()};
}

}  // namespace soak::test
