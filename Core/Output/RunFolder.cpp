#include "Output/RunFolder.h"

#include <fcntl.h>
#include <sys/stat.h>
#include <unistd.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <ctime>
#include <filesystem>
#include <fstream>
#include <iterator>

#include "Base/Error.h"
#include "Output/OutputFolder.h"
#include "Output/StorageFailure.h"

namespace soak {

namespace fs = std::filesystem;

namespace {

bool startsWith(const std::string& s, const std::string& prefix) { return s.compare(0, prefix.size(), prefix) == 0; }
bool endsWith(const std::string& s, const std::string& suffix) {
  return s.size() >= suffix.size() && s.compare(s.size() - suffix.size(), suffix.size(), suffix) == 0;
}

int countFrames(const std::string& pvdPath) {
  std::ifstream in(pvdPath, std::ios::binary);
  if (!in) return -1;
  const std::string text((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  int n = 0;
  for (std::size_t at = text.find("<DataSet"); at != std::string::npos; at = text.find("<DataSet", at + 1)) ++n;
  return n;
}

std::string listSome(const std::vector<std::string>& names, std::size_t most) {
  std::string text;
  for (std::size_t k = 0; k < names.size() && k < most; ++k) text += (k ? ", " : "") + names[k];
  if (names.size() > most) text += ", ...";
  return text;
}

// What a lock's holder wrote into the lock file: its process id, command
// line and start time.
std::string holderText() {
  std::string cmd;
  std::ifstream in("/proc/self/cmdline", std::ios::binary);
  for (char c; in.get(c);) cmd += c == '\0' ? ' ' : c;
  while (!cmd.empty() && cmd.back() == ' ') cmd.pop_back();
  char when[64] = "";
  const std::time_t now = std::time(nullptr);
  std::tm local{};
  if (localtime_r(&now, &local)) std::strftime(when, sizeof(when), "%Y-%m-%d %H:%M:%S", &local);
  return "process " + std::to_string(::getpid()) + " (" + (cmd.empty() ? "?" : cmd) + "), since " + when;
}

std::string readHolder(int fd) {
  std::string text;
  char buf[512];
  for (off_t at = 0;;) {
    const ssize_t n = ::pread(fd, buf, sizeof(buf), at);
    if (n <= 0) break;
    text.append(buf, std::size_t(n));
    at += n;
    if (text.size() > 4096) break;
  }
  while (!text.empty() && (text.back() == '\n' || text.back() == ' ')) text.pop_back();
  return text.empty() ? "another process (it has not yet written its name)" : text;
}

// Where a run takes its folder, a path the user cannot write is theirs to
// fix (exit 2); a full, read-only or failing file system is the machine's
// (StorageError, exit 5).
bool isMachineFailure(int errnum) {
  return errnum == ENOSPC || errnum == EDQUOT || errnum == EROFS || errnum == EIO;
}

// mkdir -p that records the folders it made, outermost first.
std::vector<std::string> makeFolders(const std::string& path) {
  std::vector<std::string> made;
  std::string cur;
  for (std::size_t i = 0; i <= path.size(); ++i) {
    if (i == path.size() || path[i] == '/') {
      if (!cur.empty() && cur != "/") {
        if (::mkdir(cur.c_str(), 0755) == 0) made.push_back(cur);
        else if (errno != EEXIST) {
          const int e = errno;
          for (auto it = made.rbegin(); it != made.rend(); ++it) ::rmdir(it->c_str());
          if (isMachineFailure(e)) throw StorageError(cur, e, storageCause(e));
          throw InputError("cannot create output folder '" + cur + "': " + std::strerror(e));
        }
      }
    }
    if (i < path.size()) cur += path[i];
  }
  return made;
}

std::string busy(const std::string& folder, const std::string& holder) {
  return "the output folder '" + folder + "' is in use by another run: " + holder +
         "; wait for it to end, or choose another folder with -o";
}

std::string refusal(const std::string& folder, const RunFolderContents& c) {
  if (!c.runEntries.empty())
    return "the output folder '" + folder + "' already holds " + c.describe() +
           "; a new run does not replace it unless asked: 'soak run --resume " + folder +
           "' continues it" + (c.hasCheckpoint ? "" : " (it has no checkpoint, so it cannot be resumed)") +
           ", --overwrite replaces it (its frames, checkpoint and stats are removed first; other files stay), "
           "or choose another folder with -o";
  return "the output folder '" + folder + "' is not empty: it holds " + c.describe() +
         "; a run writes into a new or empty folder: choose another with -o, or give --overwrite to write "
         "beside these files (they are left as they are)";
}

}  // namespace

bool isRunEntry(const std::string& name) {
  if (name == kRunLockFile) return false;
  const std::string base = endsWith(name, ".tmp") ? name.substr(0, name.size() - 4) : name;
  for (const std::string& e : outputEntries())
    if (base == e) return true;
  if (startsWith(base, "cloth_") && base.size() > 6) return true;  // .pvd, frames folder, _ply folder
  return false;
}

std::string RunFolderContents::describe() const {
  std::string text;
  if (!runEntries.empty()) {
    const bool whole = std::find(runEntries.begin(), runEntries.end(), "scene.xml") != runEntries.end();
    text = whole ? "a Soak run (" : "parts of a Soak run (";
    if (framesListed >= 0) text += std::to_string(framesListed) + " frames listed in water.pvd";
    else text += listSome(runEntries, 4);
    if (hasCheckpoint) text += ", a checkpoint";
    text += ")";
  }
  if (!otherEntries.empty()) {
    if (!text.empty()) text += " and ";
    text += std::to_string(otherEntries.size()) + (otherEntries.size() == 1 ? " other entry (" : " other entries (") +
            listSome(otherEntries, 4) + ")";
  }
  return text.empty() ? "nothing" : text;
}

RunFolderContents inspectRunFolder(const std::string& folder) {
  RunFolderContents c;
  std::error_code error;
  const fs::file_status st = fs::status(folder, error);
  c.exists = fs::exists(st);
  c.isFolder = fs::is_directory(st);
  if (!c.isFolder) return c;
  for (fs::directory_iterator it(folder, error), end; !error && it != end; it.increment(error)) {
    const std::string name = it->path().filename().string();
    if (name == kRunLockFile) continue;
    (isRunEntry(name) ? c.runEntries : c.otherEntries).push_back(name);
  }
  if (error) throw InputError("cannot read the output folder '" + folder + "': " + error.message());
  std::sort(c.runEntries.begin(), c.runEntries.end());
  std::sort(c.otherEntries.begin(), c.otherEntries.end());
  c.framesListed = countFrames(folder + "/water.pvd");
  c.hasCheckpoint = fs::exists(folder + "/checkpoint.soak", error);
  return c;
}

std::string runFolderHolder(const std::string& folder) {
  const int fd = ::open((folder + "/" + kRunLockFile).c_str(), O_RDONLY | O_CLOEXEC);
  if (fd < 0) return "";
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  std::string holder;
  if (::fcntl(fd, F_OFD_GETLK, &lock) == 0 && lock.l_type != F_UNLCK) holder = readHolder(fd);
  ::close(fd);
  return holder;
}

void checkRunFolderClaim(const std::string& folder, FolderClaim claim) {
  const RunFolderContents c = inspectRunFolder(folder);
  if (c.exists && !c.isFolder)
    throw InputError("the output path '" + folder + "' is a file, not a folder: choose another with -o");
  if (c.isFolder) {
    const std::string holder = runFolderHolder(folder);
    if (!holder.empty()) throw InputError(busy(folder, holder));
  }
  if (claim == FolderClaim::Resume) {
    if (!c.exists) throw InputError("there is no run folder '" + folder + "' to resume");
    return;
  }
  if (claim == FolderClaim::Fresh && !c.empty()) throw InputError(refusal(folder, c));
}

RunFolderLock::~RunFolderLock() {
  if (fd_ >= 0) ::close(fd_);
}

RunFolderLock::RunFolderLock(RunFolderLock&& other) noexcept : fd_(other.fd_), folder_(std::move(other.folder_)) {
  other.fd_ = -1;
}

RunFolderLock& RunFolderLock::operator=(RunFolderLock&& other) noexcept {
  if (this != &other) {
    if (fd_ >= 0) ::close(fd_);
    fd_ = other.fd_;
    folder_ = std::move(other.folder_);
    other.fd_ = -1;
  }
  return *this;
}

RunFolderLock RunFolderLock::acquire(const std::string& folder) {
  const std::string path = folder + "/" + kRunLockFile;
  const int fd = ::open(path.c_str(), O_RDWR | O_CREAT | O_CLOEXEC, 0644);
  if (fd < 0) {
    const int e = errno;
    if (isMachineFailure(e)) throw StorageError(path, e, storageCause(e));
    throw InputError("output folder '" + folder + "' is not writable (" + path + "): " + std::strerror(e));
  }
  struct flock lock {};
  lock.l_type = F_WRLCK;
  lock.l_whence = SEEK_SET;
  // An open-file-description lock: it conflicts with every other open of
  // the file, in this process too, and it goes when the descriptor closes.
  if (::fcntl(fd, F_OFD_SETLK, &lock) != 0) {
    const int e = errno;
    std::string holder = e == EAGAIN || e == EACCES ? readHolder(fd) : std::string();
    ::close(fd);
    if (e == EAGAIN || e == EACCES) throw InputError(busy(folder, holder));
    throw InputError("cannot lock the output folder '" + folder + "': " + std::strerror(e));
  }
  const std::string text = holderText() + "\n";
  if (::ftruncate(fd, 0) != 0 || ::pwrite(fd, text.data(), text.size(), 0) != ssize_t(text.size())) {
    const int e = errno;
    ::close(fd);
    throw storageFailure(path, e);
  }
  RunFolderLock held;
  held.fd_ = fd;
  held.folder_ = folder;
  return held;
}

RunFolderLock claimRunFolder(const std::string& folder, FolderClaim claim) {
  checkRunFolderClaim(folder, claim);
  const std::vector<std::string> made = claim == FolderClaim::Resume ? std::vector<std::string>{} : makeFolders(folder);
  RunFolderLock lock;
  try {
    lock = RunFolderLock::acquire(folder);
    // Again under the lock: another run may have written here since.
    const RunFolderContents c = inspectRunFolder(folder);
    if (claim == FolderClaim::Fresh && !c.empty()) throw InputError(refusal(folder, c));
    if (claim == FolderClaim::Overwrite) {
      // The checkpoint first, then the collections, then the frames: a crash
      // part way leaves no checkpoint pointing at frames that are gone.
      std::vector<std::string> order = c.runEntries;
      auto rank = [](const std::string& n) { return n == "checkpoint.soak" ? 0 : endsWith(n, ".pvd") ? 1 : 2; };
      std::stable_sort(order.begin(), order.end(),
                       [&](const std::string& a, const std::string& b) { return rank(a) < rank(b); });
      for (const std::string& name : order) {
        std::error_code error;
        fs::remove_all(folder + "/" + name, error);
        if (error)
          throw InputError("--overwrite cannot remove '" + folder + "/" + name + "' of the earlier run: " +
                           error.message());
      }
    }
  } catch (...) {
    // Folders this call made go again. The lock file goes only while this
    // call holds its lock: another run that won the race holds it now.
    if (!made.empty()) {
      if (lock.held()) ::unlink((folder + "/" + kRunLockFile).c_str());
      lock = RunFolderLock();
      for (auto it = made.rbegin(); it != made.rend(); ++it) ::rmdir(it->c_str());
    }
    throw;
  }
  return lock;
}

}  // namespace soak
