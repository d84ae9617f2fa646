#pragma once
#include <cstdint>
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "Base/Vec3.h"
#include "Output/PvdCollection.h"
#include "Registry/Module.h"

namespace soak {

class Simulation;
class StateWriter;
class StateReader;

// Writes a run's folder:
//   OUT/water.pvd + OUT/water/water_NNNNNN.vtu   water particles
//   OUT/cloth_<name>.pvd + OUT/cloth_<name>/*.vtp  each cloth as a triangle mesh
//   OUT/water_surface.pvd + OUT/water_surface/*.vtp  with <WaterSurface>
//   OUT/stats.csv                                 one row per frame
//   OUT/scene.xml                                 the scene as run
class FrameWriter {
 public:
  // Fresh: creates the folder (InputError if it cannot be written), writes
  // scene.xml and starts stats.csv. Resume: the folder of an earlier run;
  // nothing is touched until loadState() restores the writer's state.
  enum class Start { Fresh, Resume };
  FrameWriter(const std::string& directory, const std::string& sceneText, Start start = Start::Fresh);
  void writeFrame(Simulation& sim, int frame, double stepMs);
  const std::string& directory() const { return dir_; }
  int framesWritten() const { return frames_; }

  // Checkpoints: the .pvd lists, the stats columns and how much of
  // stats.csv belongs to the saved frames. loadState rewrites the .pvd
  // files and cuts stats.csv back to that length, so frames written after
  // the checkpoint are dropped from both and then written again.
  void saveState(StateWriter& out) const;
  void loadState(StateReader& in);

 private:
  void writeStatsRow(const StatsRow& row);
  void writeCloth(Simulation& sim, int frame);
  void writeWaterSurface(Simulation& sim, int frame, const std::vector<Vec3>& points, const std::vector<float>& mass,
                         const std::vector<float>& radius);
  std::string dir_;
  PvdCollection water_;
  std::vector<std::unique_ptr<PvdCollection>> cloth_;
  std::unique_ptr<PvdCollection> surface_;
  std::ofstream stats_;
  std::uint64_t statsBytes_ = 0;  // length of stats.csv after the last row
  std::vector<std::string> statsColumns_;
  int frames_ = 0;
};

// Creates a directory and its parents; throws InputError if impossible.
void makeDirectories(const std::string& path);

}  // namespace soak
