#include "Sweep/SweepTask.h"

#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <chrono>
#include <csignal>
#include <thread>

#include "Base/Error.h"
#include "Output/RunFolder.h"
#include "Sweep/StopSignals.h"
#include "Sweep/SweepLaunch.h"

namespace soak {

int runSweepTask(const std::string& dir, const std::string& pointId, int threads, const std::string& soakProgram,
                 const std::function<void(const std::string&)>& say) {
  const SweepLayout layout{dir};
  const SweepDescription d = readSweepDescription(layout.description());
  const std::vector<SweepPoint> points = sweepPoints(d);
  const SweepPoint* point = nullptr;
  for (const SweepPoint& p : points)
    if (p.id == pointId) point = &p;
  if (!point) throw InputError("the sweep in " + dir + " has no point '" + pointId + "' (soak sweep status lists them)");

  const PointRecord before = sweepRecordNow(layout, pointId, readPointRecord(layout.record(pointId)));
  if (before.status == "invalid") {
    say(pointId + ": invalid, not run: " + before.error);
    return 2;
  }
  if (before.status == "done") {
    say(pointId + ": already done");
    return 0;
  }
  const std::string holder = runFolderHolder(layout.runDir(pointId));
  if (!holder.empty()) {
    say(pointId + ": already running (" + holder + "); not started again");
    return 0;
  }

  const PointLaunch launch = pointLaunch(layout, d, *point, soakProgramPath(soakProgram), threads);
  if (launch.kind == LaunchKind::AlreadyDone) {
    PointRecord r = before;
    r.status = "done";
    r.exitCode = 0;
    r.error.clear();
    writePointRecord(layout.record(pointId), r);
    say(pointId + ": its run had already reached the end (done)");
    return 0;
  }
  StopSignals stop;
  const PointRecord started = recordStart(layout, pointId, ::getpid());
  logLine(layout.log(pointId), shellCommand(launch.argv));
  const long long offset = fileSize(layout.log(pointId));
  std::vector<std::string> env;
  if (threads > 0) env.push_back("OMP_NUM_THREADS=" + std::to_string(threads));
  const auto start = std::chrono::steady_clock::now();
  const pid_t pid = startChild(launch.argv, env, layout.log(pointId));
  int forwarded = 0, status = 0;
  for (;;) {
    // A signal passed on as SIGINT: the run may have had the scheduler's
    // SIGTERM too, and two different signals still stop it cleanly.
    if (stop.count() > forwarded) {
      ::kill(pid, SIGINT);
      forwarded = stop.count();
    }
    const pid_t got = ::waitpid(pid, &status, WNOHANG);
    if (got == pid) break;
    if (got < 0 && errno != EINTR) {
      status = 1 << 8;
      break;
    }
    std::this_thread::sleep_for(std::chrono::milliseconds(50));
  }
  const double seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  const PointRecord r = recordEnd(layout, pointId, started, status, seconds, offset);
  say(pointId + ": " + r.status + " after " + std::to_string(int(seconds + 0.5)) + " s" +
      (r.error.empty() ? "" : ": " + r.error));
  return r.exitCode;
}

}  // namespace soak
