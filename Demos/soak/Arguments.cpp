#include "Arguments.h"

#include <cmath>
#include <cstdlib>

#include "Base/Error.h"
#include "Base/MessageText.h"
#include "Output/CatalystSettings.h"
#include "Simulation/Runner.h"

namespace soak::cli {

const char* kUsage =
    "usage: soak <command> [options]\n"
    "\n"
    "commands:\n"
    "  run SCENE.xml [options]   simulate a scene and write ParaView files\n"
    "  run --resume DIR [opts]   continue a run from its last checkpoint (DIR/checkpoint.soak)\n"
    "  sweep plan|run|status|collect   many runs of one scene over ranges of its values, on\n"
    "                            this machine or as Slurm job arrays (soak sweep help)\n"
    "  params                    print every scene element and parameter (Markdown)\n"
    "  version                   print the version and the backends built\n"
    "  help                      this text\n"
    "\n"
    "run options:\n"
    "  -o, --output DIR          output folder (default: soak-out/<scene name>); a new or\n"
    "                            empty one: a run never replaces another unless asked\n"
    "  --overwrite               replace the run already in the output folder (its frames,\n"
    "                            checkpoint and stats are removed first; other files stay)\n"
    "  --device auto|cpu|cuda    where to simulate (default: auto = GPU when present)\n"
    "  --frames N                number of output frames after frame 0\n"
    "  --time T                  simulated seconds (instead of the scene's duration)\n"
    "  --set Element.attr=value  override a scene value (Element[i].attr for repeated elements)\n"
    "  --plugin PATH             load a plugin library (repeatable)\n"
    "  --threads N               CPU threads (default: OMP_NUM_THREADS, else the CPUs this\n"
    "                            process may use: affinity, SLURM_CPUS_PER_TASK, cgroup cpu.max)\n"
    "  --profile                 print mean milliseconds per stage at the end\n"
    "  --quiet                   no progress output\n"
    "  --check-stages            check for NaN and runaway speed after every stage, not once per\n"
    "                            frame (slower; an instability is then reported with its stage)\n"
    "  --checkpoint-every N      write DIR/checkpoint.soak every N frames, after the last frame\n"
    "                            and when interrupted (the latest replaces the one before)\n"
    "  --resume DIR              continue the run in DIR from its checkpoint; --frames or --time\n"
    "                            may extend it; the scene is DIR's scene.xml, unchanged\n"
    "  --catalyst SCRIPT.py      run a ParaView Catalyst script on the frames while the run goes on\n"
    "                            (repeatable; Doc/paraview.md, \"In situ and live\")\n"
    "  --catalyst-every N        run the Catalyst scripts (and Live) on every N-th frame only\n"
    "  --live HOST:PORT          Catalyst Live: send the frames to a ParaView listening on\n"
    "                            Catalyst > Connect (port 22222 by default); its Pause pauses the run\n"
    "\n"
    "exit codes: 0 success, 1 internal error, 2 bad input (nothing written),\n"
    "            3 device unavailable, failed or out of memory, 4 simulation unstable,\n"
    "            5 a write failed (disk full, read-only, folder removed, permission, I/O),\n"
    "            130 interrupted\n";

namespace {
double toNumber(const std::string& opt, const std::string& v) {
  char* end = nullptr;
  double d = std::strtod(v.c_str(), &end);
  if (v.empty() || *end || !std::isfinite(d))
    throw InputError(opt + ": '" + clipForMessage(v) + "' is not a finite number");
  return d;
}
// An integer option in [lo, hi]; the message names the range.
int toInteger(const std::string& opt, const std::string& v, int lo, int hi) {
  const double d = toNumber(opt, v);
  if (d != std::floor(d) || d < lo || d > hi)
    throw InputError(opt + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
  return int(d);
}
}  // namespace

RunArguments parseRunArguments(const std::vector<std::string>& args) {
  RunArguments r;
  for (std::size_t i = 0; i < args.size(); ++i) {
    const std::string& a = args[i];
    auto value = [&]() -> std::string {
      if (i + 1 >= args.size()) throw InputError(a + " needs a value");
      return args[++i];
    };
    if (a == "-o" || a == "--output") {
      r.output = value();
      if (r.output.empty()) throw InputError(a + " needs a folder name, not an empty string");
    }
    else if (a == "--device") r.device = value();
    else if (a == "--frames") r.frames = toInteger(a, value(), 0, kMaxRunFrames);
    else if (a == "--time") {
      r.time = toNumber(a, value());
      if (!(r.time >= 0)) throw InputError("--time must be >= 0");
    } else if (a == "--set") r.overrides.push_back(value());
    else if (a == "--plugin") r.plugins.push_back(value());
    else if (a == "--threads") r.threads = toInteger(a, value(), 1, kMaxThreads);
    else if (a == "--profile") r.profile = true;
    else if (a == "--quiet" || a == "-q") r.quiet = true;
    else if (a == "--check-stages") r.checkStages = true;
    else if (a == "--checkpoint-every") r.checkpointEvery = toInteger(a, value(), 1, kMaxRunFrames);
    else if (a == "--resume") r.resume = value();
    else if (a == "--overwrite") r.overwrite = true;
    else if (a == "--catalyst") r.catalystScripts.push_back(value());
    else if (a == "--catalyst-every") r.catalystEvery = toInteger(a, value(), 1, kMaxRunFrames);
    else if (a == "--live") {
      r.live = value();
      parseLiveAddress(r.live, "--live");
    }
    else if (!a.empty() && a[0] == '-') throw InputError("unknown option '" + a + "' (see soak help)");
    else if (r.scene.empty()) r.scene = a;
    else throw InputError("unexpected argument '" + a + "' (one scene per run)");
  }
  if (!r.resume.empty()) {
    if (!r.scene.empty()) throw InputError("--resume continues DIR's own scene: give no scene file with it");
    if (!r.overrides.empty()) throw InputError("--resume cannot take --set: the resumed run must be the same scene");
    if (!r.output.empty()) throw InputError("--resume writes into DIR itself: give no --output with it");
    if (r.overwrite) throw InputError("--resume continues the run in DIR: it cannot take --overwrite");
  } else if (r.scene.empty()) {
    throw InputError("soak run: no scene file given (usage: soak run SCENE.xml [options])");
  }
  if (r.frames >= 0 && r.time >= 0) throw InputError("give --frames or --time, not both");
  return r;
}

}  // namespace soak::cli
