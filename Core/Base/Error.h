#pragma once
#include <stdexcept>
#include <string>

namespace soak {

// An error in what the user gave us (scene, mesh, command line). The CLI maps
// it to exit code 2. `where` is "file:line" when known.
class InputError : public std::runtime_error {
 public:
  explicit InputError(const std::string& message, std::string where = {})
      : std::runtime_error(where.empty() ? message : where + ": " + message), where_(std::move(where)) {}
  const std::string& where() const { return where_; }

 private:
  std::string where_;
};

// The machine failed a file the run writes: no space left, a read-only file
// system, a folder removed under the run, permission denied, an I/O error.
// The CLI maps it to exit code 5. `path` is the file, `errnum` the system's
// reason (an errno value).
class StorageError : public std::runtime_error {
 public:
  StorageError(std::string path, int errnum, const std::string& cause)
      : std::runtime_error("cannot write '" + path + "': " + cause), path_(std::move(path)), errnum_(errnum) {}
  const std::string& path() const { return path_; }
  int errnum() const { return errnum_; }

 private:
  std::string path_;
  int errnum_;
};

// A device problem: CUDA asked for but unavailable, a kernel failed, out of memory.
class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace soak
