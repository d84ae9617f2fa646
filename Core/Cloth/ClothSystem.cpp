#include "Cloth/ClothSystem.h"

#include <algorithm>

#include "Backend/ForEach.h"
#include "Base/Atomic.h"
#include "Backend/Primitives.h"
#include "Cloth/ConstraintColoring.h"

namespace soak {

ClothSystem::ClothSystem(Device device)
    : device_(device),
      dEdges_(device), dEdgeRest_(device), dEdgeLambda_(device), dEdgeStiffness_(device), dBends_(device),
      dBendRest_(device), dBendLambda_(device), dBendStiffness_(device), dTriangles_(device), dTriStart_(device),
      dTriList_(device), dAttach_(device), dFirstTriStart_(device), dFirstTri_(device), dTriangleSnapshot_(device), dSlot_(device), dThickness_(device), dTetherLength_(device), dTetherPin_(device), dRest_(device), dVertexScratch_(device), dClothFlag_(device), dClothOffset_(device), dClothSlots_(device), dGridRange_(device), dGridKey_(device), dGridNear_(device), scratch_(device) {}

int ClothSystem::add(const ClothSpec& spec, ParticleState& particles) {
  const int clothIndex = int(objects_.size());
  const int first = vertexCount();
  ClothTopology topo = buildClothTopology(spec.mesh);
  ClothObject obj;
  obj.name = spec.name;
  obj.phase = clothPhase(clothIndex);
  obj.firstVertex = first;
  obj.vertexCount = int(spec.mesh.vertices.size());
  obj.firstTriangle = int(triangles_.size());
  obj.triangleCount = int(spec.mesh.triangles.size());
  obj.localTriangles = spec.mesh.triangles;

  float thickness = spec.thickness;
  if (thickness <= 0.f) {
    double sum = 0.0;
    for (float l : topo.edgeRestLength) sum += l;
    thickness = topo.edgeRestLength.empty() ? 0.01f : float(0.75 * sum / double(topo.edgeRestLength.size()));
  }
  maxThickness_ = std::max(maxThickness_, thickness);
  std::vector<char> pinned(spec.mesh.vertices.size(), 0);
  for (int v : spec.pinned) pinned[v] = 1;
  std::vector<ParticleInit> batch(spec.mesh.vertices.size());
  for (std::size_t v = 0; v < batch.size(); ++v) {
    ParticleInit& q = batch[v];
    q.position = spec.mesh.vertices[v];
    q.mass = spec.particleMass;
    q.radius = spec.supportRadius;
    q.phase = obj.phase;
    q.id = first + int(v);
    q.pinned = pinned[v] != 0;
    restPosition_.push_back(spec.mesh.vertices[v]);
    attach_.push_back(pinned[v] ? spec.attachCollider : -1);
    thickness_.push_back(thickness);
  }
  particles.append(batch);
  // Tethers to the nearest pinned vertices, as long as their rest distance
  // (the geodesic distance on a flat sheet; shorter than it on a curved mesh,
  // where a tether then also limits bending away from the pins).
  std::vector<int> pins;
  for (std::size_t v = 0; v < pinned.size(); ++v)
    if (pinned[v]) pins.push_back(int(v));
  for (std::size_t v = 0; v < batch.size(); ++v) {
    std::vector<std::pair<float, int>> near;
    if (!pinned[v] && spec.tetherSlack >= 0.f)
      for (int q : pins) near.emplace_back(length(spec.mesh.vertices[v] - spec.mesh.vertices[q]), q);
    std::sort(near.begin(), near.end());
    for (int k = 0; k < kTethers; ++k) {
      const bool has = k < int(near.size());
      tetherPin_.push_back(has ? first + near[k].second : -1);
      tetherLength_.push_back(has ? near[k].first * (1.f + spec.tetherSlack) : 0.f);
    }
  }

  for (std::size_t e = 0; e < topo.edges.size(); ++e) {
    edges_.push_back({first + topo.edges[e][0], first + topo.edges[e][1]});
    edgeRest_.push_back(topo.edgeRestLength[e]);
    edgeStiffness_.push_back(spec.stretch);
    maxEdgeLength_ = std::max(maxEdgeLength_, topo.edgeRestLength[e]);
  }
  for (std::size_t b = 0; b < topo.bendPairs.size(); ++b) {
    ClothBend cb;
    for (int a = 0; a < 4; ++a) cb.v[a] = first + topo.bendPairs[b][a];
    bends_.push_back(cb);
    bendRest_.push_back(topo.bendRestAngle[b]);
    bendStiffness_.push_back(spec.bend);
  }
  for (const auto& t : spec.mesh.triangles) triangles_.push_back({{first + t[0], first + t[1], first + t[2]}});
  objects_.push_back(std::move(obj));
  return clothIndex;
}

namespace {
template <class T>
std::vector<T> permuted(const std::vector<T>& v, const std::vector<int>& order) {
  std::vector<T> out(order.size());
  for (std::size_t k = 0; k < order.size(); ++k) out[k] = v[order[k]];
  return out;
}
}  // namespace

void ClothSystem::upload() {
  const int nv = vertexCount();
  std::vector<int> ev;
  for (const auto& e : edges_) ev.insert(ev.end(), {e.a, e.b});
  ColouredOrder ec = colourConstraints(ev, 2, nv);
  std::vector<int> bv;
  for (const auto& b : bends_) bv.insert(bv.end(), {b.v[0], b.v[1], b.v[2], b.v[3]});
  ColouredOrder bc = colourConstraints(bv, 4, nv);
  edgeColourStart_ = ec.colourStart.empty() ? std::vector<int>{0} : ec.colourStart;
  bendColourStart_ = bc.colourStart.empty() ? std::vector<int>{0} : bc.colourStart;

  dEdges_.upload(permuted(edges_, ec.order));
  dEdgeRest_.upload(permuted(edgeRest_, ec.order));
  dEdgeStiffness_.upload(permuted(edgeStiffness_, ec.order));
  dEdgeLambda_.resize(edges_.size());
  dBends_.upload(permuted(bends_, bc.order));
  dBendRest_.upload(permuted(bendRest_, bc.order));
  dBendStiffness_.upload(permuted(bendStiffness_, bc.order));
  dBendLambda_.resize(bends_.size());
  resetMultipliers();
  dTriangles_.upload(triangles_);
  // Triangles touching each vertex (CSR).
  std::vector<int> start(nv + 1, 0);
  for (const auto& t : triangles_)
    for (int a = 0; a < 3; ++a) ++start[t.v[a] + 1];
  for (int v = 0; v < nv; ++v) start[v + 1] += start[v];
  std::vector<int> list(start[nv]);
  std::vector<int> fill(start.begin(), start.end() - 1);
  for (std::size_t t = 0; t < triangles_.size(); ++t)
    for (int a = 0; a < 3; ++a) list[fill[triangles_[t].v[a]]++] = int(t);
  dTriStart_.upload(start);
  dTriList_.upload(list);
  std::vector<int> firstStart(nv + 1, 0);
  for (const auto& t : triangles_) ++firstStart[t.v[0] + 1];
  for (int v = 0; v < nv; ++v) firstStart[v + 1] += firstStart[v];
  std::vector<ClothTriangle> firstList(triangles_.size());
  std::vector<int> next(firstStart.begin(), firstStart.end() - 1);
  for (const auto& t : triangles_) firstList[next[t.v[0]]++] = t;
  dFirstTriStart_.upload(firstStart);
  dFirstTri_.upload(firstList);
  dTriangleSnapshot_.resize(firstList.size());
  dRest_.upload(restPosition_);
  dAttach_.upload(attach_);
  dThickness_.upload(thickness_);
  dTetherPin_.upload(tetherPin_);
  anyTethers_ = std::any_of(tetherPin_.begin(), tetherPin_.end(), [](int pin) { return pin >= 0; });
  dTetherLength_.upload(tetherLength_);
  dSlot_.resize(nv);
  dVertexScratch_.resize(nv);
  dClothSlots_.resize(nv);
  dGridKey_.resize(nv);
  scratch_.resize(std::max<std::size_t>(edges_.size(), 1));
}

ClothView ClothSystem::view() {
  ClothView v;
  v.edges = dEdges_.data();
  v.edgeRest = dEdgeRest_.data();
  v.edgeStiffness = dEdgeStiffness_.data();
  v.edgeLambda = dEdgeLambda_.data();
  v.bends = dBends_.data();
  v.bendRest = dBendRest_.data();
  v.bendStiffness = dBendStiffness_.data();
  v.bendLambda = dBendLambda_.data();
  v.triangles = dTriangles_.data();
  v.vertexTriangleStart = dTriStart_.data();
  v.vertexTriangles = dTriList_.data();
  v.firstVertexTriangleStart = dFirstTriStart_.data();
  v.firstVertexTriangles = dFirstTri_.data();
  v.triangleSnapshot = dTriangleSnapshot_.data();
  v.restPosition = dRest_.data();
  v.attachCollider = dAttach_.data();
  v.thickness = dThickness_.data();
  v.maxEdgeLength = maxEdgeLength_;
  v.maxThickness = maxThickness_;
  v.tetherPin = dTetherPin_.data();
  v.anyTethers = anyTethers_;
  v.tetherLength = dTetherLength_.data();
  v.vertexSlot = dSlot_.data();
  v.vertexScratch = dVertexScratch_.data();
  v.clothSlots = dClothSlots_.data();
  v.vertexCount = vertexCount();
  v.edgeCount = int(dEdges_.size());
  v.bendCount = int(dBends_.size());
  v.triangleCount = int(dTriangles_.size());
  return v;
}

void ClothSystem::updateSlots(ParticleView p) {
  int* slot = dSlot_.data();
  dClothFlag_.resize(std::size_t(p.count));
  dClothOffset_.resize(std::size_t(p.count));
  int* flag = dClothFlag_.data();
  forEach(device_, p.count, SOAK_LAMBDA(int i) {
    const bool cloth = isCloth(p.phase[i]);
    flag[i] = cloth ? 1 : 0;
    if (cloth) slot[p.id[i]] = i;
  }, "cloth.slots");
  // The cloth's slots in particle (grid cell) order: the cloth passes walk
  // these, so that a warp's lanes are all cloth and query the same cells.
  int* offset = dClothOffset_.data();
  exclusiveScanAsync(device_, flag, offset, p.count);
  int* ordered = dClothSlots_.data();
  forEach(device_, p.count, SOAK_LAMBDA(int i) {
    if (flag[i]) ordered[offset[i]] = i;
  }, "cloth.slots.order");
}

void ClothSystem::buildGrid(GridView g) {
  const int* ordered = dClothSlots_.data();
  // The cloth's grid: the same buckets as the full grid, its entries the
  // ordered slots (already sorted by bucket, as the particles are).
  const std::size_t buckets = std::size_t(g.bucketMask) + 1;
  dGridRange_.resize(buckets);
  dGridRange_.fillZero();
  BucketRange* range = dGridRange_.data();
  std::uint32_t* key = dGridKey_.data();
  const int n = vertexCount();
  forEach(device_, n, SOAK_LAMBDA(int k) {
    const std::uint32_t kk = g.slotKey[ordered[k]];
    key[k] = kk;
    const std::uint32_t b = bucketOfKey(kk, g.bucketMask);
    if (k == 0 || bucketOfKey(g.slotKey[ordered[k - 1]], g.bucketMask) != b) range[b].start = std::uint32_t(k);
    if (k == n - 1 || bucketOfKey(g.slotKey[ordered[k + 1]], g.bucketMask) != b) range[b].end = std::uint32_t(k + 1);
  }, "cloth.grid");
  // Near bits (GridView.h): each cell that holds cloth sets the bits of the
  // 27 cells around it, once per run of its entries (a cell's entries are
  // adjacent unless its bucket holds another cell too; then it sets them
  // again, to the same effect).
  dGridNear_.resize((buckets + 31) / 32);
  dGridNear_.fillZero();
  std::uint32_t* near = dGridNear_.data();
  const std::uint32_t mask = g.bucketMask;
  forEach(device_, n, SOAK_LAMBDA(int k) {
    const std::uint32_t kk = key[k];
    if (k > 0 && key[k - 1] == kk) return;
    const int c[3] = {int(kk & 1023u), int((kk >> 10) & 1023u), int((kk >> 20) & 1023u)};
    std::uint32_t spread[3][3];
    spreadAround(c, spread);
    for (int dz = 0; dz < 3; ++dz)
      for (int dy = 0; dy < 3; ++dy)
        for (int dx = 0; dx < 3; ++dx) {
          const std::uint32_t b = (spread[0][dx] | spread[1][dy] | spread[2][dz]) & mask;
          atomicSetBits(&near[b >> 5], 1u << (b & 31u));
        }
  }, "cloth.grid.near");
  clothGrid_ = g;
  clothGrid_.range = range;
  clothGrid_.cellKey = key;
  clothGrid_.slot = ordered;
  clothGrid_.nearBits = near;
}

void ClothSystem::resetMultipliers() {
  dEdgeLambda_.fillZero();
  dBendLambda_.fillZero();
}

float ClothSystem::maxStretch(ParticleView p) {
  if (dEdges_.size() == 0) return 0.f;
  ClothView c = view();
  float* strain = scratch_.data();
  forEach(device_, c.edgeCount, SOAK_LAMBDA(int e) {
    Vec3 a = p.position[c.vertexSlot[c.edges[e].a]].xyz();
    Vec3 b = p.position[c.vertexSlot[c.edges[e].b]].xyz();
    strain[e] = fabsf(length(a - b) - c.edgeRest[e]) / c.edgeRest[e];
  }, "cloth.strain");
  return reduceMax(device_, strain, c.edgeCount);
}

std::vector<Vec3> ClothSystem::downloadVertexPositions(const ParticleState& particles, int clothIndex) const {
  const ClothObject& obj = objects_[clothIndex];
  std::vector<Float4> pos = particles.downloadPositions();
  std::vector<int> ids = particles.downloadIds();
  std::vector<int> phase = particles.downloadPhases();
  std::vector<Vec3> out(obj.vertexCount);
  for (std::size_t i = 0; i < pos.size(); ++i)
    if (phase[i] == obj.phase) out[ids[i] - obj.firstVertex] = pos[i].xyz();
  return out;
}

}  // namespace soak
