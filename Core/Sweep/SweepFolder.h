#pragma once
// A sweep folder (Doc/sweeps.md):
//
//   DIR/sweep.txt               the description as planned (ranges written out)
//   DIR/manifest.csv            point, repeat, one column per varying value,
//                               status, exit_code, wall_s, attempts, error
//   DIR/points/ID/scene.xml     the point's scene, its values applied
//   DIR/points/ID/run/          the point's run folder (soak run -o)
//   DIR/points/ID/log.txt       what its runs printed
//   DIR/points/ID/status        its record (SweepRecord.h)
//
// The manifest is rebuilt from sweep.txt and the points' records whenever a
// sweep command looks at the folder; nothing else depends on it.
#include <string>
#include <vector>

#include "Sweep/SweepDescription.h"
#include "Sweep/SweepPoints.h"
#include "Sweep/SweepRecord.h"

namespace soak {

struct SweepState {
  SweepLayout layout;
  SweepDescription description;
  std::vector<SweepPoint> points;
  std::vector<PointRecord> records;  // one per point, liveness checked (sweepRecordNow)
};

struct PlanSummary {
  int points = 0;
  int added = 0;    // folders made by this plan
  int invalid = 0;  // points whose values the scene refuses
};

// Expands `d` into `dir`: each point's folder and scene.xml, the manifest.
// A point whose values the scene refuses is recorded as invalid with the
// message; every point refused is an InputError. Planning again keeps every
// point already there (its run, log and record); a description that runs
// the points differently (another scene, length, device or fixed value)
// is refused while any point has started.
PlanSummary planSweep(const SweepDescription& d, const std::string& dir, const std::vector<std::string>& plugins = {});

// Reads a planned sweep folder. InputError when it is not one.
SweepState loadSweep(const std::string& dir);

// `r` as it stands now: a record that says running while no process holds
// the run folder and its recorded process (on this host) is gone reads as
// interrupted.
PointRecord sweepRecordNow(const SweepLayout& layout, const std::string& id, const PointRecord& r);

// Writes DIR/manifest.csv from `s` (temporary name, then renamed).
void writeManifest(const SweepState& s);

// Counts of each status, "12 done, 3 failed, ..." in a fixed order.
std::string statusCounts(const SweepState& s);

// A CSV field, quoted when it must be (RFC 4180).
std::string csvField(const std::string& s);

}  // namespace soak
