// Failures of the machine under a running `soak run` (Output/StorageFailure.h):
// a full disk, a folder removed, a file system turned read-only. Each ends
// with exit code 5 and a message that names the path and the cause, no
// library's text, no temporary file left, the frames listed whole, and the
// command that continues the run where a checkpoint allows it.
//
// The small file systems are tmpfs mounts the tests make themselves (they
// run as root, as the README's test command does); a test that cannot mount
// one fails.
#include <gtest/gtest.h>
#include <signal.h>
#include <sys/mount.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cerrno>
#include <cstring>
#include <filesystem>
#include <string>
#include <vector>

#include "SoakProcess.h"

using namespace soak::test;

namespace {

// A tmpfs of `kilobytes` at a fresh folder, unmounted when this goes.
class SmallFileSystem {
 public:
  SmallFileSystem(const std::string& name, int kilobytes) : path_(freshTempPath(name)) {
    std::filesystem::create_directories(path_);
    const std::string options = "size=" + std::to_string(kilobytes) + "k";
    if (::mount("tmpfs", path_.c_str(), "tmpfs", 0, options.c_str()) != 0)
      error_ = std::string("cannot mount a tmpfs at ") + path_ + ": " + std::strerror(errno) +
               " (the storage tests run as root, as Tests/run-all.sh does)";
  }
  ~SmallFileSystem() {
    if (error_.empty()) ::umount2(path_.c_str(), MNT_DETACH);
  }
  const std::string& error() const { return error_; }
  const std::string& path() const { return path_; }
  bool remount(const std::string& options, unsigned long flags = 0) {
    return ::mount("tmpfs", path_.c_str(), "tmpfs", MS_REMOUNT | flags, options.c_str()) == 0;
  }

 private:
  std::string path_, error_;
};

std::string scene() { return std::string(SOAK_SOURCE_DIR) + "/Scenes/fig7_small.xml"; }

// What every storage failure must leave: exit 5, the cause named, no
// library text, no temporary file, every listed frame whole.
void expectCleanFailure(const SoakResult& r, const std::string& dir, const std::string& cause) {
  EXPECT_EQ(r.code, 5) << r.output;
  EXPECT_NE(r.output.find(cause), std::string::npos) << r.output;
  for (const char* library : {"vtk", "VTK", "ERROR:", "openvdb", "internal error"})
    EXPECT_EQ(r.output.find(library), std::string::npos) << library << " in: " << r.output;
  if (!std::filesystem::exists(dir)) return;
  for (const auto& e : std::filesystem::recursive_directory_iterator(dir))
    EXPECT_NE(e.path().extension(), ".tmp") << e.path() << " left behind";
  for (const std::string& f : pvdFiles(dir + "/water.pvd"))
    EXPECT_NE(readWholeFile(dir + "/" + f).find("</VTKFile>"), std::string::npos) << f << " is listed but not whole";
}

}  // namespace

TEST(StorageFailure, AFullDiskStopsTheRunWithItsCodeAndTheRunResumesOnceThereIsRoom) {
  // fig7's frames are about 50 kB each with its water surface: 1.5 MB holds
  // some frames and a checkpoint, not 40 frames.
  SmallFileSystem fs("storage_full", 1536);
  ASSERT_EQ(fs.error(), "");
  const std::string dir = fs.path() + "/run";
  const SoakResult r = runSoak("run " + scene() + " -o " + dir + " --frames 40 --device cpu --quiet --checkpoint-every 2");
  expectCleanFailure(r, dir, "no space left on the device");
  const std::size_t listed = pvdFiles(dir + "/water.pvd").size();
  ASSERT_GE(listed, 3u) << r.output;  // the frames before the disk filled are kept
  ASSERT_TRUE(pathExists(dir + "/checkpoint.soak")) << r.output;
  EXPECT_NE(r.output.find("soak run --resume " + dir), std::string::npos) << r.output;

  ASSERT_TRUE(fs.remount("size=64m"));
  const SoakResult resumed = runSoak("run --resume " + dir + " --device cpu --quiet");
  EXPECT_EQ(resumed.code, 0) << resumed.output;
  EXPECT_EQ(pvdFiles(dir + "/water.pvd").size(), 41u);
}

TEST(StorageFailure, AFullDiskBeforeAnyCheckpointSaysTheRunCannotBeResumed) {
  SmallFileSystem fs("storage_full_early", 400);
  ASSERT_EQ(fs.error(), "");
  const std::string dir = fs.path() + "/run";
  const SoakResult r = runSoak("run " + scene() + " -o " + dir + " --frames 40 --device cpu --quiet");
  expectCleanFailure(r, dir, "no space left on the device");
  EXPECT_NE(r.output.find("kept no checkpoint"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("--overwrite"), std::string::npos) << r.output;
}

TEST(StorageFailure, AReadOnlyFileSystemIsRefusedBeforeAnythingIsWritten) {
  // (A file system cannot be turned read-only under a run that has files
  // open for writing: the kernel refuses the remount.)
  SmallFileSystem fs("storage_readonly", 1024);
  ASSERT_EQ(fs.error(), "");
  std::filesystem::create_directories(fs.path() + "/old");
  ASSERT_TRUE(fs.remount("size=1m", MS_RDONLY)) << std::strerror(errno);
  for (const std::string& dir : {fs.path() + "/run", fs.path() + "/old"}) {
    const SoakResult r = runSoak("run " + scene() + " -o " + dir + " --frames 2 --device cpu --quiet");
    expectCleanFailure(r, dir, "the file system is read-only");
    EXPECT_NE(r.output.find(dir), std::string::npos) << r.output;
  }
  EXPECT_FALSE(pathExists(fs.path() + "/run"));
}

TEST(StorageFailure, TheOutputFolderRemovedMidRun) {
  const std::string dir = freshTempPath("storage_removed");
  const std::string log = dir + ".log";
  const pid_t pid = fork();
  if (pid == 0) {
    // stderr to a file, to read the message.
    FILE* f = std::freopen(log.c_str(), "w", stderr);
    (void)f;
    execl(SOAK_BINARY, SOAK_BINARY, "run", scene().c_str(), "-o", dir.c_str(), "--frames", "400", "--device", "cpu",
          "--quiet", static_cast<char*>(nullptr));
    _exit(127);
  }
  if (!waitForFile(pid, dir + "/water/water_000003.vtu")) {
    kill(pid, SIGKILL);
    FAIL() << "the run ended before it was met";
  }
  // The run may write a file between remove_all's listing and its last
  // rmdir ("Directory not empty"), as with `rm -rf` from a shell: remove
  // again until the folder is gone.
  std::error_code removeError;
  for (int tries = 0; tries < 50; ++tries) {
    std::filesystem::remove_all(dir, removeError);
    if (!std::filesystem::exists(dir)) break;
  }
  if (std::filesystem::exists(dir)) {
    kill(pid, SIGKILL);
    FAIL() << "cannot remove " << dir << ": " << removeError.message();
  }
  const SoakResult r{exitCodeOf(pid), readWholeFile(log)};
  expectCleanFailure(r, dir, "the folder is gone");
  EXPECT_NE(r.output.find("is gone, and the run with it"), std::string::npos) << r.output;
}
