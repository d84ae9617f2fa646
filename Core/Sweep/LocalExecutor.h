#pragma once
// The local executor: the points that are not done (planned, failed,
// interrupted), N at a time on this machine, each as a `soak run` child.
// One GPU each where there are GPUs (CUDA_VISIBLE_DEVICES), the CPU's cores
// divided between them otherwise (--threads, OMP_NUM_THREADS). SIGINT or
// SIGTERM stops it cleanly: no new point starts, each run under way is
// passed one SIGINT (it finishes its frame, writes its checkpoint and exits
// 130), and the manifest says interrupted; a second signal is passed on too
// and ends the runs at once.
#include <functional>
#include <string>
#include <vector>

namespace soak {

struct LocalRunOptions {
  int jobs = 0;                   // points at once; 0: one per GPU, else one per core
  bool detectGpus = true;         // when `gpus` is empty: CUDA_VISIBLE_DEVICES, else nvidia-smi
  std::vector<std::string> gpus;  // GPU ids to hand out, one per point
  int threads = 0;                // CPU threads per point; 0: the cores divided by jobs
  std::string soakProgram;        // empty: soakProgramPath()
  std::function<void(const std::string&)> say;  // one line per event; null: silent
};

struct SweepRunSummary {
  int points = 0;
  int started = 0;      // runs started (fresh, overwrite or resume)
  int done = 0;         // points done when it ended
  int failed = 0;       // failed or invalid when it ended
  int interrupted = 0;  // not finished because it was stopped
  bool stopped = false; // a signal stopped it
};

SweepRunSummary runLocalSweep(const std::string& dir, const LocalRunOptions& options);

// The exit code of `soak sweep run` for a summary: 0 when every point is
// done, 130 when stopped, 6 when points failed or are invalid.
int sweepExitCode(const SweepRunSummary& s);

// GPUs this process may use: CUDA_VISIBLE_DEVICES when set (an empty
// value, or -1, means none), else one per line of `nvidia-smi -L` in a
// build with the CUDA backend, else none.
std::vector<std::string> visibleGpus();

}  // namespace soak
