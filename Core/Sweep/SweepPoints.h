#pragma once
// The points of a sweep: every combination of the varying values, times
// the repeats, each with an id that depends only on its values (and its
// repeat), so that planning the same description again, or one with more
// values, finds the same folders.
#include <string>
#include <vector>

#include "Sweep/SweepDescription.h"

namespace soak {

struct SweepPoint {
  std::string id;                   // "p" + 12 hex digits
  int repeat = 0;                   // 0 .. repeats-1
  std::vector<std::string> values;  // one per SweepDescription::parameters, in order
};

// "p" + the first 12 hex digits of FNV-1a 64 over "name=value" lines sorted
// by name, and "repeat=r" when r > 0.
std::string sweepPointId(const std::vector<std::string>& names, const std::vector<std::string>& values, int repeat);

// All points, the first parameter varying slowest, repeats innermost.
std::vector<SweepPoint> sweepPoints(const SweepDescription& d);

// The point's --set overrides: the fixed ones, then its own values.
std::vector<std::string> sweepPointOverrides(const SweepDescription& d, const SweepPoint& p);

// Where a sweep folder keeps its parts.
struct SweepLayout {
  std::string dir;  // the sweep folder
  std::string description() const { return dir + "/sweep.txt"; }
  std::string manifest() const { return dir + "/manifest.csv"; }
  std::string pointDir(const std::string& id) const { return dir + "/points/" + id; }
  std::string pointScene(const std::string& id) const { return pointDir(id) + "/scene.xml"; }
  std::string runDir(const std::string& id) const { return pointDir(id) + "/run"; }
  std::string log(const std::string& id) const { return pointDir(id) + "/log.txt"; }
  std::string record(const std::string& id) const { return pointDir(id) + "/status"; }
  std::string slurmDir() const { return dir + "/slurm"; }
};

}  // namespace soak
