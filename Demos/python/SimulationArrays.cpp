#include "SimulationArrays.h"

#include <algorithm>
#include <numeric>
#include <stdexcept>

#include "Backend/Device.h"

namespace soak {

namespace {
const char* const kCoreFields[] = {"position", "velocity", "inverse_mass", "mass", "radius", "density", "phase", "id"};

HostArray floats(const std::string& name, int components, std::vector<float> v) {
  HostArray a;
  a.name = name;
  a.components = components;
  a.values = std::move(v);
  return a;
}
HostArray ints(const std::string& name, std::vector<int> v) {
  HostArray a;
  a.name = name;
  a.integer = true;
  a.ints = std::move(v);
  return a;
}
std::vector<float> xyz(const std::vector<Float4>& p) {
  std::vector<float> out;
  out.reserve(3 * p.size());
  for (const Float4& x : p) out.insert(out.end(), {x.x, x.y, x.z});
  return out;
}
std::vector<float> xyz(const std::vector<Vec3>& v) {
  std::vector<float> out;
  out.reserve(3 * v.size());
  for (const Vec3& x : v) out.insert(out.end(), {x.x, x.y, x.z});
  return out;
}

std::string fieldList(Simulation& sim) {
  std::string list;
  for (const std::string& f : arrayFieldNames(sim)) list += (list.empty() ? "" : ", ") + f;
  return list;
}

// Writes `data` (rows x cols) into the slots `slots` of `field`.
void writeSlots(Simulation& sim, const std::string& field, const std::vector<int>& slots, const float* data,
                std::size_t rows, std::size_t cols) {
  ParticleState& ps = sim.particles;
  const int channel = ps.findChannel(field);
  const bool vector = field == "position" || field == "velocity";
  if (!vector && channel < 0) {
    if (std::find(std::begin(kCoreFields), std::end(kCoreFields), field) != std::end(kCoreFields))
      throw std::invalid_argument("'" + field + "' is read-only (writable: position, velocity and the channels)");
    throw std::invalid_argument("no field '" + field + "' (fields: " + fieldList(sim) + ")");
  }
  const std::size_t want = vector ? 3 : 1;
  if (rows != slots.size() || (cols != want && !(want == 1 && cols == 0)))
    throw std::invalid_argument("'" + field + "' takes " + std::to_string(slots.size()) +
                                (want == 3 ? " rows of 3 values" : " values") + ", got " + std::to_string(rows) +
                                (cols ? " x " + std::to_string(cols) : std::string()));
  const ParticleView p = ps.view();
  const Device d = sim.device();
  if (field == "position") {
    std::vector<Float4> x = ps.downloadPositions();  // keeps each slot's inverse mass (w)
    for (std::size_t k = 0; k < slots.size(); ++k) {
      Float4& v = x[std::size_t(slots[k])];
      v.x = data[3 * k];
      v.y = data[3 * k + 1];
      v.z = data[3 * k + 2];
    }
    copyHostToDevice(d, p.position, x.data(), x.size() * sizeof(Float4));
  } else if (field == "velocity") {
    std::vector<Vec3> v = ps.downloadVelocities();
    for (std::size_t k = 0; k < slots.size(); ++k) v[std::size_t(slots[k])] = Vec3{data[3 * k], data[3 * k + 1], data[3 * k + 2]};
    copyHostToDevice(d, p.velocity, v.data(), v.size() * sizeof(Vec3));
  } else {
    std::vector<float> c = ps.downloadChannel(channel);
    for (std::size_t k = 0; k < slots.size(); ++k) c[std::size_t(slots[k])] = data[k];
    copyHostToDevice(d, ps.channel(channel), c.data(), c.size() * sizeof(float));
  }
}

const ClothObject& findCloth(const Simulation& sim, const std::string& name) {
  std::string names;
  for (const ClothObject& c : sim.cloth.objects()) {
    if (c.name == name) return c;
    names += (names.empty() ? "" : ", ") + c.name;
  }
  throw std::invalid_argument("no cloth '" + name + "' (cloths: " + (names.empty() ? "none" : names) + ")");
}

// Slot of each vertex of `obj`, in vertex order.
std::vector<int> clothSlots(Simulation& sim, const ClothObject& obj) {
  const std::vector<int> all = sim.cloth.vertexSlots(sim.particles.downloadIds(), sim.particles.downloadPhases());
  return std::vector<int>(all.begin() + obj.firstVertex, all.begin() + obj.firstVertex + obj.vertexCount);
}

template <class T>
std::vector<T> pick(const std::vector<T>& all, const std::vector<int>& slots, std::size_t components) {
  std::vector<T> out;
  out.reserve(slots.size() * components);
  for (int s : slots)
    for (std::size_t c = 0; c < components; ++c) out.push_back(all[std::size_t(s) * components + c]);
  return out;
}
}  // namespace

std::vector<std::string> arrayFieldNames(Simulation& sim) {
  std::vector<std::string> names(std::begin(kCoreFields), std::end(kCoreFields));
  for (int k = 0; k < sim.particles.channelCount(); ++k) names.push_back(sim.particles.channelName(k));
  return names;
}

HostArray getField(Simulation& sim, const std::string& field) {
  ParticleState& ps = sim.particles;
  if (field == "position") return floats(field, 3, xyz(ps.downloadPositions()));
  if (field == "velocity") return floats(field, 3, xyz(ps.downloadVelocities()));
  if (field == "inverse_mass") {
    std::vector<float> w;
    for (const Float4& x : ps.downloadPositions()) w.push_back(x.w);
    return floats(field, 1, std::move(w));
  }
  if (field == "mass") return floats(field, 1, ps.downloadMasses());
  if (field == "radius") return floats(field, 1, ps.downloadRadii());
  if (field == "density") return floats(field, 1, sim.fluid.downloadDensity(ps.count()));
  if (field == "phase") return ints(field, ps.downloadPhases());
  if (field == "id") return ints(field, ps.downloadIds());
  const int channel = ps.findChannel(field);
  if (channel < 0) throw std::invalid_argument("no field '" + field + "' (fields: " + fieldList(sim) + ")");
  return floats(field, 1, ps.downloadChannel(channel));
}

void setField(Simulation& sim, const std::string& field, const float* data, std::size_t rows, std::size_t cols) {
  std::vector<int> slots(std::size_t(sim.particles.count()));
  std::iota(slots.begin(), slots.end(), 0);
  writeSlots(sim, field, slots, data, rows, cols);
}

std::vector<HostArray> waterArrays(Simulation& sim) {
  ParticleState& ps = sim.particles;
  const std::vector<int> phase = ps.downloadPhases(), id = ps.downloadIds();
  std::vector<int> slots;
  for (std::size_t i = 0; i < phase.size(); ++i)
    if (isWater(phase[i])) slots.push_back(int(i));
  std::sort(slots.begin(), slots.end(), [&](int a, int b) { return id[std::size_t(a)] < id[std::size_t(b)]; });
  return {floats("position", 3, pick(xyz(ps.downloadPositions()), slots, 3)),
          floats("velocity", 3, pick(xyz(ps.downloadVelocities()), slots, 3)),
          floats("mass", 1, pick(ps.downloadMasses(), slots, 1)),
          floats("radius", 1, pick(ps.downloadRadii(), slots, 1)),
          floats("density", 1, pick(sim.fluid.downloadDensity(ps.count()), slots, 1)),
          ints("id", pick(id, slots, 1))};
}

std::vector<std::string> clothNames(const Simulation& sim) {
  std::vector<std::string> names;
  for (const ClothObject& c : sim.cloth.objects()) names.push_back(c.name);
  return names;
}

std::vector<HostArray> clothArrays(Simulation& sim, const std::string& name) {
  const ClothObject& obj = findCloth(sim, name);
  ParticleState& ps = sim.particles;
  const std::vector<int> slots = clothSlots(sim, obj);
  std::vector<HostArray> out{floats("position", 3, pick(xyz(ps.downloadPositions()), slots, 3)),
                             floats("velocity", 3, pick(xyz(ps.downloadVelocities()), slots, 3))};
  for (int k = 0; k < ps.channelCount(); ++k)
    out.push_back(floats(ps.channelName(k), 1, pick(ps.downloadChannel(k), slots, 1)));
  HostArray tri = ints("triangles", {});
  tri.components = 3;
  for (const auto& t : obj.localTriangles) tri.ints.insert(tri.ints.end(), {t[0], t[1], t[2]});
  out.push_back(std::move(tri));
  return out;
}

void setClothField(Simulation& sim, const std::string& name, const std::string& field, const float* data,
                   std::size_t rows, std::size_t cols) {
  writeSlots(sim, field, clothSlots(sim, findCloth(sim, name)), data, rows, cols);
}

}  // namespace soak
