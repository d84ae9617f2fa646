#pragma once
// soak-bench's cases and results, and the tables and JSON it prints them as.
#include <string>
#include <vector>

namespace soak::bench {

struct Case {
  std::string name;       // row name
  std::string scenePath;  // file, or empty for a synthetic scene
  std::string text;       // synthetic scene XML
  double warmupSeconds = 0.0;
  int warmupSteps = 0;
  double paperWater = 0, paperCloth = 0, paperWettingMs = -1, paperTotalMs = -1;  // Table 2 (GTX 690)
};

struct StageRow {
  std::string name;
  double ms;
  double launches;  // per step
};

struct Result {
  Case c;
  int water = 0, cloth = 0;
  double totalMs = 0, profiledMs = 0, wettingMs = 0;
  double bytesPerParticle = 0;
  double waitsPerStep = 0;  // host waits for the device (hostWaits()) per plain step
  double launchesPerStep = 0;  // operations queued on the device (launches()) per plain step
  double graphsPerStep = 0;    // CUDA graphs launched per plain step (Simulation.cudaGraph)
  double instantiationsPerStep = 0;  // of them instantiated anew (not updated in place)
  double enqueueMs = 0;        // median host time to queue one step on an idle device
  double aloneMs = 0;          // median time of one step from an idle device to its end
  double clothPhases = 0;      // dependent cloth constraint phases per step (mean over the timed steps)
  double strainMean = 0, strainP99 = 0;  // edge strain after the timed steps, largest over the cloths
  std::vector<StageRow> stages;
};

// The Table 2 table, the launch table, the cloth table and the per-stage
// tables, as Markdown on stdout.
void printTable(const std::vector<Result>& results, const std::string& deviceText, int steps);
// The same numbers as JSON.
void writeJson(const std::string& file, const std::vector<Result>& results, const std::string& deviceText, int steps);

}  // namespace soak::bench
