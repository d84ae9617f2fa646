#include "Scene/Suggest.h"

#include <algorithm>
#include <cctype>

namespace soak {

int editDistance(const std::string& a, const std::string& b) {
  std::vector<int> prev(b.size() + 1), cur(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) prev[j] = static_cast<int>(j);
  for (std::size_t i = 1; i <= a.size(); ++i) {
    cur[0] = static_cast<int>(i);
    for (std::size_t j = 1; j <= b.size(); ++j) {
      bool same = std::tolower(static_cast<unsigned char>(a[i - 1])) == std::tolower(static_cast<unsigned char>(b[j - 1]));
      cur[j] = std::min({prev[j] + 1, cur[j - 1] + 1, prev[j - 1] + (same ? 0 : 1)});
    }
    std::swap(prev, cur);
  }
  return prev[b.size()];
}

std::vector<std::string> closestNames(const std::string& word, const std::vector<std::string>& names, int count) {
  std::vector<std::pair<int, std::string>> scored;
  for (const std::string& n : names) {
    int d = editDistance(word, n);
    int limit = std::max<int>(2, static_cast<int>(std::max(word.size(), n.size())) / 2);
    if (d <= limit) scored.emplace_back(d, n);
  }
  std::stable_sort(scored.begin(), scored.end(), [](const auto& a, const auto& b) { return a.first < b.first; });
  std::vector<std::string> out;
  for (const auto& s : scored) {
    if (static_cast<int>(out.size()) >= count) break;
    out.push_back(s.second);
  }
  return out;
}

std::string suggestionText(const std::string& word, const std::vector<std::string>& names) {
  std::string s;
  std::vector<std::string> close = closestNames(word, names);
  if (!close.empty()) {
    s += "; did you mean ";
    for (std::size_t i = 0; i < close.size(); ++i) s += (i ? (i + 1 == close.size() ? " or " : ", ") : "") + ("'" + close[i] + "'");
    s += "?";
  }
  s += " (valid: ";
  for (std::size_t i = 0; i < names.size(); ++i) s += (i ? ", " : "") + names[i];
  s += ")";
  return s;
}

}  // namespace soak
