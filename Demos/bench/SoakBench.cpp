// soak-bench: time steps of the paper's Table 2 scenes and of synthetic
// scale scenes (a water block falling on a sheet pinned at four corners,
// about three quarters water, with wetting), and print a table shaped like
// Table 2 plus per-stage times, throughput and device memory per particle.
//
//   soak-bench [--device cpu|cuda] [--scenes DIR] [--only NAME,...] [--scale 100k,1M,...]
//              [--scale-sheet paper|dense]   (the scale scenes' sheet: see scaleCase)
//              [--steps N] [--warmup-steps N] [--json FILE] [--no-table2]
//              [--set Element.attr=value ...]   (applied to every case, e.g. to compare solver variants)
//              [--write-scale-scenes DIR]   (write the --scale scenes as DIR/scale_<n>.xml for
//                                            `soak run`, e.g. whole runs for their strain, and stop)
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
#include "BenchReport.h"
#include "Simulation/LoadedScene.h"

using namespace soak;
using namespace soak::bench;

namespace {

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
    << "  <Simulation timeStep='0.015'/>\n"
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

Result runCase(const Case& c, Device device, int steps, const std::vector<std::string>& overrides) {
  const std::size_t before = deviceBytesInUse(device);
  std::unique_ptr<LoadedScene> loaded = loadScene({c.scenePath, c.text, overrides, {}}, device);
  Simulation& sim = *loaded->sim;
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
  const StepGraphCounters graphsBefore = stepGraphCounters();
  const long long phasesBefore = sim.clothPhasesTaken();
  const double t0 = nowMs();
  for (int s = 0; s < steps; ++s) sim.step(false);
  synchronize(device);
  r.totalMs = (nowMs() - t0) / steps;
  r.waitsPerStep = double(hostWaits() - waitsBefore - 1) / steps;
  r.launchesPerStep = double(launches() - launchesBefore) / steps;
  const StepGraphCounters graphsAfter = stepGraphCounters();
  r.graphsPerStep = double(graphsAfter.launches - graphsBefore.launches) / steps;
  r.instantiationsPerStep = double(graphsAfter.instantiations - graphsBefore.instantiations) / steps;
  const double waterAfter = sim.collectStats().get("water_particles");
  const double phasesPerStep = double(sim.clothPhasesTaken() - phasesBefore) / steps;

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
    r.clothPhases = phasesPerStep;  // the mean: Simulation.clothSubstepTravel makes them vary
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
               "                  [--set Element.attr=value ...] [--write-scale-scenes DIR]\n");
  return 2;
}

}  // namespace

int main(int argc, char** argv) {
  std::string deviceName = "auto", scenes = "Scenes", json, only, scale, writeScenes;
  ScaleSheet sheet = ScaleSheet::Paper;
  int steps = 50, warmupSteps = 20;
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
      else if (a == "--write-scale-scenes") writeScenes = next();
      else if (a == "--help" || a == "-h") return usage(), 0;
      else return std::fprintf(stderr, "soak-bench: unknown argument '%s'\n", a.c_str()), usage();
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 2;
    }
  }
  if (!writeScenes.empty()) {
    // The scale scenes as files: soak-bench times steps, a whole run's
    // per-frame strain needs `soak run`.
    try {
      for (const std::string& s : splitList(scale)) {
        const Case c = scaleCase(parseCount(s), warmupSteps, sheet);
        std::string file = c.name;
        std::replace(file.begin(), file.end(), ' ', '_');
        const std::string path = writeScenes + "/" + file + ".xml";
        std::ofstream out(path);
        out << c.text;
        if (!(out.flush())) throw InputError("soak-bench: cannot write " + path);
        std::printf("%s\n", path.c_str());
      }
    } catch (const std::exception& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return 2;
    }
    return 0;
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
      results.push_back(runCase(c, device, steps, overrides));
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
