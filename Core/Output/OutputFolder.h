#pragma once
// The output folder is the run's own: a run refuses one that holds its input
// scene, or where it would write over a file it reads (a mesh, a plugin), so
// that `soak run scene.xml -o .` cannot replace the user's scene.xml with
// the as-run copy.
#include <string>
#include <vector>

namespace soak {

// The fixed names a run writes directly inside its output folder
// (FrameWriter.h); each cloth adds cloth_<name>.pvd, cloth_<name>/ and
// cloth_<name>_ply/ (RunFolder.h's isRunEntry knows both).
std::vector<std::string> outputEntries();

// Throws InputError when `outputFolder` holds `inputFiles[0]` (the scene)
// directly, or when any input file lies at or under an entry a run writes
// there (isRunEntry, RunFolder.h: what --overwrite would remove). Paths are
// compared after resolving links; an output folder that does not exist yet
// is compared as it will be made.
void checkOutputFolder(const std::string& outputFolder, const std::vector<std::string>& inputFiles);

}  // namespace soak
