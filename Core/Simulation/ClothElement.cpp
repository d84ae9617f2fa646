// <Cloth>: a cloth object from an OBJ mesh or a generated rectangular sheet.
#include <cmath>
#include <sstream>
#include <string>
#include <vector>

#include "Base/Error.h"
#include "Registry/ModuleRegistry.h"
#include "Registry/ParamBinding.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {

// What <Cloth> says, as the scene writes it (ClothModule turns it into a
// ClothSpec). The defaults are the scene's.
struct ClothParams {
  std::string name = "cloth";
  std::string mesh;  // as written; empty: a generated sheet
  Vec3 translate{0.f, 0.f, 0.f};
  float scale = 1.f;
  Vec3 origin{-0.6f, 1.f, -0.6f};
  Vec3 axisU{1.f, 0.f, 0.f}, axisV{0.f, 0.f, 1.f};
  float width = 1.2f, height = 1.2f;
  int cellsU = 119, cellsV = 119;
  float particleMass = 0.0066f;  // Table 1
  float supportRadius = 0.04f;   // not given: the water's h
  float thickness = 0.f;         // 0: 0.75 x mean edge length
  bool tethers = true;
  float tetherSlack = 0.f;
  ClothModel model = ClothModel::Chebyshev;  // the converging solver; pbd is the paper's
  bool stretchLimits = true;
  float stretchStiffness = 1.f, bendStiffness = 0.1f;
  float stretchCompliance = 0.f, bendCompliance = 1.f;
  std::vector<long long> pin;
  std::string pinCorners, attachTo;
};

// Vertex index of a named corner of a generated (cellsU + 1) x (cellsV + 1) sheet.
int sheetCorner(const std::string& name, int cellsU, int cellsV, const std::string& where) {
  const int nu = cellsU + 1;
  if (name == "u0v0") return 0;
  if (name == "u1v0") return cellsU;
  if (name == "u0v1") return cellsV * nu;
  if (name == "u1v1") return cellsV * nu + cellsU;
  throw InputError("<Cloth>: unknown corner '" + name + "' in pinCorners (valid: u0v0 u1v0 u0v1 u1v1)", where);
}

class ClothModule : public Module {
 public:
  ClothModule(const ElementParams& p, const ClothParams& c) : p_(p), c_(c) {}
  void configure(Simulation& sim) override {
    (c_.model == ClothModel::Pbd ? sim.clothModelsUsed.pbd : sim.clothModelsUsed.jacobiOrXpbd) = true;
  }
  void setup(Simulation& sim) override {
    const std::string& where = p_.where();
    const ClothParams& c = c_;
    ClothSpec spec;
    spec.name = c.name;
    spec.where = where;
    for (const auto& o : sim.cloth.objects())
      if (o.name == spec.name) throw InputError("<Cloth>: a cloth named '" + spec.name + "' already exists", where);
    const std::string& meshFile = c.mesh;
    const int cellsU = c.cellsU, cellsV = c.cellsV;
    if (meshFile.empty()) {
      sim.checkParticleBudget(double(cellsU + 1) * double(cellsV + 1), "<Cloth>", where);
      const Vec3 u = c.axisU, v = c.axisV;
      if (length(u) < 1e-9f || length(v) < 1e-9f || length(cross(u, v)) < 1e-6f * length(u) * length(v))
        throw InputError("<Cloth>: axisU and axisV must be non-zero and not parallel", where);
      spec.mesh = makeRectangularSheet(c.origin, u / length(u), v / length(v), c.width, c.height, cellsU, cellsV);
      spec.sheetColumns = cellsU + 1;
      spec.sheetRows = cellsV + 1;
    } else {
      spec.mesh = loadObjMesh(p_.resolvePath(meshFile));
      sim.checkParticleBudget(double(spec.mesh.vertices.size()), "<Cloth> mesh " + meshFile, where);
      spec.mesh.triangleLines.clear();  // checked against the file already; later messages name the scene
      spec.mesh.vertexLines.clear();
      for (Vec3& x : spec.mesh.vertices) x = x * c.scale + c.translate;
    }
    validateClothMesh(spec.mesh, where);
    spec.particleMass = c.particleMass;
    spec.supportRadius = p_.given("supportRadius") ? c.supportRadius : sim.water.supportRadius;
    spec.thickness = c.thickness;
    spec.tetherSlack = c.tethers ? c.tetherSlack : -1.f;
    // Eq. 5 over all the rounds of a step, so that sub-steps keep the stiffness per step.
    const int iterations = sim.settings.clothIterations * sim.settings.clothSubsteps;
    spec.model = c.model;
    if (c.model == ClothModel::Pbd && sim.settings.clothSubstepTravel > 0.f)
      throw InputError("<Cloth model=\"pbd\">: Simulation.clothSubstepTravel needs a chebyshev or xpbd cloth "
                       "(pbd's stiffness is set per iteration for a fixed number of sub-steps); for pbd add "
                       "--set Simulation.clothSubstepTravel=0",
                       where);
    if (c.model == ClothModel::Chebyshev) {
      spec.stretchStiffness = stiffnessFromCompliance(c.stretchCompliance);
      // Bending: one projection pass per sub-step (Cloth/ClothJacobi.h).
      spec.bend.kPrime = perIterationStiffness(c.bendStiffness, sim.settings.clothSubsteps);
      spec.stretchLimits = c.stretchLimits;
    } else if (c.model == ClothModel::Xpbd) {
      spec.stretch.compliance = c.stretchCompliance;
      spec.bend.compliance = c.bendCompliance;
    } else {
      spec.stretch.kPrime = perIterationStiffness(c.stretchStiffness, iterations);
      spec.bend.kPrime = perIterationStiffness(c.bendStiffness, iterations);
    }
    const int nv = int(spec.mesh.vertices.size());
    for (long long v : c.pin) {
      if (v < 0 || v >= nv)
        throw InputError("<Cloth>: pin index " + std::to_string(v) + " out of range (the mesh has " +
                             std::to_string(nv) + " vertices)",
                         where);
      spec.pinned.push_back(int(v));
    }
    std::istringstream corners(c.pinCorners);
    for (std::string corner; corners >> corner;) {
      if (!meshFile.empty())
        throw InputError("<Cloth>: pinCorners applies to generated sheets; use pin=\"indices\" with a mesh", where);
      spec.pinned.push_back(sheetCorner(corner, cellsU, cellsV, where));
    }
    const std::string& attach = c.attachTo;
    if (!attach.empty()) {
      for (std::size_t k = 0; k < sim.colliderNames.size(); ++k)
        if (sim.colliderNames[k] == attach) spec.attachCollider = int(k);
      if (spec.attachCollider < 0)
        throw InputError("<Cloth>: no collider named '" + attach +
                             "' (give the collider a name and put it before the cloth in the scene)",
                         where);
      if (spec.pinned.empty())
        throw InputError("<Cloth>: attachTo needs pinned vertices (pin or pinCorners) to attach", where);
    }
    sim.cloth.add(spec, sim.particles);
    sim.raiseSupportRadius(spec.supportRadius);
    sim.checkCellOccupancy();
  }

 private:
  ElementParams p_;
  ClothParams c_;
};

}  // namespace

void registerClothElement(ModuleRegistry& r) {
  ElementDecl decl("Cloth",
                   "A piece of cloth: a triangle mesh from an OBJ file, or a generated rectangular sheet of "
                   "(cellsU + 1) x (cellsV + 1) vertices. Each vertex is a cloth particle (Section 3.2).",
                   "Cloth");
  // Each parameter bound to its ClothParams member (Registry/ParamBinding.h).
  ParamBinding<ClothParams> cloth(decl);
  using C = ClothParams;
  cloth.fileSafeName("name", &C::name, "Name (output file cloth_<name>.pvd); unique per scene.")
      .inputFile("mesh", &C::mesh, "OBJ file (relative to the scene); empty: a generated sheet.")
      .vector("translate", &C::translate, "m", "Mesh only: translation applied after scaling.")
      .real("scale", &C::scale, "", "Mesh only: uniform scale.", 0.0, 1e6, true)
      .vector("origin", &C::origin, "m", "Sheet only: corner u0v0.")
      .vector("axisU", &C::axisU, "", "Sheet only: direction of the first side.")
      .vector("axisV", &C::axisV, "", "Sheet only: direction of the second side.")
      .real("width", &C::width, "m", "Sheet only: length along axisU.", 0.0, 1e4, true)
      .real("height", &C::height, "m", "Sheet only: length along axisV.", 0.0, 1e4, true)
      .integer("cellsU", &C::cellsU, "Sheet only: cells along axisU (vertices = cells + 1).", 1, 100000)
      .integer("cellsV", &C::cellsV, "Sheet only: cells along axisV.", 1, 100000)
      .real("particleMass", &C::particleMass, "kg", "Mass of a cloth particle (Table 1).", 0.0, 1e6, true)
      .real("supportRadius", &C::supportRadius, "m",
            "Support radius of cloth particles as water boundary (default: the water's h).", 0.0, 10.0, true)
      .real("thickness", &C::thickness, "m",
            "Contact distance between cloth layers; d of Eq. 21 is half of it. 0: 0.75 x mean edge length.", 0.0,
            10.0)
      .boolean("tethers", &C::tethers,
               "Long-range attachments: no vertex moves further from its nearest pins than its rest "
               "distance x (1 + tetherSlack); keeps hanging cloth from over-stretching at few iterations.")
      .real("tetherSlack", &C::tetherSlack, "",
            "Relative slack of the tethers (a sheet pinned at four corners sags only by this much).", 0.0, 10.0)
      .choice<ClothModel>("model", &C::model,
                          {{"pbd", ClothModel::Pbd}, {"xpbd", ClothModel::Xpbd}, {"chebyshev", ClothModel::Chebyshev}},
                          "The cloth solver. chebyshev (the default): Jacobi iterations on the implicit-Euler "
                          "energy with Chebyshev acceleration (one dependent phase per iteration; Doc/model.md, "
                          "\"Cloth solvers\"): stretch from stretchCompliance, bending from bendStiffness, applied "
                          "once per sub-step; with the Simulation's counts left to the solver it takes sub-steps "
                          "of 12 iterations, 4 at the start, more when the cloth moves fast or its strain passes 2 %, "
                          "down to 2 where it stays low. pbd: the paper's Gauss-Seidel PBD over "
                          "constraint colours, stiffness in [0, 1] with the per-iteration factor of Eq. 5 (1 x 8 "
                          "by default; for reproducing the paper: it stretches 5-10 times as much); xpbd: the same "
                          "with compliance.")
      .boolean("stretchLimits", &C::stretchLimits,
               "chebyshev: keep each vertex within the rest length of the path to the vertices 2, 4, 8, ... "
               "edges away along its lines: a generated sheet's rows and columns, a mesh's straightest lines of "
               "edges (each turning by at most 35 degrees at a vertex). No fold or bend lengthens a path on "
               "the cloth, so they never resist folding, draping or unrolling; they carry the resistance to "
               "stretch across the cloth in few iterations. false: only the edges (and tethers) resist "
               "stretch.")
      .real("stretchStiffness", &C::stretchStiffness, "", "PBD stiffness of the stretch constraint (Eq. 8).", 0.0,
            1.0)
      .real("bendStiffness", &C::bendStiffness, "", "pbd, chebyshev: stiffness of the bending constraint (Eq. 9).",
            0.0, 1.0)
      .real("stretchCompliance", &C::stretchCompliance, "m/N",
            "xpbd, chebyshev: compliance of the stretch constraint (0: inextensible).", 0.0, 1e6)
      .real("bendCompliance", &C::bendCompliance, "1/(N m)", "xpbd: compliance of the bending constraint.", 0.0,
            1e6);
  cloth.integerList("pin", &C::pin, "Vertex indices held in place (inverse mass 0).")
      .text("pinCorners", &C::pinCorners, "Sheet only: corners held in place, from u0v0 u1v0 u0v1 u1v1.")
      .text("attachTo", &C::attachTo, "Name of a collider the pinned vertices move with.");
  r.add(decl.create([cloth](const ElementParams& p) { return std::make_unique<ClothModule>(p, cloth.read(p)); }));
}

}  // namespace soak
