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

// A device problem: CUDA asked for but unavailable, a kernel failed, out of memory.
class DeviceError : public std::runtime_error {
 public:
  using std::runtime_error::runtime_error;
};

}  // namespace soak
