#pragma once
#include <fstream>
#include <memory>
#include <string>
#include <vector>

#include "Base/Vec3.h"
#include "Output/PvdCollection.h"
#include "Registry/Module.h"

namespace soak {

class Simulation;

// Writes a run's folder:
//   OUT/water.pvd + OUT/water/water_NNNNNN.vtu   water particles
//   OUT/cloth_<name>.pvd + OUT/cloth_<name>/*.vtp  each cloth as a triangle mesh
//   OUT/water_surface.pvd + OUT/water_surface/*.vtp  with <WaterSurface>
//   OUT/stats.csv                                 one row per frame
//   OUT/scene.xml                                 the scene as run
class FrameWriter {
 public:
  // Creates the folder (and fails with InputError if it cannot be written).
  FrameWriter(const std::string& directory, const std::string& sceneText);
  void writeFrame(Simulation& sim, int frame, double stepMs);
  const std::string& directory() const { return dir_; }
  int framesWritten() const { return frames_; }

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
  std::vector<std::string> statsColumns_;
  int frames_ = 0;
};

// Creates a directory and its parents; throws InputError if impossible.
void makeDirectories(const std::string& path);

}  // namespace soak
