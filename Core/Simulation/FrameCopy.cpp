#include "Simulation/FrameCopy.h"

#include <algorithm>
#include <cstring>

#include "Simulation/Simulation.h"

namespace soak {

namespace {
template <class T>
DownloadQueue::Part part(const T* device, int count) {
  return {device, std::size_t(count) * sizeof(T)};
}
template <class T>
std::vector<T> unpack(const DownloadQueue::Transfer& t, std::size_t k, std::size_t count) {
  std::vector<T> out(count, T{});
  const std::size_t bytes = std::min(t.partBytes(k), count * sizeof(T));
  if (bytes > 0) std::memcpy(static_cast<void*>(out.data()), t.part(k), bytes);
  return out;
}
}  // namespace

FrameCopy startFrameCopy(Simulation& sim, DownloadQueue& queue) {
  FrameCopy c;
  c.scalars.step = sim.stepIndex();
  c.scalars.time = sim.time();
  c.scalars.drainedWaterMass = sim.drainedWaterMass;
  c.scalars.emittedWaterMass = sim.emittedWaterMass;
  ParticleState& ps = sim.particles;
  const ParticleView p = ps.view();
  c.count = p.count;
  c.densitySlots = int(std::min<std::size_t>(sim.fluid.densitySlots(), std::size_t(p.count)));
  c.channels = ps.channelCount();
  std::vector<DownloadQueue::Part> parts{part(p.position, p.count), part(p.velocity, p.count),
                                         part(p.mass, p.count),     part(p.radius, p.count),
                                         part(p.phase, p.count),    part(p.id, p.count),
                                         part(sim.fluid.density(), c.densitySlots),
                                         part(sim.clothSubstepCount(), 1)};
  // Compression at step 0 is not measured (stats show 0), as no solve has run.
  const float* compression = sim.stepIndex() > 0 ? sim.fluid.compressionPerParticle(p, sim.fluidContext()) : nullptr;
  c.compression = compression != nullptr;
  if (c.compression) parts.push_back(part(compression, p.count));
  for (int k = 0; k < c.channels; ++k) parts.push_back(part(ps.channel(k), p.count));
  for (const auto& m : sim.modules()) {
    const std::vector<DownloadQueue::Part> own = m->statsSources(sim);
    c.moduleParts.push_back(int(own.size()));
    parts.insert(parts.end(), own.begin(), own.end());
  }
  c.transfer = queue.download(parts);
  return c;
}

FrameData finishFrameCopy(FrameCopy&& copy, DownloadQueue& queue) {
  FrameData f = std::move(copy.scalars);
  const DownloadQueue::Transfer& t = *copy.transfer;
  copy.transfer->wait();
  const std::size_t n = std::size_t(copy.count);
  std::size_t k = 0;
  f.position = unpack<Float4>(t, k++, n);
  f.velocity = unpack<Vec3>(t, k++, n);
  f.mass = unpack<float>(t, k++, n);
  f.radius = unpack<float>(t, k++, n);
  f.phase = unpack<int>(t, k++, n);
  f.id = unpack<int>(t, k++, n);
  f.density = unpack<float>(t, k++, n);  // slots past densitySlots read 0
  f.clothSubsteps = unpack<int>(t, k++, 1)[0];
  if (copy.compression) f.compression = unpack<float>(t, k++, n);
  for (int c = 0; c < copy.channels; ++c) f.channels.push_back(unpack<float>(t, k++, n));
  for (int parts : copy.moduleParts) {
    FrameData::ModuleCopies own;
    for (int j = 0; j < parts; ++j, ++k) {
      const auto* bytes = static_cast<const unsigned char*>(t.part(k));
      own.parts.emplace_back(bytes, bytes + t.partBytes(k));
    }
    f.modules.push_back(std::move(own));
  }
  queue.recycle(std::move(copy.transfer));
  return f;
}

StatsRow frameStats(const Simulation& sim, const FrameData& frame) {
  StatsRow row;
  long long water = 0, clothCount = 0;
  double waterMass = 0.0, pendingDrained = 0.0;
  for (std::size_t i = 0; i < frame.phase.size(); ++i) {
    if (isRemoved(frame.phase[i])) {
      pendingDrained += frame.mass[i];
    } else if (isWater(frame.phase[i])) {
      ++water;
      waterMass += frame.mass[i];
    } else if (isCloth(frame.phase[i])) {
      ++clothCount;
    }
  }
  float maxSpeed = 0.f;
  double kinetic = 0.0;
  for (std::size_t i = 0; i < frame.velocity.size(); ++i) {
    maxSpeed = std::max(maxSpeed, length(frame.velocity[i]));
    kinetic += 0.5 * double(frame.mass[i]) * double(lengthSquared(frame.velocity[i]));
  }
  // Compression of water particles (FluidSolver::compressionPerParticle):
  // mean over the water, max over all slots (others hold 0).
  double compressionSum = 0.0;
  float compressionMax = 0.f;
  for (float e : frame.compression) {
    compressionSum += e;
    compressionMax = std::max(compressionMax, e);
  }
  row.add("water_particles", double(water));
  row.add("cloth_particles", double(clothCount));
  row.add("free_water_mass", waterMass);
  row.add("drained_water_mass", frame.drainedWaterMass + pendingDrained);
  row.add("emitted_water_mass", frame.emittedWaterMass);
  row.add("mean_density_error", water > 0 ? compressionSum / double(water) : 0.0);
  row.add("max_density_error", compressionMax);
  row.add("max_speed", maxSpeed);
  row.add("kinetic_energy", kinetic);
  const ClothSystem& cloth = sim.cloth;
  if (cloth.empty()) {
    row.add("max_stretch", 0.0);
  } else {
    const std::vector<int> slots = cloth.vertexSlots(frame.id, frame.phase);
    row.add("max_stretch", double(cloth.maxStretch(frame.position, slots)));
    row.add("cloth_substeps", double(frame.clothSubsteps));
    // Edge strain per cloth (ClothSystem::strain): warp and weft edges of a sheet, all edges of a mesh.
    const std::vector<ClothStrain> strain = cloth.strain(frame.position, slots);
    for (std::size_t k = 0; k < strain.size(); ++k) {
      row.add("strain_mean_" + cloth.objects()[k].name, strain[k].mean);
      row.add("strain_p99_" + cloth.objects()[k].name, strain[k].p99);
      row.add("stretch_mean_" + cloth.objects()[k].name, strain[k].stretchMean);
      row.add("stretch_p99_" + cloth.objects()[k].name, strain[k].stretchP99);
      row.add("compression_p99_" + cloth.objects()[k].name, strain[k].compressionP99);
    }
  }
  static const FrameData::ModuleCopies kNone;
  for (std::size_t m = 0; m < sim.modules().size(); ++m)
    sim.modules()[m]->addStats(frame, m < frame.modules.size() ? frame.modules[m] : kNone, row);
  return row;
}

}  // namespace soak

namespace soak {

OutputLayout Simulation::outputLayout() const {
  OutputLayout l;
  for (int c = 0; c < particles.channelCount(); ++c) l.channelNames.push_back(particles.channelName(c));
  l.cloths = cloth.objects();
  if (settings.surface) {
    l.surfaceCellSize = settings.surface->cellSize;
    l.surfaceIso = settings.surface->iso;
  }
  l.water = water;
  return l;
}

FrameCopy Simulation::startFrameCopy(DownloadQueue& queue) { return soak::startFrameCopy(*this, queue); }

FrameData Simulation::finishFrameCopy(FrameCopy&& copy, DownloadQueue& queue) const {
  return soak::finishFrameCopy(std::move(copy), queue);
}

StatsRow Simulation::frameStats(const FrameData& frame) const { return soak::frameStats(*this, frame); }

}  // namespace soak
