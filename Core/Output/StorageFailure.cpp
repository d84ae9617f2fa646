#include "Output/StorageFailure.h"

#include <sys/statvfs.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>

namespace soak {

namespace {
std::string folderOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == std::string::npos ? "." : slash == 0 ? "/" : path.substr(0, slash);
}

// The likeliest reason a write into `path`'s folder failed, from the folder
// and its file system as they are now.
int probedReason(const std::string& path) {
  const std::string folder = folderOf(path);
  if (::access(folder.c_str(), F_OK) != 0) return ENOENT;
  if (::access(folder.c_str(), W_OK) != 0) return errno == EROFS ? EROFS : EACCES;
  struct statvfs fs {};
  if (::statvfs(folder.c_str(), &fs) == 0) {
    if (fs.f_flag & ST_RDONLY) return EROFS;
    if (fs.f_bavail == 0 || (fs.f_files > 0 && fs.f_favail == 0)) return ENOSPC;
  }
  return EIO;
}
}  // namespace

std::string storageCause(int errnum) {
  switch (errnum) {
    case ENOSPC: return "no space left on the device";
    case EDQUOT: return "the disk quota is used up";
    case EROFS: return "the file system is read-only";
    case EACCES:
    case EPERM: return "permission denied";
    case ENOENT: return "the folder is gone (removed while the run wrote?)";
    case EIO: return "an input/output error of the device";
    default: return std::strerror(errnum);
  }
}

StorageError storageFailure(const std::string& path, int errnum, const std::string& tmp) {
  if (!tmp.empty()) std::remove(tmp.c_str());
  if (errnum == 0 || errnum == EIO) errnum = probedReason(path);
  return StorageError(path, errnum, storageCause(errnum));
}

}  // namespace soak
