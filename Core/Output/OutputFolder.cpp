#include "Output/OutputFolder.h"

#include <algorithm>
#include <climits>
#include <cstdlib>
#include <string>
#include <vector>

#include <unistd.h>

#include "Base/Error.h"

namespace soak {

namespace {

// The absolute, link-free form of `path`, which need not exist: the longest
// existing prefix is resolved by realpath and the rest appended with "." and
// ".." folded.
std::string canonicalPath(const std::string& path) {
  std::string absolute = path;
  if (absolute.empty() || absolute[0] != '/') {
    char cwd[PATH_MAX];
    if (!::getcwd(cwd, sizeof(cwd))) return path;
    absolute = std::string(cwd) + "/" + path;
  }
  std::vector<std::string> parts;
  std::string part;
  for (std::size_t i = 0; i <= absolute.size(); ++i) {
    if (i == absolute.size() || absolute[i] == '/') {
      if (part == "..") {
        if (!parts.empty()) parts.pop_back();
      } else if (!part.empty() && part != ".") {
        parts.push_back(part);
      }
      part.clear();
    } else {
      part += absolute[i];
    }
  }
  // Resolve links on the longest prefix that exists.
  std::string resolved = "/";
  std::size_t k = 0;
  for (; k <= parts.size(); ++k) {
    std::string prefix;
    for (std::size_t j = 0; j < parts.size() - k; ++j) prefix += "/" + parts[j];
    if (prefix.empty()) prefix = "/";
    char* real = ::realpath(prefix.c_str(), nullptr);
    if (!real) continue;
    resolved = real;
    std::free(real);
    break;
  }
  for (std::size_t j = parts.size() - std::min(k, parts.size()); j < parts.size(); ++j)
    resolved += (resolved == "/" ? "" : "/") + parts[j];
  return resolved;
}

std::string parentOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == 0 ? "/" : path.substr(0, slash);
}

bool atOrUnder(const std::string& path, const std::string& entry) {
  return path == entry || (path.size() > entry.size() && path.compare(0, entry.size(), entry) == 0 &&
                           path[entry.size()] == '/');
}

}  // namespace

std::vector<std::string> outputEntries(const std::vector<std::string>& clothNames) {
  std::vector<std::string> entries{"scene.xml", "stats.csv", "checkpoint.soak", "water.pvd", "water",
                                   "water_surface.pvd", "water_surface"};
  for (const std::string& name : clothNames) {
    entries.push_back("cloth_" + name + ".pvd");
    entries.push_back("cloth_" + name);
  }
  return entries;
}

void checkOutputFolder(const std::string& outputFolder, const std::vector<std::string>& inputFiles,
                       const std::vector<std::string>& clothNames) {
  const std::string out = canonicalPath(outputFolder);
  const std::vector<std::string> entries = outputEntries(clothNames);
  for (std::size_t k = 0; k < inputFiles.size(); ++k) {
    char* real = ::realpath(inputFiles[k].c_str(), nullptr);
    if (!real) continue;  // not a file on disk (a scene given as text, a resumed run's moved scene)
    const std::string input(real);
    std::free(real);
    if (k == 0 && parentOf(input) == out)
      throw InputError("the output folder '" + outputFolder + "' holds the input scene '" + inputFiles[k] +
                       "'; a run writes its own scene.xml, stats.csv and frames there: choose another folder with -o");
    for (const std::string& e : entries)
      if (atOrUnder(input, out + (out == "/" ? "" : "/") + e))
        throw InputError("writing to the output folder '" + outputFolder + "' would replace '" + inputFiles[k] +
                         "', a file this run reads: choose another folder with -o");
  }
}

}  // namespace soak
