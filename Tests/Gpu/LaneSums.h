#pragma once
// Neighbour-style sums over lists, computed with forEachLanes (Base/Lanes.h)
// on either device, for the GPU test that compares the two.
#include <vector>

#include "Backend/Device.h"

namespace soak::test {

struct ListSums {
  std::vector<float> sum;   // per item: sum of its entries' values
  std::vector<int> count;   // per item: entries above the threshold
  std::vector<int> any;     // per item: 1 if any entry is above the threshold
};

// Item i's entries are values[start[i] .. start[i + 1]).
ListSums laneListSums(Device d, const std::vector<int>& start, const std::vector<float>& values, float threshold);

}  // namespace soak::test
