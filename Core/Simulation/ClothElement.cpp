// <Cloth>: a cloth object from an OBJ mesh or a generated rectangular sheet.
#include <cmath>
#include <sstream>

#include "Base/Error.h"
#include "Registry/ModuleRegistry.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {

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
  explicit ClothModule(const ElementParams& p) : p_(p) {}
  void setup(Simulation& sim) override {
    const std::string& where = p_.where();
    ClothSpec spec;
    spec.name = p_.text("name");
    spec.where = where;
    for (const auto& o : sim.cloth.objects())
      if (o.name == spec.name) throw InputError("<Cloth>: a cloth named '" + spec.name + "' already exists", where);
    const std::string meshFile = p_.text("mesh");
    const int cellsU = int(p_.integer("cellsU")), cellsV = int(p_.integer("cellsV"));
    if (meshFile.empty()) {
      sim.checkParticleBudget(double(cellsU + 1) * double(cellsV + 1), "<Cloth>", where);
      Vec3 u = p_.vector("axisU"), v = p_.vector("axisV");
      if (length(u) < 1e-9f || length(v) < 1e-9f || length(cross(u, v)) < 1e-6f * length(u) * length(v))
        throw InputError("<Cloth>: axisU and axisV must be non-zero and not parallel", where);
      spec.mesh = makeRectangularSheet(p_.vector("origin"), u / length(u), v / length(v), p_.realf("width"),
                                       p_.realf("height"), cellsU, cellsV);
      spec.sheetColumns = cellsU + 1;
      spec.sheetRows = cellsV + 1;
    } else {
      spec.mesh = loadObjMesh(p_.resolvePath(meshFile));
      sim.checkParticleBudget(double(spec.mesh.vertices.size()), "<Cloth> mesh " + meshFile, where);
      spec.mesh.triangleLines.clear();  // checked against the file already; later messages name the scene
      const float scale = p_.realf("scale");
      const Vec3 t = p_.vector("translate");
      for (Vec3& x : spec.mesh.vertices) x = x * scale + t;
    }
    validateClothMesh(spec.mesh, where);
    spec.particleMass = p_.realf("particleMass");
    spec.supportRadius = p_.given("supportRadius") ? p_.realf("supportRadius") : sim.water.supportRadius;
    spec.thickness = p_.realf("thickness");
    spec.tetherSlack = p_.boolean("tethers") ? p_.realf("tetherSlack") : -1.f;
    // Eq. 5 over all the rounds of a step, so that sub-steps keep the stiffness per step.
    const int iterations = sim.settings.clothIterations * sim.settings.clothSubsteps;
    const std::string model = p_.text("model");
    if (model == "chebyshev") {
      spec.model = ClothModel::Chebyshev;
      spec.stretchStiffness = stiffnessFromCompliance(p_.realf("stretchCompliance"));
      // Bending: one projection pass per sub-step (Cloth/ClothJacobi.h).
      spec.bend.kPrime = perIterationStiffness(p_.realf("bendStiffness"), sim.settings.clothSubsteps);
      spec.stretchLimits = p_.boolean("stretchLimits");
    } else if (model == "xpbd") {
      spec.model = ClothModel::Xpbd;
      spec.stretch.compliance = p_.realf("stretchCompliance");
      spec.bend.compliance = p_.realf("bendCompliance");
    } else {
      spec.stretch.kPrime = perIterationStiffness(p_.realf("stretchStiffness"), iterations);
      spec.bend.kPrime = perIterationStiffness(p_.realf("bendStiffness"), iterations);
    }
    const int nv = int(spec.mesh.vertices.size());
    for (long long v : p_.integerList("pin")) {
      if (v < 0 || v >= nv)
        throw InputError("<Cloth>: pin index " + std::to_string(v) + " out of range (the mesh has " +
                             std::to_string(nv) + " vertices)",
                         where);
      spec.pinned.push_back(int(v));
    }
    std::istringstream corners(p_.text("pinCorners"));
    for (std::string c; corners >> c;) {
      if (!meshFile.empty())
        throw InputError("<Cloth>: pinCorners applies to generated sheets; use pin=\"indices\" with a mesh", where);
      spec.pinned.push_back(sheetCorner(c, cellsU, cellsV, where));
    }
    const std::string attach = p_.text("attachTo");
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
};

}  // namespace

void registerClothElement(ModuleRegistry& r) {
  r.add(ElementDecl("Cloth",
                    "A piece of cloth: a triangle mesh from an OBJ file, or a generated rectangular sheet of "
                    "(cellsU + 1) x (cellsV + 1) vertices. Each vertex is a cloth particle (Section 3.2).",
                    "Cloth")
            .fileSafeName("name", "cloth", "Name (output file cloth_<name>.pvd); unique per scene.")
            .inputFile("mesh", "", "OBJ file (relative to the scene); empty: a generated sheet.")
            .vector("translate", "m", "0 0 0", "Mesh only: translation applied after scaling.")
            .real("scale", "", "1", "Mesh only: uniform scale.", 0.0, 1e6, true)
            .vector("origin", "m", "-0.6 1 -0.6", "Sheet only: corner u0v0.")
            .vector("axisU", "", "1 0 0", "Sheet only: direction of the first side.")
            .vector("axisV", "", "0 0 1", "Sheet only: direction of the second side.")
            .real("width", "m", "1.2", "Sheet only: length along axisU.", 0.0, 1e4, true)
            .real("height", "m", "1.2", "Sheet only: length along axisV.", 0.0, 1e4, true)
            .integer("cellsU", "119", "Sheet only: cells along axisU (vertices = cells + 1).", 1, 100000)
            .integer("cellsV", "119", "Sheet only: cells along axisV.", 1, 100000)
            .real("particleMass", "kg", "0.0066", "Mass of a cloth particle (Table 1).", 0.0, 1e6, true)
            .real("supportRadius", "m", "0.04",
                  "Support radius of cloth particles as water boundary (default: the water's h).", 0.0, 10.0, true)
            .real("thickness", "m", "0",
                  "Contact distance between cloth layers; d of Eq. 21 is half of it. 0: 0.75 x mean edge length.",
                  0.0, 10.0)
            .boolean("tethers", "true",
                     "Long-range attachments: no vertex moves further from its nearest pins than its rest "
                     "distance x (1 + tetherSlack); keeps hanging cloth from over-stretching at few iterations.")
            .real("tetherSlack", "", "0", "Relative slack of the tethers (a sheet pinned at four corners sags only by this much).", 0.0, 10.0)
            .choice("model", {"pbd", "xpbd", "chebyshev"}, "pbd",
                    "The cloth solver. pbd: the paper's Gauss-Seidel PBD over constraint colours, stiffness in "
                    "[0, 1] with the per-iteration factor of Eq. 5; xpbd: the same with compliance; chebyshev: "
                    "Jacobi iterations on the implicit-Euler energy with Chebyshev acceleration (one dependent "
                    "phase per iteration; Doc/model.md, \"Cloth solvers\"): stretch from stretchCompliance, "
                    "bending from bendStiffness, applied once per sub-step.")
            .boolean("stretchLimits", "true",
                     "chebyshev, generated sheets: keep each vertex within its rest distance of the vertices 2, 4, "
                     "8, ... apart along its row and column. They never resist folding (on a sheet cut flat no "
                     "fold lengthens them) and carry the resistance to stretch across the sheet in few "
                     "iterations.")
            .real("stretchStiffness", "", "1", "PBD stiffness of the stretch constraint (Eq. 8).", 0.0, 1.0)
            .real("bendStiffness", "", "0.1", "pbd, chebyshev: stiffness of the bending constraint (Eq. 9).", 0.0, 1.0)
            .real("stretchCompliance", "m/N", "0",
                  "xpbd, chebyshev: compliance of the stretch constraint (0: inextensible).", 0.0, 1e6)
            .real("bendCompliance", "1/(N m)", "1", "xpbd: compliance of the bending constraint.", 0.0,
                  1e6)
            .integerList("pin", "", "Vertex indices held in place (inverse mass 0).")
            .text("pinCorners", "", "Sheet only: corners held in place, from u0v0 u1v0 u0v1 u1v1.")
            .text("attachTo", "", "Name of a collider the pinned vertices move with.")
            .create([](const ElementParams& p) { return std::make_unique<ClothModule>(p); }));
}

}  // namespace soak
