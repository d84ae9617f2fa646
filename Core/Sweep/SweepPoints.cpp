#include "Sweep/SweepPoints.h"

#include <algorithm>
#include <cstdio>

#include "Checkpoint/Checkpoint.h"

namespace soak {

std::string sweepPointId(const std::vector<std::string>& names, const std::vector<std::string>& values, int repeat) {
  std::vector<std::string> lines;
  for (std::size_t i = 0; i < names.size(); ++i) lines.push_back(names[i] + "=" + values.at(i) + "\n");
  std::sort(lines.begin(), lines.end());
  std::string key;
  for (const std::string& l : lines) key += l;
  if (repeat > 0) key += "repeat=" + std::to_string(repeat) + "\n";
  char id[32];
  std::snprintf(id, sizeof(id), "p%012llx", (unsigned long long)(fnv1a64(key.data(), key.size()) >> 16));
  return id;
}

std::vector<SweepPoint> sweepPoints(const SweepDescription& d) {
  std::vector<std::string> names;
  for (const SweepParameter& p : d.parameters) names.push_back(p.name);
  std::vector<SweepPoint> points;
  std::vector<std::size_t> at(d.parameters.size(), 0);  // an odometer over the value lists
  for (;;) {
    std::vector<std::string> values;
    for (std::size_t k = 0; k < at.size(); ++k) values.push_back(d.parameters[k].values[at[k]]);
    for (int r = 0; r < d.repeats; ++r) points.push_back({sweepPointId(names, values, r), r, values});
    std::size_t k = at.size();
    while (k > 0 && ++at[k - 1] == d.parameters[k - 1].values.size()) at[--k] = 0;
    if (k == 0) break;
  }
  return points;
}

std::vector<std::string> sweepPointOverrides(const SweepDescription& d, const SweepPoint& p) {
  std::vector<std::string> o;
  for (const SweepSetting& s : d.fixed) o.push_back(s.name + "=" + s.value);
  for (std::size_t k = 0; k < d.parameters.size(); ++k) o.push_back(d.parameters[k].name + "=" + p.values[k]);
  return o;
}

}  // namespace soak
