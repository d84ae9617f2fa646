#include "Sweep/SlurmExecutor.h"

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <set>
#include <sstream>

#include "Base/Error.h"
#include "Sweep/SweepFolder.h"
#include "Sweep/SweepLaunch.h"

namespace soak {

namespace {

struct CommandResult {
  int code = -1;
  std::string output;
};

CommandResult runCommand(const std::vector<std::string>& argv) {
  CommandResult r;
  FILE* p = ::popen((shellCommand(argv) + " 2>&1").c_str(), "r");
  if (!p) return r;
  char buf[512];
  while (std::fgets(buf, sizeof(buf), p)) r.output += buf;
  const int status = ::pclose(p);
  r.code = WIFEXITED(status) ? WEXITSTATUS(status) : -1;
  return r;
}

std::string trimmed(std::string s) {
  while (!s.empty() && (s.back() == '\n' || s.back() == '\r' || s.back() == ' ')) s.pop_back();
  return s;
}

std::string folderName(const std::string& dir) {
  std::string d = dir;
  while (d.size() > 1 && d.back() == '/') d.pop_back();
  return d.substr(d.find_last_of('/') + 1);
}

void writeText(const std::string& path, const std::string& text, std::ios::openmode mode = std::ios::trunc) {
  std::ofstream out(path, std::ios::binary | mode);
  out << text;
  out.flush();
  if (!out) throw StorageError(path, errno, std::strerror(errno));
}

std::vector<std::pair<std::string, std::string>> submissions(const SweepLayout& layout) {
  std::vector<std::pair<std::string, std::string>> list;  // batch number, job id
  std::ifstream in(layout.slurmDir() + "/jobs.txt");
  for (std::string batch, job; in >> batch >> job;) list.emplace_back(batch, job);
  return list;
}

std::vector<std::string> lines(const std::string& path) {
  std::vector<std::string> out;
  std::ifstream in(path);
  for (std::string l; std::getline(in, l);) out.push_back(l);
  return out;
}

}  // namespace

std::string slurmScript(const std::string& dir, const SlurmOptions& o) {
  std::ostringstream s;
  s << "#!/bin/bash\n"
       "# A Soak sweep as a Slurm job array (Doc/sweeps.md). Array task i runs the point on\n"
       "# line i + 1 of the batch file given as the first argument, with `soak sweep task`:\n"
       "# it resumes the point from its checkpoint when there is one (a requeued or\n"
       "# preempted task goes on where it stopped) and records the point's status.\n"
       "#\n"
       "# `soak sweep run DIR --executor slurm` submits it. By hand, on any Slurm cluster\n"
       "# where the sweep folder is on a shared file system:\n"
       "#   cd SWEEP_FOLDER\n"
       "#   sbatch --array=0-$(( $(wc -l < slurm/batch-000.txt) - 1 ))%8 slurm/sweep.sbatch slurm/batch-000.txt\n"
       "# The job runs in the folder it is submitted from (or --chdir); SOAK is the soak\n"
       "# program (sbatch --export=ALL,SOAK=/path/to/soak when it is elsewhere there).\n";
  s << "#SBATCH --job-name=" << (o.jobName.empty() ? "soak-" + folderName(dir) : o.jobName) << "\n";
  s << "#SBATCH --cpus-per-task=" << o.cpusPerTask << "\n";
  if (!o.memory.empty()) s << "#SBATCH --mem=" << o.memory << "\n";
  if (o.gpusPerTask > 0) s << "#SBATCH --gres=gpu:" << o.gpusPerTask << "\n";
  if (!o.timeLimit.empty()) s << "#SBATCH --time=" << o.timeLimit << "\n";
  if (!o.partition.empty()) s << "#SBATCH --partition=" << o.partition << "\n";
  s << "#SBATCH --requeue\n"
       "#SBATCH --open-mode=append\n"
       "#SBATCH --output=slurm/%A_%a.out\n"
       "set -eu\n";
  s << "SOAK=${SOAK:-" << shellCommand({soakProgramPath(o.soakProgram)}) << "}\n";
  s << "[ -x \"$SOAK\" ] || SOAK=$(command -v soak) || {\n"
       "  echo \"soak sweep: no soak program at $SOAK nor on the PATH (sbatch --export=ALL,SOAK=...)\" >&2; exit 2; }\n"
       "batch=${1:?the batch file (slurm/batch-NNN.txt) is the first argument}\n"
       "point=$(sed -n \"$((SLURM_ARRAY_TASK_ID + 1))p\" \"$batch\")\n"
       "[ -n \"$point\" ] || { echo \"soak sweep: $batch has no line $((SLURM_ARRAY_TASK_ID + 1))\" >&2; exit 2; }\n"
       "echo \"soak sweep: task ${SLURM_ARRAY_JOB_ID}_${SLURM_ARRAY_TASK_ID} runs point $point on $(hostname)\"\n"
       "exec \"$SOAK\" sweep task \"$PWD\" \"$point\" --threads \"${SLURM_CPUS_PER_TASK:-1}\"\n";
  return s.str();
}

std::vector<std::string> slurmQueuedPoints(const std::string& dir, const SlurmOptions& options) {
  const SweepLayout layout{dir};
  std::vector<std::string> queued;
  for (const auto& sub : submissions(layout)) {
    const CommandResult r = runCommand({options.squeue, "-h", "-r", "-j", sub.second, "-o", "%K"});
    if (r.code != 0) {
      // A job Slurm has forgotten (finished long ago) is not queued.
      if (r.output.find("Invalid job id") != std::string::npos) continue;
      throw InputError("squeue could not list job " + sub.second + " of this sweep (exit code " +
                       std::to_string(r.code) + "): " + trimmed(r.output));
    }
    const std::vector<std::string> batch = lines(layout.slurmDir() + "/batch-" + sub.first + ".txt");
    std::istringstream in(r.output);
    for (std::string task; in >> task;) {
      const long index = std::strtol(task.c_str(), nullptr, 10);
      if (index >= 0 && std::size_t(index) < batch.size()) queued.push_back(batch[std::size_t(index)]);
    }
  }
  return queued;
}

SlurmSubmission submitSlurmSweep(const std::string& dir, const SlurmOptions& options) {
  SweepState state = loadSweep(dir);
  const SweepLayout& layout = state.layout;
  writeManifest(state);
  SlurmSubmission sub;
  const std::vector<std::string> queuedList = slurmQueuedPoints(dir, options);
  const std::set<std::string> queued(queuedList.begin(), queuedList.end());
  std::string ids;
  for (std::size_t i = 0; i < state.points.size(); ++i) {
    const std::string& id = state.points[i].id;
    if (pointSettled(state.records[i])) continue;
    if (queued.count(id)) {
      ++sub.queued;
      continue;
    }
    ids += id + "\n";
    ++sub.points;
  }
  if (sub.points == 0) return sub;

  ::mkdir(layout.slurmDir().c_str(), 0777);
  writeText(layout.slurmDir() + "/sweep.sbatch", slurmScript(dir, options));
  ::chmod((layout.slurmDir() + "/sweep.sbatch").c_str(), 0755);
  char number[16];
  std::snprintf(number, sizeof(number), "%03d", int(submissions(layout).size()));
  sub.batchFile = layout.slurmDir() + "/batch-" + number + ".txt";
  writeText(sub.batchFile, ids);

  std::string array = "--array=0-" + std::to_string(sub.points - 1);
  if (options.maxRunning > 0) array += "%" + std::to_string(options.maxRunning);
  std::vector<std::string> argv = {options.sbatch, "--parsable", array, "--chdir=" + dir};
  for (const std::string& a : options.sbatchArguments) argv.push_back(a);
  argv.push_back("slurm/sweep.sbatch");
  argv.push_back("slurm/batch-" + std::string(number) + ".txt");
  sub.command = shellCommand(argv);
  const CommandResult r = runCommand(argv);
  const std::string answer = trimmed(r.output);
  const std::string jobId = answer.substr(answer.find_last_of('\n') + 1);
  if (r.code != 0 || jobId.empty() || jobId.find_first_not_of("0123456789;") != std::string::npos)
    throw InputError("sbatch refused the sweep (exit code " + std::to_string(r.code) + "): " + answer +
                     "\n  command: " + sub.command);
  sub.jobId = jobId.substr(0, jobId.find(';'));  // "id;cluster" on a federation
  writeText(layout.slurmDir() + "/jobs.txt", std::string(number) + " " + sub.jobId + "\n", std::ios::app);
  return sub;
}

}  // namespace soak
