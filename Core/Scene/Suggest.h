#pragma once
#include <string>
#include <vector>

namespace soak {

// Edit distance (insertions, deletions, substitutions, case-insensitive).
int editDistance(const std::string& a, const std::string& b);
// Up to `count` names closest to `word`, nearest first, only reasonably close ones.
std::vector<std::string> closestNames(const std::string& word, const std::vector<std::string>& names, int count = 3);
// "; did you mean 'x'?" or "" when nothing is close, plus the list of valid names.
std::string suggestionText(const std::string& word, const std::vector<std::string>& names);

}  // namespace soak
