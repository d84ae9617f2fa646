#pragma once
// Names that become parts of file names (a cloth's name, collections in a
// checkpoint): letters, digits, '_', '-' and '.', not starting with '.', so
// that no name can name a folder, climb out of the output folder or hide.
#include <cstddef>
#include <string>

namespace soak {

constexpr std::size_t kMaxNameLength = 64;

inline bool isSafeFileName(const std::string& name, std::size_t maxLength = 255) {
  if (name.empty() || name.size() > maxLength || name[0] == '.') return false;
  for (char c : name) {
    const bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_' ||
                    c == '-' || c == '.';
    if (!ok) return false;
  }
  return true;
}

}  // namespace soak
