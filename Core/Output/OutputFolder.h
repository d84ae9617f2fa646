#pragma once
// The output folder is the run's own: a run refuses one that holds its input
// scene, or where it would write over a file it reads (a mesh, a plugin), so
// that `soak run scene.xml -o .` cannot replace the user's scene.xml with
// the as-run copy.
#include <string>
#include <vector>

namespace soak {

// The files and folders a run writes directly inside its output folder
// (FrameWriter.h), given the names of its cloth objects.
std::vector<std::string> outputEntries(const std::vector<std::string>& clothNames);

// Throws InputError when `outputFolder` holds `inputFiles[0]` (the scene)
// directly, or when any input file lies at or under one of the entries of
// outputEntries(clothNames) there, or under any entry that a run writes
// (isRunEntry, RunFolder.h), which --overwrite would remove. Paths are compared after resolving links;
// an output folder that does not exist yet is compared as it will be made.
void checkOutputFolder(const std::string& outputFolder, const std::vector<std::string>& inputFiles,
                       const std::vector<std::string>& clothNames);

}  // namespace soak
