// The output elements Core provides: <Camera>, <Output>, <WaterSurface>.
#include <algorithm>
#include <cmath>

#include "Base/Error.h"
#include "Base/MessageText.h"
#include "Registry/ModuleRegistry.h"
#include "Simulation/ElementGroups.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {

// <Camera> is read by Doc/render.py; the simulation ignores it.
class CameraModule : public Module {};

class OutputModule : public Module {
 public:
  explicit OutputModule(const ElementParams& p) : p_(p) {}
  void configure(Simulation& sim) override {
    const std::string c = p_.text("compression");
    OutputSettings& o = sim.settings.output;
    o.compression = c == "none" ? Compression::None
                    : c == "zlib" ? Compression::ZLib
                    : c == "lzma" ? Compression::LZMA
                                  : Compression::LZ4;
    o.writerThreads = int(p_.integer("writerThreads"));
    o.queuedFrames = int(p_.integer("queuedFrames"));
    o.vdb = p_.boolean("vdb");
    o.ply = p_.boolean("ply");
    o.plyColour = p_.text("plyColour");
  }
  // Every module's setup has run: the channels the plugins add exist.
  void addStages(Pipeline&, Simulation& sim) override {
    OutputSettings& o = sim.settings.output;
    if (!o.ply || o.plyColour.empty()) return;
    const ParticleState& ps = sim.particles;
    if (!p_.given("plyColour")) {  // the default colours by saturation where the scene has it
      bool found = false;
      for (int c = 0; c < ps.channelCount(); ++c) found = found || ps.channelName(c) == o.plyColour;
      if (!found) o.plyColour.clear();
      return;
    }
    std::vector<std::string> names;
    for (int c = 0; c < ps.channelCount(); ++c) names.push_back(ps.channelName(c));
    if (std::find(names.begin(), names.end(), o.plyColour) != names.end()) return;
    std::string list;
    for (const std::string& n : names) list += (list.empty() ? "" : ", ") + n;
    throw InputError("<Output>: plyColour '" + o.plyColour + "' is not a channel of this scene (" +
                         (list.empty() ? std::string("it has none") : "its channels: " + list) +
                         "); name one, or set plyColour=\"\" for no colours",
                     p_.where());
  }

 private:
  ElementParams p_;
};

class WaterSurfaceModule : public Module {
 public:
  explicit WaterSurfaceModule(const ElementParams& p) : p_(p) {}
  void configure(Simulation& sim) override {
    sim.settings.surfaceCellSize = p_.realf("cellSize");
    sim.settings.surfaceIso = p_.realf("iso");
  }
  // Each water particle adds its kernel to the grid points within its
  // support radius: (2 h / cellSize + 1)^3 of them.
  void setup(Simulation& sim) override {
    const double across = 2.0 * double(sim.water.supportRadius) / double(sim.settings.surfaceCellSize) + 1.0;
    if (across * across * across > double(kMaxSplatPoints))
      throw InputError("<WaterSurface>: cellSize " + formatNumber(sim.settings.surfaceCellSize) +
                           " m is too fine for the support radius " + formatNumber(sim.water.supportRadius) +
                           " m: each particle would touch " + formatNumber(across * across * across) +
                           " grid points, more than " + std::to_string(kMaxSplatPoints) +
                           "; use a cellSize of at least " +
                           formatNumber(2.0 * double(sim.water.supportRadius) / (std::cbrt(double(kMaxSplatPoints)) - 1.0)) +
                           " m",
                       p_.where());
  }
  static constexpr long long kMaxSplatPoints = 32768;

 private:
  ElementParams p_;
};

}  // namespace

void registerOutputElements(ModuleRegistry& r) {
  r.add(ElementDecl("Camera",
                    "The view Doc/render.py (soak's ParaView script) draws this scene from; the simulation "
                    "ignores it.",
                    "Output")
            .vector("position", "m", "0 1 4", "Where the camera is.")
            .vector("focus", "m", "0 0.8 0", "The point it looks at.")
            .vector("up", "", "0 1 0", "Which way is up on the picture.")
            .real("viewAngle", "deg", "30", "Vertical field of view.", 1.0, 170.0)
            .makeUnique()
            .create([](const ElementParams&) { return std::make_unique<CameraModule>(); }));
  r.add(ElementDecl("Output",
                    "How frames are written: the compressor of the VTK files, OpenVDB and PLY copies for "
                    "Houdini and Blender, and the background threads that write them while the simulation goes "
                    "on (Doc/output.md).",
                    "Output")
            .choice("compression", {"lz4", "zlib", "lzma", "none"}, "lz4",
                    "Compressor of the .vtu/.vtp files (Doc/output.md measures MB and ms per frame of each).")
            .integer("writerThreads", "-1",
                     "Threads that build and write frame files in the background; 0 writes them on the stepping "
                     "thread; -1 chooses: 8 when the simulation runs on the GPU, 1 on the CPU (Doc/output.md).",
                     -1, 64)
            .integer("queuedFrames", "8",
                     "Frames captured and not yet written before a step waits for the disk.", 1, 1000)
            .boolean("vdb", "false",
                     "Also write the water as OpenVDB, water_vdb/water_NNNNNN.vdb: a level set \"surface\" (the "
                     "<WaterSurface> splat and iso; without that element a cell of 0.7 r0 and iso 0.5) and a points "
                     "grid \"particles\" with v, pscale and id (Doc/output.md: loading in Houdini and Blender).")
            .boolean("ply", "false",
                     "Also write each cloth as binary PLY, cloth_<name>_ply/cloth_<name>_NNNNNN.ply, with velocity, "
                     "every channel and a vertex colour per vertex.")
            .text("plyColour", "saturation",
                  "Channel the PLY vertex colours show, white at 0 to deep blue at 1 (empty: no colours; the "
                  "default colours by saturation where the scene has that channel, and not at all otherwise).")
            .makeUnique()
            .create([](const ElementParams& p) { return std::make_unique<OutputModule>(p); }));
  r.add(ElementDecl("WaterSurface",
                    "Writes a water surface mesh per frame (water_surface.pvd): the particles' relative density "
                    "splatted on a grid and contoured with flying edges (VTK).",
                    "Output")
            .real("cellSize", "m", "0.014", "Grid cell (the paper: about 0.7 r0).", 0.0, 10.0, true)
            .real("iso", "", "0.5", "Relative density (rho / rho0) of the surface.", 0.0, 10.0, true)
            .makeUnique()
            .create([](const ElementParams& p) { return std::make_unique<WaterSurfaceModule>(p); }));
}

}  // namespace soak
