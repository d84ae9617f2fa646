// soak-run-bench: times whole runs as `soak run` does them, output included
// (issue: a run is as fast as its step). For one scene it runs, each from a
// fresh load:
//   - without output (the step alone),
//   - with output at 1 frame per second,
//   - with output at the scene's frame rate,
// for each output configuration asked for, and prints the wall time of each,
// the ratio to the run without output and to the 1 fps run, the MB written
// and MB per second.
//
//   soak-run-bench SCENE [--device cpu|cuda] [--time T] [--set Element.attr=value ...]
//                  [--configs lz4,zlib,lzma,none,zlib-sync,...]   (default: lz4)
//                  [--out DIR]   (where the runs write; removed after each)
//
// A config is a compressor, optionally with "-sync" (Output.writerThreads=0:
// frames written on the stepping thread).
#include <sys/stat.h>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "Base/Error.h"
#include "Base/MessageText.h"
#include "Output/FrameWriter.h"
#include "Simulation/LoadedScene.h"
#include "Simulation/Runner.h"

using namespace soak;

namespace {

struct Timing {
  double seconds = 0.0, megabytes = 0.0, captureMs = 0.0;
  int frames = 0;
  long long steps = 0;
};

double folderMegabytes(const std::string& dir) {
  double bytes = 0.0;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    if (e.is_regular_file()) bytes += double(e.file_size());
  return bytes / 1e6;
}

// One run from a fresh load; output to `dir` unless it is empty.
Timing timeRun(const std::string& scene, Device device, double time, std::vector<std::string> overrides,
               const std::string& dir) {
  auto loaded = loadScene({scene, "", overrides, {}}, device);
  Simulation& sim = *loaded->sim;
  RunOptions options;
  options.time = time;
  std::filesystem::remove_all(dir);
  std::unique_ptr<FrameWriter> writer;
  const auto t0 = std::chrono::steady_clock::now();
  if (!dir.empty())
    writer = std::make_unique<FrameWriter>(dir, loaded->scene.textAsRun(), FrameWriter::Start::Fresh,
                                           sim.settings.output);
  Runner runner(sim, writer.get());
  const RunProgress p = runner.run(options);
  const double capture = writer ? writer->captureSeconds() : 0.0;
  writer.reset();  // joins the writer threads: every frame is on disk
  synchronize(device);
  Timing t;
  t.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
  t.frames = p.frame + 1;
  t.steps = p.steps;
  t.captureMs = 1e3 * capture / double(t.frames);
  if (!dir.empty()) {
    t.megabytes = folderMegabytes(dir);
    std::filesystem::remove_all(dir);
  }
  return t;
}

std::vector<std::string> split(const std::string& s) {
  std::vector<std::string> parts;
  std::stringstream in(s);
  for (std::string p; std::getline(in, p, ',');)
    if (!p.empty()) parts.push_back(p);
  return parts;
}

}  // namespace

int main(int argc, char** argv) {
  try {
    std::string scene, deviceName = "auto", configs = "lz4", out = "soak-run-bench-out";
    double time = -1.0;
    std::vector<std::string> overrides;
    for (int i = 1; i < argc; ++i) {
      const std::string a = argv[i];
      auto next = [&]() -> std::string {
        if (i + 1 >= argc) throw InputError(a + " needs a value");
        return argv[++i];
      };
      if (a == "--device") deviceName = next();
      else if (a == "--time") time = std::stod(next());
      else if (a == "--set") overrides.push_back(next());
      else if (a == "--configs") configs = next();
      else if (a == "--out") out = next();
      else if (!a.empty() && a[0] == '-') throw InputError("soak-run-bench: unknown option '" + a + "'");
      else scene = a;
    }
    if (scene.empty()) throw InputError("usage: soak-run-bench SCENE [--device D] [--time T] [--configs lz4,...]");
    const Device device = resolveDevice(deviceName);
    std::printf("soak-run-bench: %s on %s%s, %s simulated\n", scene.c_str(), soak::deviceName(device),
                device == Device::Cuda ? (" (" + cudaDeviceDescription() + ")").c_str() : "",
                time >= 0 ? (formatNumber(time) + " s").c_str() : "the scene's duration");
    const Timing bare = timeRun(scene, device, time, overrides, "");
    std::printf("no output: %.3f s wall, %lld steps\n\n", bare.seconds, bare.steps);
    std::printf("| output | frames | wall s | / no output | / 1 fps | MB | MB/s | ms a frame on the stepping thread |\n"
                "|---|---|---|---|---|---|---|---|\n");
    for (const std::string& config : split(configs)) {
      const bool sync = config.size() > 5 && config.substr(config.size() - 5) == "-sync";
      const std::string compressor = sync ? config.substr(0, config.size() - 5) : config;
      std::vector<std::string> o = overrides;
      o.push_back("Output.compression=" + compressor);
      if (sync) o.push_back("Output.writerThreads=0");
      std::vector<std::string> slow = o;
      slow.push_back("Simulation.frameRate=1");
      const Timing oneFps = timeRun(scene, device, time, slow, out);
      const Timing full = timeRun(scene, device, time, o, out);
      for (const auto& [label, t] : {std::pair<std::string, Timing>{config + ", 1 fps", oneFps},
                                     std::pair<std::string, Timing>{config + ", scene fps", full}})
        std::printf("| %s | %d | %.3f | %.3f | %.3f | %.1f | %.1f | %.2f |\n", label.c_str(), t.frames, t.seconds,
                    t.seconds / bare.seconds, t.seconds / oneFps.seconds, t.megabytes, t.megabytes / t.seconds,
                    t.captureMs);
      std::fflush(stdout);
    }
    return 0;
  } catch (const std::exception& e) {
    std::fprintf(stderr, "soak-run-bench: %s\n", e.what());
    return 2;
  }
}
