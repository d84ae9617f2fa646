#pragma once
// All cloth objects of a run: their constraints (coloured for parallel
// Gauss-Seidel), rest shapes and triangles, on the simulation's device.
// Cloth vertices are particles; `vertexSlot` maps a global cloth vertex
// index (the particle's `id`) to its slot after each neighbour sort.
#include <array>
#include <limits>
#include <string>
#include <vector>

#include "Backend/Buffer.h"
#include "Cloth/ClothConstraints.h"
#include "Cloth/ClothJacobi.h"
#include "Cloth/ClothTopology.h"
#include "Neighbours/GridView.h"
#include "Particles/ParticleState.h"

namespace soak {

constexpr int kTethers = 4;

struct alignas(8) ClothEdge {
  int a, b;
};
struct alignas(16) ClothBend {
  int v[4];
};
// One vertex's tethers as one 16-byte load (ClothView::tetherPin and
// tetherLength hold kTethers entries per vertex).
struct alignas(16) TetherPins {
  int pin[kTethers];
};
struct alignas(16) TetherLengths {
  float length[kTethers];
};
static_assert(sizeof(TetherPins) == kTethers * sizeof(int), "kTethers ints per vertex");
struct ClothTriangle {
  int v[3];
};

// A cloth triangle as the triangle searches (vertex-triangle contact,
// water-triangle coupling) read it: its vertices now and at the start of the
// step, and both unit normals, in one place. Stored at the triangle's
// position k in firstVertexTriangles and refreshed before each search
// (Coupling/TriangleCoupling.h), so that a test reads contiguous bytes
// instead of three slots and six particle positions, and does not recompute
// the normals for every particle that tests the triangle.
//
// Eight vectors packed into six Float4 (96 bytes, not eight Float4 with a
// spare w each): the first three hold what every test reads (a, n, a0, n0:
// which side the particle came from and how far it is now), the last three
// what only a test that goes on reads (b, c; b0, c0 where the path crossed
// the plane). A degenerate triangle has n = 0 (makeTriangleSnapshot).
struct TriangleSnapshot {
  Float4 q[6];
  SOAK_HD Vec3 a() const { return Vec3(q[0].x, q[0].y, q[0].z); }                 // predicted vertices
  SOAK_HD Vec3 n() const { return Vec3(q[0].w, q[1].x, q[1].y); }                 // unit normal now
  SOAK_HD Vec3 a0() const { return Vec3(q[1].z, q[1].w, q[2].x); }                // start-of-step vertices
  SOAK_HD Vec3 n0() const { return Vec3(q[2].y, q[2].z, q[2].w); }                // unit normal at the start
  SOAK_HD Vec3 b() const { return Vec3(q[3].x, q[3].y, q[3].z); }
  SOAK_HD Vec3 c() const { return Vec3(q[3].w, q[4].x, q[4].y); }
  SOAK_HD Vec3 b0() const { return Vec3(q[4].z, q[4].w, q[5].x); }
  SOAK_HD Vec3 c0() const { return Vec3(q[5].y, q[5].z, q[5].w); }
};
static_assert(sizeof(TriangleSnapshot) == 96, "six Float4 per triangle");

// What the cloth stages see (raw device pointers, passed to kernels).
struct ClothView {
  const ClothEdge* edges = nullptr;  // in colour order
  const float* edgeRest = nullptr;
  const ConstraintStiffness* edgeStiffness = nullptr;
  float* edgeLambda = nullptr;
  const ClothBend* bends = nullptr;  // in colour order
  const float* bendRest = nullptr;
  const ConstraintStiffness* bendStiffness = nullptr;
  float* bendLambda = nullptr;
  const ClothTriangle* triangles = nullptr;
  const int* vertexTriangleStart = nullptr;  // CSR: triangles touching each vertex
  const int* vertexTriangles = nullptr;
  // The triangles whose first vertex is v, copied in place (CSR): the
  // triangle searches visit each triangle from its first vertex only.
  const int* firstVertexTriangleStart = nullptr;
  const ClothTriangle* firstVertexTriangles = nullptr;
  TriangleSnapshot* triangleSnapshot = nullptr;  // per firstVertexTriangles entry (see TriangleSnapshot)
  // The edges whose first (lower) vertex is v (CSR): the second vertex of
  // each, increasing, for the crossing guard (CrossingGuard.h).
  const int* firstVertexEdgeStart = nullptr;
  const int* firstVertexEdgeOther = nullptr;
  const Vec3* restPosition = nullptr;  // per vertex, as created
  // Per vertex: material coordinates (u, v, 0): warp along u, weft along v
  // (a sheet's axes in metres, or a mesh's vt; 0 where the mesh has none,
  // ClothObject::hasMaterialCoordinates).
  const Vec3* materialCoord = nullptr;
  const int* attachCollider = nullptr; // per vertex: collider index it moves with, or -1
  const float* thickness = nullptr;    // per vertex: cloth thickness (contact distance), m
  int* vertexSlot = nullptr;           // per vertex: current particle slot
  const int* clothSlots = nullptr;     // the cloth particles' slots in increasing order (vertexCount of them)
  Float4* vertexScratch = nullptr;     // per vertex: predicted position in vertex order, during the constraint solve
  // Long-range attachments ("tethers", Kim et al. 2012): vertex v stays
  // within tetherLength of pinned vertex tetherPin (kTethers per vertex, -1: none).
  const int* tetherPin = nullptr;
  const float* tetherLength = nullptr;
  bool anyTethers = false;  // some vertex of a PBD or XPBD cloth has a tether
  // Cloth.model="chebyshev" (ClothJacobi.h): the vertices it solves, and per
  // vertex (CSR over all vertices, empty for the others) its stretch edges
  // and the bends it is part of.
  const int* jacobiVertices = nullptr;
  const int* springStart = nullptr;
  const JacobiSpring* springs = nullptr;
  const float* springStiffness = nullptr;  // per vertex: its springs' stiffness (N/m), its cloth's
  const int* bendRefStart = nullptr;
  const JacobiBendRef* bendRefs = nullptr;
  const ClothBend* jacobiBends = nullptr;
  const float* jacobiBendRest = nullptr;
  const float* jacobiBendStiffness = nullptr;  // kPrime of Eq. 5 per sub-step
  // Per vertex, from the published fields (Cloth/VertexFields.h); null: 1.
  const float* bendScale = nullptr;      // field::kBendStiffnessScale
  const float* frictionScale = nullptr;  // field::kFrictionScale
  bool anyJacobiBends = false;
  const unsigned char* solvedByJacobi = nullptr;  // per vertex: 1 for a chebyshev cloth's vertex
  int jacobiVertexCount = 0;
  Float4* jacobiPrevious = nullptr;  // per vertex: the iterate before the last (Chebyshev)
  Float4* jacobiTarget = nullptr;    // per vertex: the predicted position y of the sub-step, w its collider margin
  int vertexCount = 0, edgeCount = 0, bendCount = 0, triangleCount = 0;
  float maxEdgeLength = 0.f;  // longest rest edge of any cloth (bounds a triangle's reach from its vertices)
  float maxThickness = 0.f;   // largest thickness of any cloth
};

// Which solver a cloth's constraints go to (Cloth.model).
enum class ClothModel { Pbd, Xpbd, Chebyshev };

// Edge strain |l - l0| / l0 of one cloth: over its warp and weft edges on a
// generated sheet, over all edges on a mesh. Its two sides apart as well:
// stretch max(0, l / l0 - 1) and compression max(0, 1 - l / l0), each
// over all those edges. Fabric under compression buckles into wrinkles
// finer than the mesh (a sheet pulled at its corners wrinkles along the
// pulls), which a mesh shows as shortened edges; stretch is what the
// threads resist (Doc/model.md, "The default cloth solver").
struct ClothStrain {
  double mean = 0.0, p99 = 0.0, max = 0.0;
  double stretchMean = 0.0, stretchP99 = 0.0, compressionP99 = 0.0;
};

// How one cloth object is made (host side, from a <Cloth> element).
struct ClothSpec {
  std::string name;
  TriangleMesh mesh;
  float particleMass = 0.0066f;   // kg per vertex (Table 1)
  float supportRadius = 0.04f;    // h of cloth particles as boundary / porous particles
  ConstraintStiffness stretch, bend;  // PBD and XPBD
  ClothModel model = ClothModel::Pbd;
  float stretchStiffness = kStiffest;  // N/m, chebyshev (bending: bend.kPrime, once per sub-step)
  int sheetColumns = 0;           // vertices per row of a generated sheet (0: a mesh); strain is then measured
                                  // over the edges along its rows and columns
  int sheetRows = 0;              // rows of vertices of a generated sheet
  bool stretchLimits = false;     // chebyshev: the multi-scale stretch limits (Cloth/StretchLimits.h)
  std::vector<int> pinned;        // local vertex indices with inverse mass 0
  int attachCollider = -1;        // pinned vertices follow this collider (-1: fixed)
  float thickness = 0.f;          // contact distance, m (0: 0.75 x mean edge length)
  float tetherSlack = 0.f;        // tethers allow (1 + slack) x rest distance to the pins; < 0: no tethers
  std::string where;              // the <Cloth> element's file:line, for messages
};

struct ClothObject {
  std::string name;
  int phase = 0;
  int firstVertex = 0, vertexCount = 0;
  int firstTriangle = 0, triangleCount = 0;
  int firstEdge = 0, edgeCount = 0;  // in creation order (host)
  std::vector<std::array<int, 3>> localTriangles;  // for output
  bool hasMaterialCoordinates = false;  // a sheet, or a mesh with vt for every vertex
  double restArea = 0.0;             // m^2, sum of its triangles at rest
  std::string where;                 // the <Cloth> element's file:line
};

class ClothSystem {
 public:
  explicit ClothSystem(Device device = Device::Cpu);
  // Appends the cloth's vertices as particles and its constraints.
  // Returns the cloth's index.
  int add(const ClothSpec& spec, ParticleState& particles);
  // Colours the constraints and uploads everything (call once, after add()).
  void upload();
  bool empty() const { return objects_.empty(); }
  const std::vector<ClothObject>& objects() const { return objects_; }
  int vertexCount() const { return int(restPosition_.size()); }
  int stretchColours() const { return int(edgeColourStart_.size()) - 1; }
  int bendColours() const { return int(bendColourStart_.size()) - 1; }
  const std::vector<int>& edgeColourStart() const { return edgeColourStart_; }
  const std::vector<int>& bendColourStart() const { return bendColourStart_; }
  float maxEdgeLength() const { return maxEdgeLength_; }
  float minEdgeLength() const { return minEdgeLength_; }  // shortest rest edge of any cloth
  float maxThickness() const { return maxThickness_; }
  ClothView view();
  // Recomputes vertexSlot and clothSlots from the particles' ids and phases
  // (after a reorder); nothing waits for the device.
  void updateSlots(ParticleView p);
  // Builds the cloth's own grid from the full grid `g` just built (after
  // updateSlots); nothing waits for the device.
  void buildGrid(GridView g);
  // The grid over the cloth particles alone (GridView.h), valid until the
  // particles are sorted again: queries for cloth neighbours visit the same
  // cloth particles in the same order as through the full grid, without
  // stepping over the water around them.
  GridView grid() const { return clothGrid_; }
  // The published per-vertex fields the solves read (null where no stage
  // made them); view() carries them.
  void setFieldViews(const float* bendScale, const float* frictionScale) {
    bendScale_ = bendScale;
    frictionScale_ = frictionScale;
  }
  // Zeroes the XPBD multipliers (start of each step).
  void resetMultipliers();
  // Largest relative edge strain |l - l0| / l0 over all edges (a reduction:
  // the host waits).
  float maxStretch(ParticleView p);
  // The edges the strain stats count (a sheet's warp and weft, a mesh's
  // every edge), on the device, with their rest lengths.
  struct EdgeList {
    const ClothEdge* edges = nullptr;
    const float* rest = nullptr;
    int count = 0;
  };
  EdgeList strainEdges() const { return {dStrainEdges_.data(), dStrainEdgeRest_.data(), int(dStrainEdges_.size())}; }
  // Slot of each cloth vertex (global vertex index) in host copies of the
  // particles' ids and phases; -1 where a vertex is absent.
  std::vector<int> vertexSlots(const std::vector<int>& id, const std::vector<int>& phase) const;
  // The same maximum from host copies of the positions, with vertexSlots.
  float maxStretch(const std::vector<Float4>& position, const std::vector<int>& slots) const;
  // Strain of each cloth (ClothStrain) from host copies of the positions,
  // with vertexSlots.
  std::vector<ClothStrain> strain(const std::vector<Float4>& position, const std::vector<int>& slots) const;
  // Whether some cloth uses the PBD/XPBD constraints, or the Jacobi solve.
  bool anyColouredConstraints() const { return stretchColours() > 0 || bendColours() > 0 || anyTethers_; }
  bool anyJacobi() const { return !jacobiVertices_.empty(); }
  // Dependent phases of one constraint round of each solver: the colours
  // (+ the tethers' phase) for PBD/XPBD, one for the Jacobi solve.
  int colouredPhasesPerIteration() const { return stretchColours() + bendColours() + (anyTethers_ ? 1 : 0); }
  // Dependent constraint phases of one step: per sub-step, `iterations`
  // rounds of the colours, and `iterations` Jacobi phases plus its bend pass.
  int constraintPhasesPerStep(int iterations, int substeps) const {
    const int coloured = colouredPhasesPerIteration() > 0 ? iterations * colouredPhasesPerIteration() : 0;
    const int jacobi = anyJacobi() ? iterations + (jacobiBendCount_ > 0 ? 1 : 0) : 0;
    return substeps * (coloured + jacobi);
  }
  // Each vertex's share of its cloth's rest area (a third of each of its
  // triangles), m^2, indexed by vertex.
  std::vector<float> vertexRestAreas() const;
  // Host copy of the positions of one cloth's vertices, in vertex order.
  std::vector<Vec3> downloadVertexPositions(const ParticleState& particles, int clothIndex) const;

 private:
  void uploadJacobi();
  Device device_;
  std::vector<ClothObject> objects_;
  const float* bendScale_ = nullptr;
  const float* frictionScale_ = nullptr;
  // Host staging, in creation order until upload() colours them.
  std::vector<ClothEdge> edges_;
  std::vector<float> edgeRest_;
  std::vector<ConstraintStiffness> edgeStiffness_;
  std::vector<ClothBend> bends_;
  std::vector<float> bendRest_;
  std::vector<ConstraintStiffness> bendStiffness_;
  std::vector<ClothTriangle> triangles_;
  std::vector<Vec3> restPosition_, materialCoord_;
  std::vector<int> attach_;
  std::vector<float> thickness_;
  std::vector<int> tetherPin_;
  std::vector<float> tetherLength_;
  std::vector<unsigned char> edgeMeasured_;  // per edge (creation order): counted in strain()
  std::vector<unsigned char> jacobi_;         // per vertex: solved by the Jacobi solve
  std::vector<float> springStiffness_;  // per vertex: its cloth's chebyshev stretch stiffness (edges and limits)
  std::vector<int> jacobiVertices_;
  int jacobiBendCount_ = 0;
  std::vector<JacobiSpring> limitOf_;  // stretch limits, with limitVertex_ the vertex each belongs to
  std::vector<int> limitVertex_;
  std::vector<int> edgeColourStart_, bendColourStart_;
  float maxEdgeLength_ = 0.f, maxThickness_ = 0.f;
  float minEdgeLength_ = std::numeric_limits<float>::max();
  Buffer<ClothEdge> dEdges_;
  // Every edge of every model, for maxStretch (dEdges_ holds pbd's only).
  Buffer<ClothEdge> dMeasuredEdges_;
  Buffer<float> dMeasuredEdgeRest_;
  Buffer<ClothEdge> dStrainEdges_;  // strainEdges()
  Buffer<float> dStrainEdgeRest_;
  Buffer<float> dEdgeRest_, dEdgeLambda_;
  Buffer<ConstraintStiffness> dEdgeStiffness_;
  Buffer<ClothBend> dBends_;
  Buffer<float> dBendRest_, dBendLambda_;
  Buffer<ConstraintStiffness> dBendStiffness_;
  Buffer<ClothTriangle> dTriangles_;
  Buffer<int> dTriStart_, dTriList_, dAttach_, dSlot_, dFirstTriStart_;
  Buffer<ClothTriangle> dFirstTri_;
  Buffer<int> dFirstEdgeStart_, dFirstEdgeOther_;
  Buffer<TriangleSnapshot> dTriangleSnapshot_;
  Buffer<float> dThickness_, dTetherLength_;
  Buffer<int> dTetherPin_;
  Buffer<Vec3> dRest_, dMaterialCoord_;
  Buffer<Float4> dVertexScratch_;
  Buffer<int> dClothFlag_, dClothOffset_, dClothSlots_;  // per particle, per particle, per vertex
  bool anyTethers_ = false;  // some vertex has a tether (set by upload())
  Buffer<int> dJacobiVertices_, dSpringStart_, dBendRefStart_;
  Buffer<JacobiSpring> dSprings_;
  Buffer<JacobiBendRef> dBendRefs_;
  Buffer<ClothBend> dJacobiBends_;
  Buffer<float> dJacobiBendRest_, dJacobiBendStiffness_, dSpringStiffness_;
  Buffer<unsigned char> dSolvedByJacobi_;
  Buffer<Float4> dJacobiPrevious_, dJacobiTarget_;
  Buffer<BucketRange> dGridRange_;  // the cloth grid: per bucket
  Buffer<std::uint32_t> dGridKey_;  // the cloth grid: per vertex
  Buffer<std::uint32_t> dGridNear_;  // the cloth grid: near bits, one per bucket
  GridView clothGrid_;
  Buffer<float> scratch_;
};

}  // namespace soak
