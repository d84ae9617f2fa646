#pragma once
// One point of a sweep, run to its end in the foreground: what a Slurm
// array task (and each printed line) executes as `soak sweep task DIR ID`.
// It resumes from the point's checkpoint when there is one, records the
// point's status, passes SIGINT/SIGTERM on to the run once each (so that a
// cancelled or preempted task leaves a checkpoint), and returns the run's
// exit code.
#include <functional>
#include <string>

namespace soak {

// `threads` > 0 is passed to soak run (--threads, OMP_NUM_THREADS).
// `say` gets one line when the point is not run (done, invalid, running
// elsewhere) and one when it ends.
int runSweepTask(const std::string& dir, const std::string& pointId, int threads, const std::string& soakProgram,
                 const std::function<void(const std::string&)>& say);

}  // namespace soak
