#pragma once
// A run folder belongs to one run (Doc/reliability.md, "Run folders"):
//  - a new run takes only a folder that does not exist or is empty;
//    over a folder that holds an earlier run it is refused unless asked to
//    overwrite, which removes that run's own files first (frames,
//    checkpoint, stats, scene) so that nothing stale stays beside the new
//    run, and leaves every other file where it is;
//  - while a run (or a resume) writes, it holds an exclusive lock on
//    DIR/.soak.lock, so a second process, or a second run in the same
//    process, is refused at once with the name of the holder. The lock is an
//    open-file-description lock: the kernel drops it when the process ends,
//    however it ends, so a killed run leaves no stale lock behind.
#include <string>
#include <vector>

namespace soak {

// The lock file inside a run folder.
constexpr const char* kRunLockFile = ".soak.lock";

// What a folder holds, sorted into a Soak run's own entries and the rest.
struct RunFolderContents {
  bool exists = false;
  bool isFolder = false;
  std::vector<std::string> runEntries;    // scene.xml, stats.csv, water/, cloth_<name>.pvd, their .tmp files...
  std::vector<std::string> otherEntries;  // anything else (the lock file is neither)
  int framesListed = -1;                  // frames listed in water.pvd; -1 without one
  bool hasCheckpoint = false;
  bool empty() const { return runEntries.empty() && otherEntries.empty(); }
  // One line for a message: "a Soak run (31 frames listed in water.pvd, a
  // checkpoint)", "3 other files (notes.txt, a.png, ...)".
  std::string describe() const;
};

// Whether `name`, an entry directly inside a run folder, is one a run
// writes: the fixed names of outputEntries() (OutputFolder.h), the
// per-cloth "cloth_<name>.pvd", "cloth_<name>/", "cloth_<name>_ply/", and
// a ".tmp" file of any of these left by an interrupted write.
bool isRunEntry(const std::string& name);

RunFolderContents inspectRunFolder(const std::string& folder);

// How a run takes its folder.
enum class FolderClaim {
  Fresh,      // the folder must not exist or be empty
  Overwrite,  // an earlier run's own entries are removed first
  Resume,     // the folder holds the run being continued (its checkpoint is checked elsewhere)
};

// Without writing anything: InputError when `claim` cannot take `folder` as
// it is now (a file there, a folder that holds something for Fresh, a
// missing one for Resume, a folder another run holds). The message says
// what is there and the choices (--resume, --overwrite, another -o).
void checkRunFolderClaim(const std::string& folder, FolderClaim claim);

// Who holds `folder`'s lock now ("process 1234 (soak run ...), since ..."),
// or "" when nobody does. Reads only.
std::string runFolderHolder(const std::string& folder);

// The lock a running run holds on its folder; released when destroyed (or
// by the kernel when the process dies).
class RunFolderLock {
 public:
  RunFolderLock() = default;
  ~RunFolderLock();
  RunFolderLock(RunFolderLock&& other) noexcept;
  RunFolderLock& operator=(RunFolderLock&& other) noexcept;
  RunFolderLock(const RunFolderLock&) = delete;
  RunFolderLock& operator=(const RunFolderLock&) = delete;
  bool held() const { return fd_ >= 0; }
  const std::string& folder() const { return folder_; }

  // Takes the lock on `folder` (which must exist): InputError naming the
  // holder (its process id and command line) when another run holds it.
  static RunFolderLock acquire(const std::string& folder);

 private:
  int fd_ = -1;
  std::string folder_;
};

// Claims `folder` for a run: checks it as checkRunFolderClaim does, creates
// it (and its parents) when it is missing, takes its lock, checks it again
// under the lock (another run may have written it in between) and, for
// Overwrite, removes the earlier run's entries. Throws InputError, leaving
// behind no folder it created, when any of this fails.
RunFolderLock claimRunFolder(const std::string& folder, FolderClaim claim);

}  // namespace soak
