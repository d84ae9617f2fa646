#pragma once
// The Slurm executor: the points that are not done, as one sbatch job
// array. It writes
//
//   DIR/slurm/sweep.sbatch      the job script (resources from the options;
//                               works copied to any cluster that shares DIR)
//   DIR/slurm/batch-NNN.txt     the point ids of one submission, one a line:
//                               array task i runs line i + 1
//   DIR/slurm/jobs.txt          "NNN JOBID" for each submission
//
// and submits `sbatch --array=0-(M-1)%K --chdir=DIR slurm/sweep.sbatch
// slurm/batch-NNN.txt`. Each task runs `soak sweep task DIR ID` (SweepTask.h):
// requeued or preempted, it resumes from the point's checkpoint. Submitting
// again leaves out the points done, invalid, or still queued or running in
// an earlier submission (squeue).
#include <string>
#include <vector>

namespace soak {

struct SlurmOptions {
  int maxRunning = 0;        // %K of --array; 0: no limit
  int cpusPerTask = 1;       // --cpus-per-task (the run's --threads)
  std::string memory;        // --mem per task ("4G"); empty: the cluster's default
  int gpusPerTask = 0;       // --gres=gpu:N
  std::string timeLimit;     // --time ("02:00:00"); empty: the partition's
  std::string partition;     // --partition; empty: the default
  std::string jobName;       // --job-name; empty: soak-<sweep folder name>
  std::vector<std::string> sbatchArguments;  // passed to sbatch as they are
  std::string soakProgram;   // the script's default SOAK; empty: soakProgramPath()
  std::string sbatch = "sbatch";  // the program that submits
  std::string squeue = "squeue";  // the program that lists queued tasks
};

// The job script's text for a sweep in `dir` (absolute).
std::string slurmScript(const std::string& dir, const SlurmOptions& options);

struct SlurmSubmission {
  int points = 0;            // points submitted (0: nothing to do)
  int queued = 0;            // points left out: queued or running already
  std::string jobId;         // sbatch's answer
  std::string batchFile;     // DIR/slurm/batch-NNN.txt
  std::string command;       // the sbatch command line run
};

// Writes the script and the batch file and submits them. InputError when
// sbatch or squeue fails (their message included).
SlurmSubmission submitSlurmSweep(const std::string& dir, const SlurmOptions& options);

// Point ids of the sweep's array tasks that Slurm still has pending or
// running, from DIR/slurm/jobs.txt and squeue.
std::vector<std::string> slurmQueuedPoints(const std::string& dir, const SlurmOptions& options);

}  // namespace soak
