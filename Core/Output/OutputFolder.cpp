#include "Output/OutputFolder.h"

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "Base/Error.h"
#include "Output/RunFolder.h"

namespace soak {

namespace {

// The absolute, link-free form of `path`, which need not exist: the longest
// existing prefix with its links resolved, the rest with "." and ".." folded.
std::string canonicalPath(const std::string& path) {
  std::error_code error;
  const std::filesystem::path p = std::filesystem::weakly_canonical(std::filesystem::absolute(path, error), error);
  if (error) return path;
  std::string text = p.lexically_normal().string();
  while (text.size() > 1 && text.back() == '/') text.pop_back();
  return text;
}

std::string parentOf(const std::string& path) {
  const std::size_t slash = path.find_last_of('/');
  return slash == 0 ? "/" : path.substr(0, slash);
}

}  // namespace

std::vector<std::string> outputEntries() {
  return {"scene.xml", "stats.csv", "checkpoint.soak", "water.pvd", "water", "water_surface.pvd", "water_surface",
          "water_vdb"};
}

void checkOutputFolder(const std::string& outputFolder, const std::vector<std::string>& inputFiles) {
  const std::string out = canonicalPath(outputFolder);
  const std::string prefix = out + (out == "/" ? "" : "/");
  for (std::size_t k = 0; k < inputFiles.size(); ++k) {
    char* real = ::realpath(inputFiles[k].c_str(), nullptr);
    if (!real) continue;  // not a file on disk (a scene given as text, a resumed run's moved scene)
    const std::string input(real);
    std::free(real);
    if (k == 0 && parentOf(input) == out)
      throw InputError("the output folder '" + outputFolder + "' holds the input scene '" + inputFiles[k] +
                       "'; a run writes its own scene.xml, stats.csv and frames there: choose another folder with -o");
    // An input inside the output folder may not lie in an entry a run writes.
    const bool inside = input.size() > prefix.size() && input.compare(0, prefix.size(), prefix) == 0;
    if (inside && isRunEntry(input.substr(prefix.size(), input.find('/', prefix.size()) - prefix.size())))
      throw InputError("writing to the output folder '" + outputFolder + "' would replace '" + inputFiles[k] +
                       "', a file this run reads: choose another folder with -o");
  }
}

}  // namespace soak
