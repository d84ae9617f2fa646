#pragma once
// Temporary files that belong to one test process. ctest runs tests in
// parallel, each in a process of its own: a file with a fixed name would be
// rewritten by one test while another reads it.
#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <string>
#include <vector>

namespace soak::test {

// A path under the test temp folder that no other process uses; the file is
// removed when this process exits.
inline std::string processTempPath(const std::string& name) {
  struct RemovedAtExit {
    std::vector<std::string> paths;
    ~RemovedAtExit() {
      for (const std::string& p : paths) std::remove(p.c_str());
    }
  };
  static RemovedAtExit created;
  std::string path = ::testing::TempDir() + "soak_" + std::to_string(::getpid()) + "_" + name;
  created.paths.push_back(path);
  return path;
}

}  // namespace soak::test
