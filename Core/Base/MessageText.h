#pragma once
// How error messages show what the user gave: values cut so that a message
// never echoes a megabyte back, numbers in six significant digits.
#include <cstddef>
#include <cstdio>
#include <string>

namespace soak {

constexpr std::size_t kShownCharacters = 60;

// `raw` as a message shows it: cut after kShownCharacters, saying how long it was.
inline std::string clipForMessage(const std::string& raw) {
  if (raw.size() <= kShownCharacters) return raw;
  return raw.substr(0, kShownCharacters) + "... (" + std::to_string(raw.size()) + " characters)";
}

// A number as messages and docs print it ("%g": 0.04, 1e-05, 100000).
inline std::string formatNumber(double v) {
  char b[32];
  std::snprintf(b, sizeof(b), "%g", v);
  return b;
}

}  // namespace soak
