#pragma once
// Running one point of a sweep: the `soak run` command line it needs now,
// the child process that runs it, and its record before and after. Every
// executor (local pool, Slurm task, printed lines) goes through these.
#include <sys/types.h>

#include <string>
#include <vector>

#include "Sweep/SweepFolder.h"

namespace soak {

// How a point's run starts, from what its run folder holds.
enum class LaunchKind {
  Fresh,        // an empty or missing run folder: soak run scene.xml -o run
  Overwrite,    // an earlier run without a checkpoint: soak run ... --overwrite
  Resume,       // a checkpoint short of the end: soak run --resume run
  AlreadyDone,  // a checkpoint at the last frame: nothing to run
};

struct PointLaunch {
  LaunchKind kind = LaunchKind::Fresh;
  std::vector<std::string> argv;  // argv[0] is the soak program; empty for AlreadyDone
};

// `threads` > 0 adds --threads. Reads the checkpoint's header when there is one.
PointLaunch pointLaunch(const SweepLayout& layout, const SweepDescription& d, const SweepPoint& p,
                        const std::string& soakProgram, int threads);

// The soak program the executors start: `given` when not empty, else
// $SOAK_BINARY, else bin/soak beside the core library's lib/ (the build
// tree and an install), else "soak" from the PATH.
std::string soakProgramPath(const std::string& given = {});

// A command line as a POSIX shell reads it (words quoted where needed).
std::string shellCommand(const std::vector<std::string>& argv);

// Starts argv in a process group of its own (a terminal's Ctrl-C reaches
// the executor, which passes it on once), its output appended to `logPath`,
// with `environment` ("NAME=value") added to this process's.
pid_t startChild(const std::vector<std::string>& argv, const std::vector<std::string>& environment,
                 const std::string& logPath);

// The record of a point whose run starts now: running, one more attempt,
// this host and `pid` (the process that waits for the run). Written.
PointRecord recordStart(const SweepLayout& layout, const std::string& id, long long pid);

// The record once the run has ended with `waitStatus` (from waitpid) after
// `seconds`; the error is the last "soak:" line the run printed after
// `logOffset` bytes of the log. Written.
PointRecord recordEnd(const SweepLayout& layout, const std::string& id, PointRecord r, int waitStatus,
                      double seconds, long long logOffset);

// Size of a file (0 when missing): where this attempt's output starts in the log.
long long fileSize(const std::string& path);

// Appends one line to the point's log ("== attempt 2: resume ... on host").
void logLine(const std::string& logPath, const std::string& line);

}  // namespace soak
