#include "Sweep/SweepLaunch.h"

#include <dlfcn.h>
#include <fcntl.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <ctime>
#include <fstream>
#include <sstream>

#include "Base/Error.h"
#include "Checkpoint/Checkpoint.h"
#include "Output/RunFolder.h"

extern char** environ;

namespace soak {

namespace {
void lengthOption(const SweepDescription& d, std::vector<std::string>& argv) {
  if (d.frames >= 0) {
    argv.push_back("--frames");
    argv.push_back(std::to_string(d.frames));
  } else if (d.time >= 0) {
    char t[32];
    std::snprintf(t, sizeof(t), "%.9g", d.time);
    argv.push_back("--time");
    argv.push_back(t);
  }
}

std::string nowText() {
  char b[64];
  const std::time_t t = std::time(nullptr);
  std::strftime(b, sizeof(b), "%Y-%m-%d %H:%M:%S", std::localtime(&t));
  return b;
}
}  // namespace

PointLaunch pointLaunch(const SweepLayout& layout, const SweepDescription& d, const SweepPoint& p,
                        const std::string& soakProgram, int threads) {
  PointLaunch launch;
  const std::string run = layout.runDir(p.id);
  const RunFolderContents contents = inspectRunFolder(run);
  std::vector<std::string>& a = launch.argv;
  a.push_back(soakProgram);
  a.push_back("run");
  if (contents.hasCheckpoint) {
    const CheckpointHeader h = Checkpoint::read(run + "/" + kCheckpointFile).header();
    if (h.frame >= h.plannedFrames) {
      launch.kind = LaunchKind::AlreadyDone;
      launch.argv.clear();
      return launch;
    }
    launch.kind = LaunchKind::Resume;
    a.push_back("--resume");
    a.push_back(run);
  } else {
    launch.kind = contents.exists && !contents.empty() ? LaunchKind::Overwrite : LaunchKind::Fresh;
    a.push_back(layout.pointScene(p.id));
    a.push_back("-o");
    a.push_back(run);
    if (launch.kind == LaunchKind::Overwrite) a.push_back("--overwrite");
    lengthOption(d, a);
    a.push_back("--checkpoint-every");
    a.push_back(std::to_string(d.checkpointEvery));
  }
  a.push_back("--device");
  a.push_back(d.device);
  if (threads > 0) {
    a.push_back("--threads");
    a.push_back(std::to_string(threads));
  }
  a.push_back("--quiet");
  return launch;
}

std::string soakProgramPath(const std::string& given) {
  if (!given.empty()) return given;
  if (const char* env = std::getenv("SOAK_BINARY"); env && *env) return env;
  Dl_info info{};
  if (dladdr(reinterpret_cast<void*>(&soakProgramPath), &info) != 0 && info.dli_fname) {
    const std::string lib = info.dli_fname;
    const std::size_t slash = lib.find_last_of('/');
    if (slash != std::string::npos) {
      const std::string candidate = lib.substr(0, slash) + "/../bin/soak";
      char* real = ::realpath(candidate.c_str(), nullptr);
      if (real) {
        std::string r(real);
        std::free(real);
        if (::access(r.c_str(), X_OK) == 0) return r;
      }
    }
  }
  return "soak";
}

std::string shellCommand(const std::vector<std::string>& argv) {
  std::string line;
  for (const std::string& w : argv) {
    if (!line.empty()) line += " ";
    if (!w.empty() && w.find_first_not_of("abcdefghijklmnopqrstuvwxyzABCDEFGHIJKLMNOPQRSTUVWXYZ0123456789_-./=:,+@%") ==
                          std::string::npos) {
      line += w;
      continue;
    }
    line += "'";
    for (char c : w) line += c == '\'' ? std::string("'\\''") : std::string(1, c);
    line += "'";
  }
  return line;
}

pid_t startChild(const std::vector<std::string>& argv, const std::vector<std::string>& environment,
                 const std::string& logPath) {
  // Everything the child needs is built before fork: between fork and exec
  // it calls only async-signal-safe functions.
  std::vector<char*> args;
  for (const std::string& a : argv) args.push_back(const_cast<char*>(a.c_str()));
  args.push_back(nullptr);
  std::vector<std::string> envText;
  for (char** e = environ; *e; ++e) {
    const std::string entry(*e);
    const std::string name = entry.substr(0, entry.find('='));
    bool replaced = false;
    for (const std::string& add : environment) replaced = replaced || add.substr(0, add.find('=')) == name;
    if (!replaced) envText.push_back(entry);
  }
  for (const std::string& add : environment) envText.push_back(add);
  std::vector<char*> env;
  for (const std::string& e : envText) env.push_back(const_cast<char*>(e.c_str()));
  env.push_back(nullptr);
  const int log = ::open(logPath.c_str(), O_WRONLY | O_CREAT | O_APPEND | O_CLOEXEC, 0644);
  if (log < 0) throw StorageError(logPath, errno, std::strerror(errno));
  const std::string program = argv.at(0);
  const pid_t pid = ::fork();
  if (pid < 0) {
    const int err = errno;
    ::close(log);
    throw std::runtime_error(std::string("cannot start a process: ") + std::strerror(err));
  }
  if (pid == 0) {
    ::setpgid(0, 0);
    ::dup2(log, STDOUT_FILENO);
    ::dup2(log, STDERR_FILENO);
    const int null = ::open("/dev/null", O_RDONLY);
    if (null >= 0) ::dup2(null, STDIN_FILENO);
    if (program.find('/') == std::string::npos) ::execvpe(program.c_str(), args.data(), env.data());
    else ::execve(program.c_str(), args.data(), env.data());
    static const char msg[] = "soak: error: the soak program could not be started (exec failed)\n";
    (void)!::write(STDERR_FILENO, msg, sizeof(msg) - 1);
    ::_exit(127);
  }
  ::close(log);
  return pid;
}

long long fileSize(const std::string& path) {
  struct stat st {};
  return ::stat(path.c_str(), &st) == 0 ? (long long)st.st_size : 0;
}

void logLine(const std::string& logPath, const std::string& line) {
  std::ofstream(logPath, std::ios::app) << line << "\n";
}

PointRecord recordStart(const SweepLayout& layout, const std::string& id, long long pid) {
  PointRecord r = readPointRecord(layout.record(id));
  r.status = "running";
  ++r.attempts;
  r.host = thisHostName();
  r.pid = pid;
  writePointRecord(layout.record(id), r);
  logLine(layout.log(id), "== attempt " + std::to_string(r.attempts) + " on " + r.host + " at " + nowText());
  return r;
}

PointRecord recordEnd(const SweepLayout& layout, const std::string& id, PointRecord r, int waitStatus,
                      double seconds, long long logOffset) {
  r.wallSeconds += seconds;
  r.pid = 0;
  if (WIFEXITED(waitStatus)) r.exitCode = WEXITSTATUS(waitStatus);
  else r.exitCode = 128 + WTERMSIG(waitStatus);
  // Stopped by a signal (Ctrl-C, scancel, preemption, the OOM killer):
  // the point resumes from its checkpoint on the next run.
  const bool stopped = r.exitCode == 130 || (WIFSIGNALED(waitStatus) && (WTERMSIG(waitStatus) == SIGINT ||
                                                                          WTERMSIG(waitStatus) == SIGTERM ||
                                                                          WTERMSIG(waitStatus) == SIGKILL ||
                                                                          WTERMSIG(waitStatus) == SIGHUP));
  r.status = r.exitCode == 0 ? "done" : stopped ? "interrupted" : "failed";
  r.error.clear();
  if (r.exitCode != 0) {
    std::ifstream in(layout.log(id), std::ios::binary);
    in.seekg(logOffset);
    for (std::string line; std::getline(in, line);)
      if (line.rfind("soak:", 0) == 0) r.error = line.substr(line.rfind("soak: error: ", 0) == 0 ? 13 : 6);
    if (!WIFEXITED(waitStatus))
      r.error = "killed by signal " + std::to_string(WTERMSIG(waitStatus)) + (r.error.empty() ? "" : "; " + r.error);
    if (r.error.empty())
      r.error = stopped ? "stopped by a signal; the next sweep run resumes it from its checkpoint"
                        : "exit code " + std::to_string(r.exitCode) + " without a message (see log.txt)";
    if (r.error.size() > 500) r.error = r.error.substr(0, 500) + "...";
  }
  writePointRecord(layout.record(id), r);
  char line[96];
  std::snprintf(line, sizeof(line), "== attempt %d ended: %s, exit code %d, %.1f s", r.attempts, r.status.c_str(),
                r.exitCode, seconds);
  logLine(layout.log(id), line);
  return r;
}

}  // namespace soak
