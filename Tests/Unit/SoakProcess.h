#pragma once
// Running the soak program from a test, as a user would: its exit code and
// what it printed; temporary folders; whole files.
#include <gtest/gtest.h>
#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

#include <chrono>
#include <regex>
#include <thread>
#include <vector>

#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

namespace soak::test {

struct SoakResult {
  int code;  // exit code; -1 if killed by a signal
  std::string output;
};

// A shell command's exit code and everything it printed (stdout and stderr).
inline SoakResult runShell(const std::string& command) {
  FILE* p = popen(("(" + command + ") 2>&1").c_str(), "r");
  std::string out;
  char buf[512];
  while (p && fgets(buf, sizeof(buf), p)) out += buf;
  const int status = p ? pclose(p) : -1;
  return {WIFEXITED(status) ? WEXITSTATUS(status) : -1, out};
}

inline SoakResult runSoak(const std::string& args) { return runShell(std::string(SOAK_BINARY) + " " + args); }

// The same under a time limit (SIGKILL after `seconds`) and a memory limit
// (`megabytes` of address space; under AddressSanitizer, whose shadow
// memory needs terabytes of address space, of resident memory instead), so
// that a hang or a memory bomb fails the test instead of the machine. Exit
// code 137 (-1 here) means a limit was hit.
inline SoakResult runSoakLimited(const std::string& args, int seconds, int megabytes) {
#if defined(__SANITIZE_ADDRESS__)
  const bool asan = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
  const bool asan = true;
#else
  const bool asan = false;
#endif
#else
  const bool asan = false;
#endif
  const std::string limit = asan ? "export ASAN_OPTIONS=\"$ASAN_OPTIONS:hard_rss_limit_mb=" + std::to_string(megabytes) + "\"; "
                                 : "ulimit -v " + std::to_string(megabytes * 1024) + "; ";
  return runShell(limit + "exec timeout -s KILL " + std::to_string(seconds) + " " + SOAK_BINARY + " " + args);
}

// A fresh (removed) path under the test temp folder.
inline std::string freshTempPath(const std::string& name) {
  const std::string d = ::testing::TempDir() + "soak_" + name;
  std::system(("rm -rf '" + d + "'").c_str());
  return d;
}

inline bool pathExists(const std::string& path) {
  struct stat st {};
  return stat(path.c_str(), &st) == 0;
}

inline std::string readWholeFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

inline void writeWholeFile(const std::string& path, const std::string& text) {
  std::ofstream(path, std::ios::binary) << text;
}

// The files a .pvd collection lists, in its order.
inline std::vector<std::string> pvdFiles(const std::string& pvdPath) {
  const std::string text = readWholeFile(pvdPath);
  std::vector<std::string> files;
  const std::regex entry("file=\"([^\"]+)\"");
  for (auto it = std::sregex_iterator(text.begin(), text.end(), entry); it != std::sregex_iterator(); ++it)
    files.push_back((*it)[1]);
  return files;
}

// Waits for a child process; its exit code, or -1 if a signal ended it.
inline int exitCodeOf(pid_t pid) {
  int status = 0;
  waitpid(pid, &status, 0);
  return WIFEXITED(status) ? WEXITSTATUS(status) : -1;
}

// Starts soak in the background; returns its pid.
inline pid_t startSoak(const std::vector<std::string>& args) {
  const pid_t pid = fork();
  if (pid == 0) {
    std::vector<char*> argv{const_cast<char*>(SOAK_BINARY)};
    for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
    argv.push_back(nullptr);
    execv(SOAK_BINARY, argv.data());
    _exit(127);
  }
  return pid;
}

// Waits until `path` exists (or the process ends); true if it appeared while running.
inline bool waitForFile(pid_t pid, const std::string& path) {
  for (int i = 0; i < 60000; ++i) {
    if (pathExists(path)) return true;
    int status = 0;
    if (waitpid(pid, &status, WNOHANG) == pid) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(1));
  }
  return false;
}

}  // namespace soak::test
