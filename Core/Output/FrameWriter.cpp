#include "Output/FrameWriter.h"

#include <vtkPolyData.h>

#include "Output/WaterSurface.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <sstream>

#include "Base/Error.h"
#include "Output/VtkFiles.h"
#include "Simulation/Simulation.h"

namespace soak {

void makeDirectories(const std::string& path) {
  std::string cur;
  for (std::size_t i = 0; i <= path.size(); ++i) {
    if (i == path.size() || path[i] == '/') {
      if (!cur.empty() && cur != "/" && ::mkdir(cur.c_str(), 0755) != 0 && errno != EEXIST)
        throw InputError("cannot create output folder '" + cur + "': " + std::strerror(errno));
    }
    if (i < path.size()) cur += path[i];
  }
  if (::access(path.c_str(), W_OK) != 0)
    throw InputError("output folder '" + path + "' is not writable: " + std::strerror(errno));
}

FrameWriter::FrameWriter(const std::string& directory, const std::string& sceneText, Start start)
    : dir_(directory), water_(directory + "/water.pvd") {
  if (start == Start::Resume) return;
  makeDirectories(dir_ + "/water");
  writeFileAtomically(dir_ + "/scene.xml", sceneText);
  stats_.open(dir_ + "/stats.csv", std::ios::out | std::ios::trunc);
  if (!stats_) throw InputError("cannot write '" + dir_ + "/stats.csv'");
}

namespace {
std::string frameName(const std::string& prefix, int frame, const char* ext) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%s_%06d.%s", prefix.c_str(), frame, ext);
  return buf;
}
}  // namespace

void FrameWriter::writeWaterSurface(Simulation& sim, int frame, const std::vector<Vec3>& points,
                                    const std::vector<float>& mass, const std::vector<float>& radius) {
  if (!surface_) {
    makeDirectories(dir_ + "/water_surface");
    surface_ = std::make_unique<PvdCollection>(dir_ + "/water_surface.pvd");
  }
  WaterSurfaceSettings s;
  s.cellSize = sim.settings.surfaceCellSize;
  s.iso = sim.settings.surfaceIso;
  vtkSmartPointer<vtkPolyData> surface = buildWaterSurface(points, mass, radius, sim.water.restDensity, s);
  const std::string file = frameName("water_surface", frame, "vtp");
  writePolyDataVtp(dir_ + "/water_surface/" + file, surface);
  surface_->add(sim.time(), "water_surface/" + file);
}

void FrameWriter::writeFrame(Simulation& sim, int frame, double stepMs) {
  ParticleState& ps = sim.particles;
  std::vector<Float4> pos = ps.downloadPositions();
  std::vector<Vec3> vel = ps.downloadVelocities();
  std::vector<float> mass = ps.downloadMasses(), radius = ps.downloadRadii();
  std::vector<int> phase = ps.downloadPhases(), id = ps.downloadIds();

  // Water: sorted by id so frames list particles in a stable order.
  std::vector<std::size_t> water;
  for (std::size_t i = 0; i < phase.size(); ++i)
    if (isWater(phase[i])) water.push_back(i);
  std::sort(water.begin(), water.end(), [&](std::size_t a, std::size_t b) { return id[a] < id[b]; });
  std::vector<Vec3> points(water.size());
  const std::vector<float> density = sim.fluid.downloadDensity(int(phase.size()));
  PointArray v{"velocity", 3, {}}, m{"mass", 1, {}}, r{"radius", 1, {}}, ids{"id", 1, {}}, rho{"density", 1, {}};
  for (std::size_t k = 0; k < water.size(); ++k) {
    std::size_t i = water[k];
    points[k] = pos[i].xyz();
    v.values.insert(v.values.end(), {vel[i].x, vel[i].y, vel[i].z});
    m.values.push_back(mass[i]);
    r.values.push_back(radius[i]);
    ids.values.push_back(static_cast<float>(id[i]));
    rho.values.push_back(density[i]);
  }
  const std::string file = frameName("water", frame, "vtu");
  writeParticlesVtu(dir_ + "/water/" + file, points, {v, m, r, ids, rho});
  water_.add(sim.time(), "water/" + file);
  if (sim.settings.surfaceCellSize > 0.f) writeWaterSurface(sim, frame, points, m.values, r.values);
  writeCloth(sim, frame);

  StatsRow row;
  row.add("frame", frame);
  row.add("time", sim.time());
  row.add("step", double(sim.stepIndex()));
  const StatsRow simStats = sim.collectStats();
  for (const auto& c : simStats.values()) row.add(c.first, c.second);
  row.add("step_ms", stepMs);
  writeStatsRow(row);
  ++frames_;
}

void FrameWriter::writeCloth(Simulation& sim, int frame) {
  const auto& objects = sim.cloth.objects();
  if (objects.empty()) return;
  ParticleState& ps = sim.particles;
  std::vector<Float4> pos = ps.downloadPositions();
  std::vector<Vec3> vel = ps.downloadVelocities();
  std::vector<int> phase = ps.downloadPhases(), id = ps.downloadIds();
  std::vector<std::vector<float>> channels;
  for (int c = 0; c < ps.channelCount(); ++c) channels.push_back(ps.downloadChannel(c));
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const ClothObject& obj = objects[k];
    const std::string name = "cloth_" + obj.name;
    if (cloth_.size() <= k) {
      makeDirectories(dir_ + "/" + name);
      cloth_.push_back(std::make_unique<PvdCollection>(dir_ + "/" + name + ".pvd"));
    }
    std::vector<Vec3> points(obj.vertexCount);
    PointArray v{"velocity", 3, std::vector<float>(3 * obj.vertexCount)};
    std::vector<PointArray> data{v};
    for (int c = 0; c < ps.channelCount(); ++c)
      data.push_back({ps.channelName(c), 1, std::vector<float>(obj.vertexCount)});
    for (std::size_t i = 0; i < phase.size(); ++i) {
      if (phase[i] != obj.phase) continue;
      const int local = id[i] - obj.firstVertex;
      points[local] = pos[i].xyz();
      data[0].values[3 * local] = vel[i].x;
      data[0].values[3 * local + 1] = vel[i].y;
      data[0].values[3 * local + 2] = vel[i].z;
      for (int c = 0; c < ps.channelCount(); ++c) data[c + 1].values[local] = channels[c][i];
    }
    const std::string file = frameName(name, frame, "vtp");
    writeMeshVtp(dir_ + "/" + name + "/" + file, points, obj.localTriangles, data);
    cloth_[k]->add(sim.time(), name + "/" + file);
  }
}

void FrameWriter::writeStatsRow(const StatsRow& row) {
  std::ostringstream text;
  if (statsColumns_.empty()) {
    for (const auto& c : row.values()) statsColumns_.push_back(c.first);
    for (std::size_t i = 0; i < statsColumns_.size(); ++i) text << (i ? "," : "") << statsColumns_[i];
    text << "\n";
  }
  for (std::size_t i = 0; i < row.values().size(); ++i)
    text << (i ? "," : "") << std::setprecision(10) << row.values()[i].second;
  text << "\n";
  const std::string bytes = text.str();
  stats_ << bytes;
  stats_.flush();
  if (!stats_) throw std::runtime_error("cannot write '" + dir_ + "/stats.csv'");
  statsBytes_ += bytes.size();
}

}  // namespace soak
