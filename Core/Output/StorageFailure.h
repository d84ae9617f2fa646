#pragma once
// Turning a failed write into a StorageError (Base/Error.h) that says why in
// the user's terms, whichever library failed: VTK and OpenVDB report a
// failed write without the system's reason, so the reason is found by
// looking at the file's folder and file system.
#include <string>

#include "Base/Error.h"

namespace soak {

// The error for a write of `path` that failed. `errnum` is the system's
// reason where the caller has it (errno after open, write, fsync or rename),
// 0 where it has not: the folder gone (ENOENT), not writable (EACCES,
// EROFS), the file system full (ENOSPC), else EIO. Removes `tmp`, the
// partial file, where given.
StorageError storageFailure(const std::string& path, int errnum, const std::string& tmp = {});

// The user's words for an errno value of a failed write.
std::string storageCause(int errnum);

}  // namespace soak
