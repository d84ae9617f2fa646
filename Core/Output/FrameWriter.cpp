#include "Output/FrameWriter.h"

#include <vtkPolyData.h>

#include <algorithm>
#include <chrono>
#include <cmath>

#include "Output/FrameArrays.h"
#include "Output/PlyFiles.h"
#include "Output/VdbFiles.h"
#include "Output/WaterSurface.h"

#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iomanip>
#include <sstream>

#include "Base/Error.h"
#include "Output/StorageFailure.h"
#include "Output/VtkFiles.h"

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

FrameWriter::FrameWriter(const std::string& directory, const std::string& sceneText, Start start,
                         OutputSettings settings)
    : dir_(directory), settings_(settings), water_(directory + "/water.pvd") {
  if (start == Start::Resume) return;
  makeDirectories(dir_ + "/water");
  writeFileAtomically(dir_ + "/scene.xml", sceneText);
  stats_.open(dir_ + "/stats.csv", std::ios::out | std::ios::trunc);
  if (!stats_) throw InputError("cannot write '" + dir_ + "/stats.csv'");
}

FrameWriter::~FrameWriter() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  for (std::thread& t : threads_) t.join();  // each drains the queue before it ends
  queue_.clear();
  downloads_.reset();
}

namespace {
std::string frameName(const std::string& prefix, int frame, const char* ext) {
  char buf[64];
  std::snprintf(buf, sizeof(buf), "%s_%06d.%s", prefix.c_str(), frame, ext);
  return buf;
}
}  // namespace

// The cloth meshes' triangles, the channel names and the surface settings
// do not change during a run: taken once, with the folders they need.
void FrameWriter::captureLayout(const OutputLayout& layout) {
  channelNames_ = layout.channelNames;
  const auto& objects = layout.cloths;
  for (std::size_t k = 0; k < objects.size(); ++k) {
    const ClothObject& obj = objects[k];
    ClothLayout l;
    l.collection = "cloth_" + obj.name;
    l.phase = obj.phase;
    l.firstVertex = obj.firstVertex;
    l.vertexCount = obj.vertexCount;
    l.triangles = obj.localTriangles;
    if (cloth_.size() <= k) {
      makeDirectories(dir_ + "/" + l.collection);
      cloth_.push_back(std::make_unique<PvdCollection>(dir_ + "/" + l.collection + ".pvd"));
    }
    if (settings_.ply) {
      makeDirectories(dir_ + "/" + l.collection + "_ply");
      for (std::size_t c = 0; c < channelNames_.size(); ++c)
        if (channelNames_[c] == settings_.plyColour) l.colourChannel = int(c);
    }
    clothLayout_.push_back(std::move(l));
  }
  if (sink_) sink_->start(layout);
  surfaceOn_ = layout.surfaceCellSize > 0.f;
  splatCellSize_ = layout.surfaceCellSize;
  splatIso_ = layout.surfaceIso;
  restDensity_ = layout.water.restDensity;
  waterSpacing_ = layout.water.spacing;
  particleMass_ = layout.water.particleMass;
  if (settings_.vdb) {
    // The surface mesh's splat where <WaterSurface> sets one; else a cell of
    // 0.7 r0 (the paper's), no finer than 1/31 of the support's diameter so
    // that a particle touches at most 32^3 grid points (WaterSurface's limit).
    if (!surfaceOn_) {
      splatCellSize_ = std::max(0.7f * layout.water.spacing, 2.f * layout.water.supportRadius / 31.f);
      splatIso_ = 0.5f;
    }
    makeDirectories(dir_ + "/water_vdb");
  }
  if (surfaceOn_ && !surface_) {
    makeDirectories(dir_ + "/water_surface");
    surface_ = std::make_unique<PvdCollection>(dir_ + "/water_surface.pvd");
  }
  haveLayout_ = true;
}

void FrameWriter::writeFrame(FrameSource& source, int frame, double stepMs) {
  const auto start = std::chrono::steady_clock::now();
  struct AddTime {
    double& total;
    std::chrono::steady_clock::time_point start;
    ~AddTime() { total += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(); }
  } addTime{captureSeconds_, start};
  if (!haveLayout_) captureLayout(source.outputLayout());
  if (!downloads_) {
    source_ = &source;
    downloads_ = std::make_unique<DownloadQueue>(source.frameDevice());
    writerThreads_ = writerThreadsFor(settings_, source.frameDevice());
  }
  auto c = std::make_unique<Capture>();
  c->frame = frame;
  c->stepMs = stepMs;

  if (writerThreads_ == 0) {  // written here, on the stepping thread
    c->copy = source.startFrameCopy(*downloads_);
    Frame f = receive(*c);
    const Written files = writeFiles(f);
    commit(f, files);
    return;
  }
  {
    // Room in the queue first: the copies below then take host memory only
    // for frames the queue holds.
    std::unique_lock<std::mutex> lock(mutex_);
    if (error_) std::rethrow_exception(error_);
    if (captured_ - committed_ >= settings_.queuedFrames) {
      waitedForDisk_ = true;
      changed_.wait(lock, [&] { return captured_ - committed_ < settings_.queuedFrames || error_; });
      if (error_) std::rethrow_exception(error_);
    }
  }
  // On the stepping thread: the copies are queued, nothing waits for them.
  c->copy = source.startFrameCopy(*downloads_);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    c->sequence = captured_++;
    queue_.push_back(std::move(c));
    while (int(threads_.size()) < writerThreads_) threads_.emplace_back([this] { writerLoop(); });
  }
  changed_.notify_all();
}

// The frame's arrays on the host and its stats row.
FrameWriter::Frame FrameWriter::receive(Capture& c) const {
  Frame f;
  f.frame = c.frame;
  f.data = source_->finishFrameCopy(std::move(c.copy), *downloads_);
  f.stats.add("frame", c.frame);
  f.stats.add("time", f.data.time);
  f.stats.add("step", double(f.data.step));
  const StatsRow simStats = source_->frameStats(f.data);
  for (const auto& col : simStats.values()) f.stats.add(col.first, col.second);
  f.stats.add("step_ms", c.stepMs);
  return f;
}

void FrameWriter::flush() {
  {
    std::unique_lock<std::mutex> lock(mutex_);
    changed_.wait(lock, [&] { return committed_ == captured_; });
    if (error_) std::rethrow_exception(error_);
  }
  if (sink_) sink_->finish();
}

// Each thread takes the oldest queued frame, writes its files, then waits
// for its turn to commit (frames are listed in the order they were taken).
// After an error, frames are still taken in turn but neither written nor
// listed, so flush() returns and reports the error.
void FrameWriter::writerLoop() {
  for (;;) {
    std::unique_ptr<Capture> c;
    bool failed = false;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty()) return;
      c = std::move(queue_.front());
      queue_.pop_front();
      failed = bool(error_);
    }
    Written files;
    Frame f;
    if (!failed) {
      try {
        f = receive(*c);
        files = writeFiles(f);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!error_) error_ = std::current_exception();
        failed = true;
      }
    }
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return committed_ == c->sequence; });
      failed = failed || bool(error_);
    }
    // Only this thread's frame is next: the commit needs no lock.
    if (!failed) {
      try {
        commit(f, files);
      } catch (...) {
        std::lock_guard<std::mutex> lock(mutex_);
        if (!error_) error_ = std::current_exception();
      }
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      ++committed_;
    }
    changed_.notify_all();
  }
}

// The frame's files, each written under a temporary name and renamed.
FrameWriter::Written FrameWriter::writeFiles(const Frame& f) const {
  const FrameData& c = f.data;
  Written w;
  if (testDelaySeconds_ > 0.0) std::this_thread::sleep_for(std::chrono::duration<double>(testDelaySeconds_));
  // Water: sorted by id so frames list particles in a stable order.
  const WaterArrays waterData = waterArrays(c);
  const std::vector<std::size_t>& water = waterData.slots;
  const std::vector<Vec3>& points = waterData.points;
  const PointArray& m = waterData.data[1];
  const PointArray& r = waterData.data[2];
  w.water = "water/" + frameName("water", f.frame, "vtu");
  writeParticlesVtu(dir_ + "/" + w.water, points, waterData.data, settings_.compression);
  // One splat for the surface mesh and the VDB level set.
  WaterSurfaceSettings splatSettings;
  splatSettings.cellSize = splatCellSize_;
  splatSettings.iso = splatIso_;
  RelativeDensityGrid splat;
  if (surfaceOn_ || settings_.vdb) splat = splatRelativeDensity(points, m.values, r.values, restDensity_, splatSettings);
  if (surfaceOn_) {
    w.surface = "water_surface/" + frameName("water_surface", f.frame, "vtp");
    vtkSmartPointer<vtkPolyData> mesh = contourRelativeDensity(splat, splatIso_);
    writePolyDataVtp(dir_ + "/" + w.surface, mesh, settings_.compression);
    if (sink_) {
      mesh->Register(nullptr);
      w.surfaceMesh = std::shared_ptr<vtkPolyData>(mesh.GetPointer(), [](vtkPolyData* p) { p->UnRegister(nullptr); });
    }
  }
  if (settings_.vdb) {
    WaterVdbFrame vdb;
    vdb.position = points;
    vdb.velocity.resize(water.size());
    vdb.id.resize(water.size());
    vdb.pointRadius.resize(water.size());
    for (std::size_t k = 0; k < water.size(); ++k) {
      const std::size_t i = water[k];
      vdb.velocity[k] = c.velocity[i];
      vdb.id[k] = c.id[i];
      // Half the spacing for a full particle; a lighter one (a drip's
      // remainder) draws with the radius of its volume.
      vdb.pointRadius[k] = 0.5f * waterSpacing_ * std::cbrt(std::max(0.f, c.mass[i] / particleMass_));
    }
    vdb.spacing = waterSpacing_;
    writeWaterVdb(dir_ + "/water_vdb/" + frameName("water", f.frame, "vdb"), vdb, splat, splatSettings);
  }
  for (const ClothLayout& obj : clothLayout_) {
    ClothArrays cloth = clothArrays(c, obj.phase, obj.firstVertex, obj.vertexCount, channelNames_);
    std::vector<Vec3>& clothPoints = cloth.points;
    const std::vector<PointArray>& data = cloth.data;
    w.cloth.push_back(obj.collection + "/" + frameName(obj.collection, f.frame, "vtp"));
    writeMeshVtp(dir_ + "/" + w.cloth.back(), clothPoints, obj.triangles, data, settings_.compression);
    if (settings_.ply) {
      ClothPlyFrame ply;
      ply.position = std::move(clothPoints);
      ply.velocity.resize(ply.position.size());
      for (std::size_t i = 0; i < ply.velocity.size(); ++i)
        ply.velocity[i] = Vec3(data[0].values[3 * i], data[0].values[3 * i + 1], data[0].values[3 * i + 2]);
      ply.triangles = obj.triangles;
      ply.channels.assign(data.begin() + 1, data.end());
      ply.colourChannel = obj.colourChannel;
      writeClothPly(dir_ + "/" + obj.collection + "_ply/" + frameName(obj.collection, f.frame, "ply"), ply);
    }
  }
  return w;
}

// Lists the frame, once all its files are on disk, then hands it to the
// sink (which may wait here while its queue is full).
void FrameWriter::commit(Frame& f, const Written& files) {
  const double time = f.data.time;
  water_.add(time, files.water);
  if (surfaceOn_) surface_->add(time, files.surface);
  for (std::size_t k = 0; k < files.cloth.size(); ++k) cloth_[k]->add(time, files.cloth[k]);
  writeStatsRow(f.stats);
  ++frames_;
  if (sink_ && sink_->wants(f.frame)) {
    auto frame = std::make_shared<SinkFrame>();
    frame->frame = f.frame;
    frame->data = std::move(f.data);
    frame->surface = files.surfaceMesh;
    sink_->consume(std::move(frame));
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
  if (!stats_) throw storageFailure(dir_ + "/stats.csv", errno);
  statsBytes_ += bytes.size();
}

}  // namespace soak
