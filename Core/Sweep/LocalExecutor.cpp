#include "Sweep/LocalExecutor.h"

#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <deque>
#include <sstream>
#include <thread>

#include "Backend/Device.h"
#include "Backend/ProcessLimits.h"
#include "Base/Error.h"
#include "Sweep/StopSignals.h"
#include "Sweep/SweepLaunch.h"

namespace soak {

namespace {

using Clock = std::chrono::steady_clock;

struct Running {
  pid_t pid = 0;
  std::size_t index = 0;
  std::string gpu;
  Clock::time_point start;
  long long logOffset = 0;
  PointRecord record;
};

std::string oneDecimal(double v) {
  char b[32];
  std::snprintf(b, sizeof(b), "%.1f", v);
  return b;
}

}  // namespace

std::vector<std::string> visibleGpus() {
  std::vector<std::string> gpus;
  if (const char* env = std::getenv("CUDA_VISIBLE_DEVICES")) {
    std::istringstream in(env);
    for (std::string id; std::getline(in, id, ',');)
      if (!id.empty() && id != "-1") gpus.push_back(id);
    return gpus;
  }
  if (!cudaBackendBuilt()) return gpus;
  FILE* p = ::popen("nvidia-smi -L 2>/dev/null", "r");
  if (!p) return gpus;
  char line[512];
  for (int i = 0; std::fgets(line, sizeof(line), p);)
    if (std::string(line).rfind("GPU ", 0) == 0) gpus.push_back(std::to_string(i++));
  ::pclose(p);
  return gpus;
}

int sweepExitCode(const SweepRunSummary& s) {
  if (s.stopped) return 130;
  return s.done == s.points ? 0 : 6;
}

SweepRunSummary runLocalSweep(const std::string& dir, const LocalRunOptions& options) {
  SweepState state = loadSweep(dir);
  const SweepLayout& layout = state.layout;
  auto say = [&](const std::string& line) {
    if (options.say) options.say(line);
  };
  std::vector<std::string> gpus = options.gpus;
  if (gpus.empty() && options.detectGpus && state.description.device != "cpu") gpus = visibleGpus();
  const int cores = usableCpuCount();
  const int jobs = options.jobs > 0 ? options.jobs : !gpus.empty() ? int(gpus.size()) : cores;
  const int threads = options.threads > 0 ? options.threads : std::max(1, cores / jobs);
  const std::string program = soakProgramPath(options.soakProgram);

  std::deque<std::size_t> pending;
  for (std::size_t i = 0; i < state.points.size(); ++i) {
    const PointRecord& r = state.records[i];
    if (!pointSettled(r) && r.status != "running") pending.push_back(i);
  }
  SweepRunSummary summary;
  summary.points = int(state.points.size());
  say("soak sweep: " + std::to_string(pending.size()) + " of " + std::to_string(state.points.size()) +
      " points to run, " + std::to_string(jobs) + " at a time" +
      (gpus.empty() ? ", " + std::to_string(threads) + " CPU thread(s) each" : ", one GPU each") + " (" +
      statusCounts(state) + ")");

  StopSignals stop;
  int forwarded = 0;
  std::vector<Running> running;
  std::vector<std::string> freeGpus = gpus;
  Clock::time_point lastManifest = Clock::now();
  bool manifestStale = false;
  const std::size_t total = pending.size();
  std::size_t finished = 0;

  while (!running.empty() || (!pending.empty() && stop.count() == 0)) {
    while (stop.count() == 0 && !pending.empty() && int(running.size()) < jobs) {
      const std::size_t index = pending.front();
      pending.pop_front();
      const SweepPoint& p = state.points[index];
      try {
        const PointLaunch launch = pointLaunch(layout, state.description, p, program, threads);
        if (launch.kind == LaunchKind::AlreadyDone) {
          PointRecord r = state.records[index];
          r.status = "done";
          r.exitCode = 0;
          r.error.clear();
          writePointRecord(layout.record(p.id), r);
          state.records[index] = r;
          ++finished;
          say("  " + p.id + ": its run had already reached the end (done)");
          continue;
        }
        Running slot;
        slot.index = index;
        slot.record = recordStart(layout, p.id, ::getpid());
        logLine(layout.log(p.id), shellCommand(launch.argv));
        slot.logOffset = fileSize(layout.log(p.id));
        std::vector<std::string> env = {"OMP_NUM_THREADS=" + std::to_string(threads)};
        if (!freeGpus.empty()) {
          slot.gpu = freeGpus.back();
          freeGpus.pop_back();
          env.push_back("CUDA_VISIBLE_DEVICES=" + slot.gpu);
        }
        slot.start = Clock::now();
        slot.pid = startChild(launch.argv, env, layout.log(p.id));
        state.records[index] = slot.record;
        running.push_back(slot);
        ++summary.started;
        manifestStale = true;
      } catch (const std::exception& e) {
        PointRecord r = readPointRecord(layout.record(p.id));
        r.status = "failed";
        r.exitCode = 1;
        r.error = std::string("could not start its run: ") + e.what();
        writePointRecord(layout.record(p.id), r);
        state.records[index] = r;
        ++finished;
        say("  " + p.id + ": " + r.error);
      }
    }

    // Each signal is passed on once, as SIGINT: a run that got the same
    // signal from elsewhere (a process group, a scheduler) is not ended
    // at once by the copy.
    if (stop.count() > forwarded) {
      if (forwarded == 0)
        say("soak sweep: stopping: no new points; the " + std::to_string(running.size()) +
            " run(s) under way finish their frame and write a checkpoint");
      for (const Running& r : running) ::kill(r.pid, SIGINT);
      forwarded = stop.count();
    }

    bool reaped = false;
    for (std::size_t k = 0; k < running.size();) {
      int status = 0;
      if (::waitpid(running[k].pid, &status, WNOHANG) != running[k].pid) {
        ++k;
        continue;
      }
      Running& r = running[k];
      const SweepPoint& p = state.points[r.index];
      const double seconds = std::chrono::duration<double>(Clock::now() - r.start).count();
      state.records[r.index] = recordEnd(layout, p.id, r.record, status, seconds, r.logOffset);
      const PointRecord& rec = state.records[r.index];
      ++finished;
      say("  [" + std::to_string(finished) + "/" + std::to_string(total) + "] " + p.id + ": " + rec.status + " (" +
          oneDecimal(seconds) + " s" + (rec.error.empty() ? "" : "; " + rec.error) + ")");
      if (!r.gpu.empty()) freeGpus.push_back(r.gpu);
      running.erase(running.begin() + long(k));
      reaped = manifestStale = true;
    }
    if (manifestStale && Clock::now() - lastManifest > std::chrono::seconds(1)) {
      writeManifest(state);
      manifestStale = false;
      lastManifest = Clock::now();
    }
    if (!reaped) std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }

  state = loadSweep(dir);
  writeManifest(state);
  summary.stopped = stop.count() > 0;
  for (const PointRecord& r : state.records) {
    if (r.status == "done") ++summary.done;
    else if (r.status == "failed" || r.status == "invalid") ++summary.failed;
    else if (r.status == "interrupted") ++summary.interrupted;
  }
  say("soak sweep: " + statusCounts(state) + "; manifest " + layout.manifest());
  return summary;
}

}  // namespace soak
