#include "Cloth/ClothSystem.h"

#include <algorithm>
#include <cmath>

#include "Backend/ForEach.h"
#include "Base/Atomic.h"
#include "Backend/Primitives.h"
#include "Cloth/ConstraintColoring.h"
#include "Cloth/StretchLimits.h"

namespace soak {

ClothSystem::ClothSystem(Device device)
    : device_(device),
      dEdges_(device), dMeasuredEdges_(device), dMeasuredEdgeRest_(device), dStrainEdges_(device), dStrainEdgeRest_(device), dEdgeRest_(device), dEdgeLambda_(device), dEdgeStiffness_(device), dBends_(device),
      dBendRest_(device), dBendLambda_(device), dBendStiffness_(device), dTriangles_(device), dTriStart_(device),
      dTriList_(device), dAttach_(device), dFirstTriStart_(device), dFirstTri_(device), dFirstEdgeStart_(device), dFirstEdgeOther_(device), dTriangleSnapshot_(device), dSlot_(device), dThickness_(device), dTetherLength_(device), dTetherPin_(device), dRest_(device), dMaterialCoord_(device), dVertexScratch_(device), dClothFlag_(device), dClothOffset_(device), dClothSlots_(device), dJacobiVertices_(device), dSpringStart_(device), dBendRefStart_(device), dSprings_(device), dBendRefs_(device), dJacobiBends_(device), dJacobiBendRest_(device), dJacobiBendStiffness_(device), dSpringStiffness_(device), dSolvedByJacobi_(device), dJacobiPrevious_(device), dJacobiTarget_(device), dGridRange_(device), dGridKey_(device), dGridNear_(device), scratch_(device) {}

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
  obj.hasMaterialCoordinates = spec.mesh.uv.size() == spec.mesh.vertices.size();
  obj.where = spec.where;
  for (const auto& t : spec.mesh.triangles)
    obj.restArea += 0.5 * double(length(cross(spec.mesh.vertices[t[1]] - spec.mesh.vertices[t[0]],
                                              spec.mesh.vertices[t[2]] - spec.mesh.vertices[t[0]])));
  const bool jacobi = spec.model == ClothModel::Chebyshev;

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
    materialCoord_.push_back(spec.mesh.uv.empty() ? Vec3(0.f, 0.f, 0.f)
                                                  : Vec3(spec.mesh.uv[v][0], spec.mesh.uv[v][1], 0.f));
    jacobi_.push_back(jacobi ? 1 : 0);
    springStiffness_.push_back(spec.stretchStiffness);
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

  obj.firstEdge = int(edges_.size());
  obj.edgeCount = int(topo.edges.size());
  for (std::size_t e = 0; e < topo.edges.size(); ++e) {
    const int a = topo.edges[e][0], b = topo.edges[e][1];
    const int nu = spec.sheetColumns;
    edgeMeasured_.push_back(nu == 0 || a / nu == b / nu || a % nu == b % nu);
    edges_.push_back({first + topo.edges[e][0], first + topo.edges[e][1]});
    edgeRest_.push_back(topo.edgeRestLength[e]);
    edgeStiffness_.push_back(spec.stretch);
    maxEdgeLength_ = std::max(maxEdgeLength_, topo.edgeRestLength[e]);
    minEdgeLength_ = std::min(minEdgeLength_, topo.edgeRestLength[e]);
  }
  for (std::size_t b = 0; b < topo.bendPairs.size(); ++b) {
    ClothBend cb;
    for (int a = 0; a < 4; ++a) cb.v[a] = first + topo.bendPairs[b][a];
    bends_.push_back(cb);
    bendRest_.push_back(topo.bendRestAngle[b]);
    bendStiffness_.push_back(spec.bend);
  }
  // Stretch limits (chebyshev; Cloth/StretchLimits.h): along the rows and
  // columns of a generated sheet, along the straightest lines of edges of a mesh.
  if (jacobi && spec.stretchLimits) {
    const std::vector<StretchLimit> limits = spec.sheetColumns > 0
                                                 ? sheetStretchLimits(spec.mesh.vertices, spec.sheetColumns, spec.sheetRows)
                                                 : meshStretchLimits(spec.mesh.vertices, topo);
    for (const StretchLimit& l : limits) {
      limitVertex_.push_back(first + l.a);
      limitOf_.push_back(makeSpring(first + l.b, l.rest, true));
    }
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
  // PBD and XPBD constraints are coloured for Gauss-Seidel; those of
  // chebyshev cloths go to the per-vertex lists of the Jacobi solve.
  std::vector<int> ev, pbdEdges;
  for (std::size_t e = 0; e < edges_.size(); ++e)
    if (!jacobi_[edges_[e].a]) {
      ev.insert(ev.end(), {edges_[e].a, edges_[e].b});
      pbdEdges.push_back(int(e));
    }
  ColouredOrder ec = colourConstraints(ev, 2, nv);
  std::vector<int> bv, pbdBends;
  for (std::size_t b = 0; b < bends_.size(); ++b)
    if (!jacobi_[bends_[b].v[0]]) {
      bv.insert(bv.end(), {bends_[b].v[0], bends_[b].v[1], bends_[b].v[2], bends_[b].v[3]});
      pbdBends.push_back(int(b));
    }
  ColouredOrder bc = colourConstraints(bv, 4, nv);
  edgeColourStart_ = ec.colourStart.empty() ? std::vector<int>{0} : ec.colourStart;
  bendColourStart_ = bc.colourStart.empty() ? std::vector<int>{0} : bc.colourStart;
  std::vector<int> edgeOrder(ec.order.size()), bendOrder(bc.order.size());
  for (std::size_t k = 0; k < ec.order.size(); ++k) edgeOrder[k] = pbdEdges[ec.order[k]];
  for (std::size_t k = 0; k < bc.order.size(); ++k) bendOrder[k] = pbdBends[bc.order[k]];

  dEdges_.upload(permuted(edges_, edgeOrder));
  dEdgeRest_.upload(permuted(edgeRest_, edgeOrder));
  dMeasuredEdges_.upload(edges_);
  dMeasuredEdgeRest_.upload(edgeRest_);
  std::vector<ClothEdge> strainEdges;
  std::vector<float> strainRest;
  for (std::size_t e = 0; e < edges_.size(); ++e)
    if (edgeMeasured_[e]) {
      strainEdges.push_back(edges_[e]);
      strainRest.push_back(edgeRest_[e]);
    }
  dStrainEdges_.upload(strainEdges);
  dStrainEdgeRest_.upload(strainRest);
  dEdgeStiffness_.upload(permuted(edgeStiffness_, edgeOrder));
  dEdgeLambda_.resize(edgeOrder.size());
  dBends_.upload(permuted(bends_, bendOrder));
  dBendRest_.upload(permuted(bendRest_, bendOrder));
  dBendStiffness_.upload(permuted(bendStiffness_, bendOrder));
  dBendLambda_.resize(bendOrder.size());
  uploadJacobi();
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
  // edges_ holds each edge once, a < b, in increasing (a, b).
  std::vector<int> edgeStart(nv + 1, 0), edgeOther(edges_.size());
  for (const ClothEdge& e : edges_) ++edgeStart[e.a + 1];
  for (int v = 0; v < nv; ++v) edgeStart[v + 1] += edgeStart[v];
  std::vector<int> nextEdge(edgeStart.begin(), edgeStart.end() - 1);
  for (const ClothEdge& e : edges_) edgeOther[nextEdge[e.a]++] = e.b;
  dFirstEdgeStart_.upload(edgeStart);
  dFirstEdgeOther_.upload(edgeOther);
  dRest_.upload(restPosition_);
  dMaterialCoord_.upload(materialCoord_);
  dAttach_.upload(attach_);
  dThickness_.upload(thickness_);
  dTetherPin_.upload(tetherPin_);
  anyTethers_ = false;
  for (int v = 0; v < nv; ++v) anyTethers_ = anyTethers_ || (!jacobi_[v] && tetherPin_[std::size_t(v) * kTethers] >= 0);
  dTetherLength_.upload(tetherLength_);
  dSlot_.resize(nv);
  dVertexScratch_.resize(nv);
  dClothSlots_.resize(nv);
  dGridKey_.resize(nv);
  scratch_.resize(std::max<std::size_t>(edges_.size(), 1));
}

void ClothSystem::uploadJacobi() {
  const int nv = vertexCount();
  jacobiVertices_.clear();
  for (int v = 0; v < nv; ++v)
    if (jacobi_[v]) jacobiVertices_.push_back(v);
  std::vector<int> springStart(nv + 1, 0), refStart(nv + 1, 0);
  std::vector<int> jacobiBends;
  for (const ClothEdge& e : edges_)
    if (jacobi_[e.a]) {
      ++springStart[e.a + 1];
      ++springStart[e.b + 1];
    }
  for (int v : limitVertex_) ++springStart[v + 1];
  for (std::size_t b = 0; b < bends_.size(); ++b)
    if (jacobi_[bends_[b].v[0]]) {
      jacobiBends.push_back(int(b));
      for (int a = 0; a < 4; ++a) ++refStart[bends_[b].v[a] + 1];
    }
  for (int v = 0; v < nv; ++v) {
    springStart[v + 1] += springStart[v];
    refStart[v + 1] += refStart[v];
  }
  std::vector<JacobiSpring> springs(springStart[nv]);
  std::vector<int> fill(springStart.begin(), springStart.end() - 1);
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const ClothEdge edge = edges_[e];
    if (!jacobi_[edge.a]) continue;
    springs[fill[edge.a]++] = makeSpring(edge.b, edgeRest_[e], false);
    springs[fill[edge.b]++] = makeSpring(edge.a, edgeRest_[e], false);
  }
  for (std::size_t k = 0; k < limitOf_.size(); ++k) springs[fill[limitVertex_[k]]++] = limitOf_[k];
  std::vector<JacobiBendRef> refs(refStart[nv]);
  fill.assign(refStart.begin(), refStart.end() - 1);
  for (std::size_t k = 0; k < jacobiBends.size(); ++k)
    for (int a = 0; a < 4; ++a) refs[fill[bends_[jacobiBends[k]].v[a]]++] = {int(k), a};
  jacobiBendCount_ = int(jacobiBends.size());
  dJacobiVertices_.upload(jacobiVertices_);
  dSpringStart_.upload(springStart);
  dSprings_.upload(springs);
  dSpringStiffness_.upload(springStiffness_);
  dBendRefStart_.upload(refStart);
  dBendRefs_.upload(refs);
  dJacobiBends_.upload(permuted(bends_, jacobiBends));
  dJacobiBendRest_.upload(permuted(bendRest_, jacobiBends));
  std::vector<float> bendKPrime(jacobiBends.size());
  for (std::size_t k = 0; k < jacobiBends.size(); ++k) bendKPrime[k] = bendStiffness_[jacobiBends[k]].kPrime;
  dJacobiBendStiffness_.upload(bendKPrime);
  dSolvedByJacobi_.upload(jacobi_);
  dJacobiPrevious_.resize(std::size_t(nv));
  dJacobiTarget_.resize(std::size_t(nv));
}

ClothView ClothSystem::view() {
  ClothView v;
  v.bendScale = bendScale_;
  v.frictionScale = frictionScale_;
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
  v.firstVertexEdgeStart = dFirstEdgeStart_.data();
  v.firstVertexEdgeOther = dFirstEdgeOther_.data();
  v.restPosition = dRest_.data();
  v.materialCoord = dMaterialCoord_.data();
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
  v.jacobiVertices = dJacobiVertices_.data();
  v.springStart = dSpringStart_.data();
  v.springs = dSprings_.data();
  v.springStiffness = dSpringStiffness_.data();
  v.bendRefStart = dBendRefStart_.data();
  v.bendRefs = dBendRefs_.data();
  v.jacobiBends = dJacobiBends_.data();
  v.jacobiBendRest = dJacobiBendRest_.data();
  v.jacobiBendStiffness = dJacobiBendStiffness_.data();
  v.anyJacobiBends = jacobiBendCount_ > 0;
  v.solvedByJacobi = dSolvedByJacobi_.data();
  v.jacobiVertexCount = int(jacobiVertices_.size());
  v.jacobiPrevious = dJacobiPrevious_.data();
  v.jacobiTarget = dJacobiTarget_.data();
  v.vertexCount = vertexCount();
  v.edgeCount = int(dEdges_.size());
  v.bendCount = int(dBends_.size());
  v.triangleCount = int(dTriangles_.size());
  return v;
}

void ClothSystem::resetMultipliers() {
  dEdgeLambda_.fillZero();
  dBendLambda_.fillZero();
}

float ClothSystem::maxStretch(ParticleView p) {
  const int count = int(dMeasuredEdges_.size());
  if (count == 0) return 0.f;
  const int* vertexSlot = view().vertexSlot;
  const ClothEdge* edges = dMeasuredEdges_.data();
  const float* rest = dMeasuredEdgeRest_.data();
  float* strain = scratch_.data();
  forEach(device_, count, SOAK_LAMBDA(int e) {
    Vec3 a = p.position[vertexSlot[edges[e].a]].xyz();
    Vec3 b = p.position[vertexSlot[edges[e].b]].xyz();
    strain[e] = fabsf(length(a - b) - rest[e]) / rest[e];
  }, "cloth.strain");
  return reduceMax(device_, strain, count);
}

std::vector<int> ClothSystem::vertexSlots(const std::vector<int>& id, const std::vector<int>& phase) const {
  std::vector<int> slot(restPosition_.size(), -1);
  for (std::size_t i = 0; i < phase.size(); ++i)
    if (isCloth(phase[i]) && id[i] >= 0 && std::size_t(id[i]) < slot.size()) slot[std::size_t(id[i])] = int(i);
  return slot;
}

float ClothSystem::maxStretch(const std::vector<Float4>& position, const std::vector<int>& slot) const {
  float worst = 0.f;
  for (std::size_t e = 0; e < edges_.size(); ++e) {
    const int a = slot[std::size_t(edges_[e].a)], b = slot[std::size_t(edges_[e].b)];
    if (a < 0 || b < 0) continue;
    const float rest = edgeRest_[e];
    worst = std::max(worst, std::fabs(length(position[std::size_t(a)].xyz() - position[std::size_t(b)].xyz()) - rest) / rest);
  }
  return worst;
}

std::vector<ClothStrain> ClothSystem::strain(const std::vector<Float4>& position, const std::vector<int>& slot) const {
  std::vector<ClothStrain> out;
  std::vector<double> strains, stretch, compression;
  // The 99th percentile of `v` (reordered).
  const auto p99 = [](std::vector<double>& v) {
    const std::size_t k = std::min(v.size() - 1, std::size_t(0.99 * double(v.size())));
    std::nth_element(v.begin(), v.begin() + std::ptrdiff_t(k), v.end());
    return v[k];
  };
  for (const ClothObject& obj : objects_) {
    strains.clear();
    stretch.clear();
    compression.clear();
    for (int e = obj.firstEdge; e < obj.firstEdge + obj.edgeCount; ++e) {
      if (!edgeMeasured_[std::size_t(e)]) continue;
      const int a = slot[std::size_t(edges_[std::size_t(e)].a)], b = slot[std::size_t(edges_[std::size_t(e)].b)];
      if (a < 0 || b < 0) continue;
      const double l = double(length(position[std::size_t(a)].xyz() - position[std::size_t(b)].xyz()));
      const double l0 = double(edgeRest_[std::size_t(e)]);
      strains.push_back(std::fabs(l - l0) / l0);
      stretch.push_back(std::max(0.0, l / l0 - 1.0));
      compression.push_back(std::max(0.0, 1.0 - l / l0));
    }
    ClothStrain s;
    if (!strains.empty()) {
      double sum = 0.0;
      for (double v : strains) sum += v;
      s.mean = sum / double(strains.size());
      s.max = *std::max_element(strains.begin(), strains.end());
      double stretchSum = 0.0;
      for (double v : stretch) stretchSum += v;
      s.stretchMean = stretchSum / double(stretch.size());
      s.p99 = p99(strains);
      s.stretchP99 = p99(stretch);
      s.compressionP99 = p99(compression);
    }
    out.push_back(s);
  }
  return out;
}

std::vector<float> ClothSystem::vertexRestAreas() const {
  std::vector<float> area(restPosition_.size(), 0.f);
  for (const ClothTriangle& t : triangles_) {
    const Vec3 a = restPosition_[std::size_t(t.v[0])], b = restPosition_[std::size_t(t.v[1])],
               c = restPosition_[std::size_t(t.v[2])];
    const float third = length(cross(b - a, c - a)) / 6.f;
    for (int k = 0; k < 3; ++k) area[std::size_t(t.v[k])] += third;
  }
  return area;
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
