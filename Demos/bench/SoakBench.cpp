// soak-bench: time steps of the paper's Table 2 scenes and of synthetic
// scale scenes (a water block falling on a sheet pinned at four corners,
// about three quarters water, with wetting), and print a table shaped like
// Table 2 plus per-stage times, throughput and device memory per particle.
//
//   soak-bench [--device cpu|cuda] [--scenes DIR] [--only NAME,...] [--scale 100k,1M,...]
//              [--scale-sheet paper|dense]   (the scale scenes' sheet: see scaleCase)
//              [--steps N] [--warmup-steps N] [--json FILE] [--no-table2]
//              [--coupling-lanes N]  (fewest GPU lanes per water particle in coupling)
//              [--set Element.attr=value ...]   (applied to every case, e.g. to compare solver variants)
//
// Each case: the scene is built, advanced by its warm-up (simulated seconds
// for Table 2 scenes, so the jet has emitted its water; steps for the scale
// scenes), then N steps are timed twice: once as a plain run (wall time over
// N steps, device synchronised at the end) and once with per-stage profiling
// (each stage timed on the device between events queued before and after
// it, Pipeline::run; the stages add up to about the plain time). "waits/step": the times the host waited for
// the device (hostWaits()) per plain step, the final synchronisation not
// counted: only maintenance steps wait (Simulation.h), one in 16.
#include <omp.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "Base/Error.h"
#include "Simulation/LoadedScene.h"

using namespace soak;

namespace {

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
  double enqueueMs = 0;        // median host time to queue one step on an idle device
  double aloneMs = 0;          // median time of one step from an idle device to its end
  int clothPhases = 0;         // dependent cloth constraint phases per step
  double strainMean = 0, strainP99 = 0;  // edge strain after the timed steps, largest over the cloths
  std::vector<StageRow> stages;
};

// Table 2 of Shao et al. 2017: water, cloth, wetting ms, total ms per step on a GTX 690.
std::vector<Case> table2Cases(const std::string& dir) {
  struct Row {
    const char* file;
    double warmup, water, cloth, wet, total;
  };
  const Row rows[] = {
      {"fig1_jet", 4.0, 25.1e3, 14.4e3, 5.2, 28.7},        {"fig3a_dry_drop", 0.5, 13.8e3, 14.4e3, 0.0, 21.6},
      {"fig3b_wet_drop", 0.5, 22.4e3, 14.4e3, 4.9, 27.4},  {"fig5b_diffusion_nogravity", 0.5, 50.0e3, 10.0e3, 5.6, 42.5},
      {"fig5c_diffusion_gravity", 0.5, 50.0e3, 10.0e3, 5.7, 42.9}, {"fig6a_emission", 1.5, 11.3e3, 14.4e3, 4.5, 20.2},
      {"fig6b_emission", 1.5, 10.8e3, 14.4e3, 4.3, 19.8},  {"fig7_small", 1.0, 1.9e3, 2.5e3, 1.3, 5.2},
      {"fig9a_ball", 1.0, 85.2e3, 14.4e3, 15.2, 67.8},     {"fig9b_ball_sticky", 1.0, 86.5e3, 14.4e3, 15.8, 68.5},
  };
  std::vector<Case> cases;
  for (const Row& r : rows) {
    Case c;
    c.name = r.file;
    c.scenePath = dir + "/" + r.file + ".xml";
    c.warmupSeconds = r.warmup;
    c.paperWater = r.water;
    c.paperCloth = r.cloth;
    c.paperWettingMs = r.wet;
    c.paperTotalMs = r.total;
    cases.push_back(c);
  }
  return cases;
}

// "100k", "1M", "2.5M" -> particles.
long long parseCount(const std::string& s) {
  char* end = nullptr;
  double v = std::strtod(s.c_str(), &end);
  std::string unit = end ? end : "";
  if (unit == "k" || unit == "K") v *= 1e3;
  else if (unit == "M" || unit == "m") v *= 1e6;
  else if (!unit.empty()) throw InputError("soak-bench: cannot read particle count '" + s + "' (use 100k, 1M, ...)");
  if (!(v >= 1000)) throw InputError("soak-bench: particle count '" + s + "' must be at least 1000");
  return (long long)v;
}

// A water block of about 3/4 n particles (spacing 0.02 m) falls 5 cm onto a
// sheet of about n/4 vertices pinned at four corners.
//
// "paper" sheet (the default): the vertices 1 cm apart, as in the Table 2
// scenes (a 120 x 120 sheet over 1.2 m), so that a cloth particle has as
// many cloth neighbours within h as there: about 50. The water is a slab
// over the middle of the sheet (1/1.3 of its width), as deep as 3/4 n
// particles make it (about 0.4 m at every size).
//
// "dense" sheet (for comparison): the sheet is 1.3
// times the width of a cubic block, so its vertices crowd closer as n grows
// (4.7 mm at 1M, 3.2 mm at 10M) and a cloth particle has about 230 cloth
// neighbours within h: the cloth-cloth passes then cost 4-5 times the
// paper scenes' per particle.
enum class ScaleSheet { Paper, Dense };

Case scaleCase(long long n, int warmupSteps, ScaleSheet sheet) {
  const int verts = std::max(2, int(std::lround(std::sqrt(0.25 * double(n)))));
  const double water = 0.75 * double(n), spacing = 0.02;
  double width, across, depth;  // sheet width; the block's width and depth
  if (sheet == ScaleSheet::Dense) {
    const int side = std::max(2, int(std::lround(std::cbrt(water))));
    across = depth = side * spacing;
    width = 1.3 * across;
  } else {
    width = 0.01 * (verts - 1);
    const int side = std::max(2, int(std::floor(width / 1.3 / spacing)));
    const int layers = std::max(1, int(std::lround(water / (double(side) * side))));
    across = side * spacing;
    depth = layers * spacing;
  }
  std::ostringstream x;
  x << "<Scene>\n"
    << "  <Simulation timeStep='0.015' clothSubsteps='1'/>\n"
    << "  <Water/>\n"
    << "  <Cloth origin='" << -width / 2 << " 1 " << -width / 2 << "' width='" << width << "' height='" << width
    << "' cellsU='" << verts - 1 << "' cellsV='" << verts - 1 << "' pinCorners='u0v0 u1v0 u0v1 u1v1' tetherSlack='0.1'/>\n"
    << "  <WaterBlock min='" << -across / 2 << " 1.05 " << -across / 2 << "' max='" << across / 2 << " "
    << 1.05 + depth << " " << across / 2 << "'/>\n"
    << "  <Plane point='0 0 0' normal='0 1 0'/>\n"
    << "  <WetCloth/>\n"
    << "</Scene>\n";
  Case c;
  std::ostringstream name;
  name << "scale " << (n >= 1000000 ? std::to_string(n / 1000000) + "M" : std::to_string(n / 1000) + "k")
       << (sheet == ScaleSheet::Dense ? " dense" : "");
  c.name = name.str();
  c.scenePath = "<scale " + std::to_string(n) + (sheet == ScaleSheet::Dense ? " dense" : "") + ">";
  c.text = x.str();
  c.warmupSteps = warmupSteps;
  return c;
}

double nowMs() {
  using namespace std::chrono;
  return duration<double, std::milli>(steady_clock::now().time_since_epoch()).count();
}

double median(std::vector<double> v) {
  if (v.empty()) return 0.0;
  std::sort(v.begin(), v.end());
  return v[v.size() / 2];
}

Result runCase(const Case& c, Device device, int steps, const std::vector<std::string>& overrides,
               int couplingLanes) {
  const std::size_t before = deviceBytesInUse(device);
  std::unique_ptr<LoadedScene> loaded = loadScene({c.scenePath, c.text, overrides, {}}, device);
  Simulation& sim = *loaded->sim;
  sim.couplingMinLanes = couplingLanes;
  const double dt = sim.settings.timeStep;
  const int warm = c.warmupSteps + int(std::lround(c.warmupSeconds / dt));
  for (int s = 0; s < warm; ++s) sim.step(false);
  synchronize(device);

  Result r;
  r.c = c;
  // Water counts stay on the device (drips and drains change them): the
  // table gives the mean of the counts before and after the timed steps.
  const int cloth = sim.cloth.empty() ? 0 : sim.cloth.vertexCount();
  const double waterBefore = sim.collectStats().get("water_particles");
  synchronize(device);
  const unsigned long long waitsBefore = hostWaits(), launchesBefore = launches();
  const double t0 = nowMs();
  for (int s = 0; s < steps; ++s) sim.step(false);
  synchronize(device);
  r.totalMs = (nowMs() - t0) / steps;
  r.waitsPerStep = double(hostWaits() - waitsBefore - 1) / steps;
  r.launchesPerStep = double(launches() - launchesBefore) / steps;
  const double waterAfter = sim.collectStats().get("water_particles");

  // One step at a time from an idle device: the host's time to queue it
  // (the call's return) and the step's whole time. Medians, so that the
  // maintenance step among them (which waits) does not count. Where the
  // queueing takes about as long as the step, launches, not the device,
  // set the pace.
  std::vector<double> enqueue, alone;
  for (int s = 0; s < std::min(steps, 32); ++s) {
    synchronize(device);
    const double a = nowMs();
    sim.step(false);
    const double b = nowMs();
    synchronize(device);
    enqueue.push_back(b - a);
    alone.push_back(nowMs() - a);
  }
  r.enqueueMs = median(enqueue);
  r.aloneMs = median(alone);

  sim.pipeline.resetTimings();
  for (int s = 0; s < steps; ++s) sim.step(true);
  for (const StageTiming& t : sim.pipeline.timings()) {
    r.stages.push_back({t.name, t.meanMs(), t.meanLaunches()});
    r.profiledMs += t.meanMs();
    if (t.name.rfind("wet.", 0) == 0) r.wettingMs += t.meanMs();
  }
  r.cloth = cloth;
  r.water = int(std::lround(0.5 * (waterBefore + waterAfter)));
  if (!sim.cloth.empty()) {
    r.clothPhases = sim.cloth.constraintPhasesPerStep(sim.settings.clothIterations, sim.settings.clothSubsteps);
    const ParticleState& ps = sim.particles;
    const std::vector<int> slots = sim.cloth.vertexSlots(ps.downloadIds(), ps.downloadPhases());
    for (const ClothStrain& s : sim.cloth.strain(ps.downloadPositions(), slots)) {
      r.strainMean = std::max(r.strainMean, s.mean);
      r.strainP99 = std::max(r.strainP99, s.p99);
    }
  }
  r.bytesPerParticle = double(deviceBytesInUse(device) - before) / double(std::max(1, sim.particles.count()));
  return r;
}

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
  std::printf("| scene | launches/step | enqueue ms | alone ms | total ms |\n|---|---|---|---|---|\n");
  for (const Result& r : results)
    std::printf("| %s | %.1f | %.3f | %.3f | %.3f |\n", r.c.name.c_str(), r.launchesPerStep, r.enqueueMs, r.aloneMs,
                r.totalMs);
  std::printf("\ncloth: dependent constraint phases per step, and edge strain after the timed steps (mean and 99th\n"
              "percentile over a sheet's warp and weft edges, a mesh's edges; the largest over the scene's cloths)\n\n");
  std::printf("| scene | cloth phases/step | cloth.solve ms | strain mean %% | strain p99 %% |\n|---|---|---|---|---|\n");
  for (const Result& r : results) {
    double solveMs = 0.0;
    for (const StageRow& s : r.stages)
      if (s.name == "cloth.solve") solveMs = s.ms;
    if (r.cloth > 0)
      std::printf("| %s | %d | %.3f | %.3f | %.2f |\n", r.c.name.c_str(), r.clothPhases, solveMs, 100.0 * r.strainMean,
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
      << ", \"cloth_phases_per_step\": " << r.clothPhases << ", \"strain_mean\": " << r.strainMean << ", \"strain_p99\": " << r.strainP99 << ", \"launches_per_step\": " << r.launchesPerStep << ", \"enqueue_ms\": " << r.enqueueMs
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

std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> out;
  std::stringstream in(s);
  for (std::string item; std::getline(in, item, ',');)
    if (!item.empty()) out.push_back(item);
  return out;
}

int usage() {
  std::fprintf(stderr,
               "usage: soak-bench [--device cpu|cuda] [--scenes DIR] [--only NAME,...] [--scale 100k,1M,...]\n"
               "                  [--scale-sheet paper|dense]\n"
               "                  [--steps N] [--warmup-steps N] [--json FILE] [--no-table2]\n"
               "                  [--set Element.attr=value ...] [--coupling-lanes N]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string deviceName = "auto", scenes = "Scenes", json, only, scale;
  ScaleSheet sheet = ScaleSheet::Paper;
  int steps = 50, warmupSteps = 20, couplingLanes = 1;
  bool table2 = true;
  std::vector<std::string> overrides;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    auto next = [&]() -> std::string {
      if (i + 1 >= argc) throw InputError("soak-bench: " + a + " needs a value");
      return argv[++i];
    };
    try {
      if (a == "--device") deviceName = next();
      else if (a == "--scenes") scenes = next();
      else if (a == "--only") only = next();
      else if (a == "--scale") scale = next();
      else if (a == "--scale-sheet") {
        const std::string v = next();
        if (v != "paper" && v != "dense") throw InputError("soak-bench: --scale-sheet takes paper or dense, not '" + v + "'");
        sheet = v == "dense" ? ScaleSheet::Dense : ScaleSheet::Paper;
      }
      else if (a == "--steps") steps = std::stoi(next());
      else if (a == "--warmup-steps") warmupSteps = std::stoi(next());
      else if (a == "--json") json = next();
      else if (a == "--no-table2") table2 = false;
      else if (a == "--set") overrides.push_back(next());
      else if (a == "--coupling-lanes") couplingLanes = std::stoi(next());
      else if (a == "--help" || a == "-h") return usage(), 0;
      else return std::fprintf(stderr, "soak-bench: unknown argument '%s'\n", a.c_str()), usage();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 2;
    }
  }
  try {
    const Device device = resolveDevice(deviceName);
    const std::string deviceText = device == Device::Cuda
                                       ? "cuda (" + cudaDeviceDescription() + ")"
                                       : "cpu (OpenMP, " + std::to_string(omp_get_max_threads()) + " threads)";
    std::vector<Case> cases;
    if (table2) {
      const std::vector<std::string> wanted = splitList(only);
      for (const Case& c : table2Cases(scenes)) {
        bool take = wanted.empty();
        for (const std::string& w : wanted) take = take || w == c.name;
        if (take) cases.push_back(c);
      }
    }
    for (const std::string& s : splitList(scale)) cases.push_back(scaleCase(parseCount(s), warmupSteps, sheet));
    std::vector<Result> results;
    for (const Case& c : cases) {
      std::fprintf(stderr, "soak-bench: %s ...\n", c.name.c_str());
      results.push_back(runCase(c, device, steps, overrides, couplingLanes));
      const Result& r = results.back();
      std::fprintf(stderr, "soak-bench: %s: %d water + %d cloth, %.3f ms per step (wetting %.3f ms)\n",
                   c.name.c_str(), r.water, r.cloth, r.totalMs, r.wettingMs);
    }
    printTable(results, deviceText, steps);
    if (!json.empty()) writeJson(json, results, deviceText, steps);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return 2;
  }
  return 0;
}
