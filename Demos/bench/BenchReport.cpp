#include "BenchReport.h"

#include <cstdio>
#include <fstream>

#include "Base/Error.h"

namespace soak::bench {

namespace {

std::string countText(double n) {
  char b[32];
  if (n >= 1e6) std::snprintf(b, sizeof b, "%.2fM", n / 1e6);
  else std::snprintf(b, sizeof b, "%.1fk", n / 1e3);
  return b;
}

// One row per stage (in the order first met), one column per case.
void printStageTable(const std::vector<Result>& results, const char* title, const char* format,
                     double StageRow::*field) {
  std::printf("\n%s:\n\n| stage |", title);
  for (const Result& r : results) std::printf(" %s |", r.c.name.c_str());
  std::printf("\n|---|");
  for (std::size_t i = 0; i < results.size(); ++i) std::printf("---|");
  std::printf("\n");
  std::vector<std::string> names;
  for (const Result& r : results)
    for (const StageRow& s : r.stages) {
      bool seen = false;
      for (const std::string& n : names) seen = seen || n == s.name;
      if (!seen) names.push_back(s.name);
    }
  for (const std::string& name : names) {
    std::printf("| %s |", name.c_str());
    for (const Result& r : results) {
      const StageRow* row = nullptr;
      for (const StageRow& s : r.stages)
        if (s.name == name) row = &s;
      if (!row) {
        std::printf(" - |");
      } else {
        std::printf(" ");
        std::printf(format, row->*field);
        std::printf(" |");
      }
    }
    std::printf("\n");
  }
}

}  // namespace

void printTable(const std::vector<Result>& results, const std::string& deviceText, int steps) {
  std::printf("\nsoak-bench on %s, %d timed steps per case after warm-up\n", deviceText.c_str(), steps);
  std::printf("wetting = sum of the wet.* stages (profiled); total = plain step wall time; paper = Table 2, GTX 690\n\n");
  std::printf("| scene | water | cloth | wetting ms | total ms | wetting share | steps/s | particle-steps/s | bytes/particle "
              "| waits/step | paper water | paper total ms | speed-up |\n");
  std::printf("|---|---|---|---|---|---|---|---|---|---|---|---|---|\n");
  for (const Result& r : results) {
    const double n = r.water + r.cloth;
    std::printf("| %s | %s | %s | %.3f | %.3f | %.1f %% | %.0f | %.3g | %.0f | %.2f |", r.c.name.c_str(),
                countText(r.water).c_str(), countText(r.cloth).c_str(), r.wettingMs, r.totalMs,
                r.profiledMs > 0 ? 100.0 * r.wettingMs / r.profiledMs : 0.0, 1000.0 / r.totalMs,
                n * 1000.0 / r.totalMs, r.bytesPerParticle, r.waitsPerStep);
    if (r.c.paperTotalMs > 0)
      std::printf(" %s | %.1f | %.1fx |\n", countText(r.c.paperWater).c_str(), r.c.paperTotalMs,
                  r.c.paperTotalMs / r.totalMs);
    else
      std::printf(" - | - | - |\n");
  }
  std::printf("\nlaunches: operations queued on the device per plain step (launches()); one step at a time from an\n"
              "idle device (median of up to 32): the host's time to queue it, and the step's time to its end\n\n");
  std::printf("| scene | launches/step | graphs/step | graphs instantiated/step | enqueue ms | alone ms | total ms |\n"
              "|---|---|---|---|---|---|---|\n");
  for (const Result& r : results)
    std::printf("| %s | %.1f | %.2f | %.3f | %.3f | %.3f | %.3f |\n", r.c.name.c_str(), r.launchesPerStep,
                r.graphsPerStep, r.instantiationsPerStep, r.enqueueMs, r.aloneMs, r.totalMs);
  std::printf("\ncloth: dependent constraint phases per step, and edge strain after the timed steps (mean and 99th\n"
              "percentile over a sheet's warp and weft edges, a mesh's edges; the largest over the scene's cloths)\n\n");
  std::printf("| scene | cloth phases/step | cloth.solve ms | strain mean %% | strain p99 %% |\n|---|---|---|---|---|\n");
  for (const Result& r : results) {
    double solveMs = 0.0;
    for (const StageRow& s : r.stages)
      if (s.name == "cloth.solve") solveMs = s.ms;
    if (r.cloth > 0)
      std::printf("| %s | %.1f | %.3f | %.3f | %.2f |\n", r.c.name.c_str(), r.clothPhases, solveMs, 100.0 * r.strainMean,
                  100.0 * r.strainP99);
  }
  printStageTable(results, "per-stage ms per step (profiled)", "%.3f", &StageRow::ms);
  printStageTable(results, "per-stage launches per step", "%.1f", &StageRow::launches);
}

void writeJson(const std::string& file, const std::vector<Result>& results, const std::string& deviceText, int steps) {
  std::ofstream o(file);
  if (!o) throw InputError("soak-bench: cannot write '" + file + "'");
  o << "{\n  \"device\": \"" << deviceText << "\",\n  \"timed_steps\": " << steps << ",\n  \"cases\": [\n";
  for (std::size_t i = 0; i < results.size(); ++i) {
    const Result& r = results[i];
    o << "    {\"scene\": \"" << r.c.name << "\", \"water\": " << r.water << ", \"cloth\": " << r.cloth
      << ", \"wetting_ms\": " << r.wettingMs << ", \"total_ms\": " << r.totalMs
      << ", \"profiled_total_ms\": " << r.profiledMs << ", \"steps_per_s\": " << 1000.0 / r.totalMs
      << ", \"particle_steps_per_s\": " << (r.water + r.cloth) * 1000.0 / r.totalMs
      << ", \"bytes_per_particle\": " << r.bytesPerParticle << ", \"host_waits_per_step\": " << r.waitsPerStep
      << ", \"cloth_phases_per_step\": " << r.clothPhases << ", \"strain_mean\": " << r.strainMean << ", \"strain_p99\": " << r.strainP99 << ", \"launches_per_step\": " << r.launchesPerStep << ", \"graphs_per_step\": " << r.graphsPerStep << ", \"graph_instantiations_per_step\": " << r.instantiationsPerStep << ", \"enqueue_ms\": " << r.enqueueMs
      << ", \"alone_ms\": " << r.aloneMs;
    if (r.c.paperTotalMs > 0)
      o << ", \"paper_total_ms\": " << r.c.paperTotalMs << ", \"paper_wetting_ms\": " << r.c.paperWettingMs
        << ", \"speedup\": " << r.c.paperTotalMs / r.totalMs;
    o << ", \"stages\": {";
    for (std::size_t k = 0; k < r.stages.size(); ++k)
      o << (k ? ", " : "") << "\"" << r.stages[k].name << "\": " << r.stages[k].ms;
    o << "}}" << (i + 1 < results.size() ? "," : "") << "\n";
  }
  o << "  ]\n}\n";
}

}  // namespace soak::bench
