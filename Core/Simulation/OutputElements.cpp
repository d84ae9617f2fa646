// The output elements Core provides: <Camera>, <Output>, <WaterSurface>, <Catalyst>.
#include <algorithm>
#include <cmath>

#include "Base/Error.h"
#include "Base/MessageText.h"
#include "Registry/ModuleRegistry.h"
#include "Registry/ParamBinding.h"
#include "Simulation/ElementGroups.h"
#include "Simulation/Simulation.h"

namespace soak {

namespace {

// <Camera>'s parameters: read by Doc/render.py; the simulation checks and ignores them.
struct CameraParams {
  Vec3 position{0.f, 1.f, 4.f};
  Vec3 focus{0.f, 0.8f, 0.f};
  Vec3 up{0.f, 1.f, 0.f};
  float viewAngle = 30.f;
};
class CameraModule : public Module {};

class OutputModule : public Module {
 public:
  OutputModule(const ElementParams& p, const OutputSettings& o) : p_(p), o_(o) {}
  void configure(Simulation& sim) override { sim.settings.output = o_; }
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
  OutputSettings o_;
};

class WaterSurfaceModule : public Module {
 public:
  WaterSurfaceModule(const WaterSurfaceSettings& s, std::string where) : s_(s), where_(std::move(where)) {}
  void configure(Simulation& sim) override { sim.settings.surface = s_; }
  // Each water particle adds its kernel to the grid points within its
  // support radius: (2 h / cellSize + 1)^3 of them.
  void setup(Simulation& sim) override {
    const double across = 2.0 * double(sim.water.supportRadius) / double(s_.cellSize) + 1.0;
    if (across * across * across > double(kMaxSplatPoints))
      throw InputError("<WaterSurface>: cellSize " + formatNumber(s_.cellSize) +
                           " m is too fine for the support radius " + formatNumber(sim.water.supportRadius) +
                           " m: each particle would touch " + formatNumber(across * across * across) +
                           " grid points, more than " + std::to_string(kMaxSplatPoints) +
                           "; use a cellSize of at least " +
                           formatNumber(2.0 * double(sim.water.supportRadius) / (std::cbrt(double(kMaxSplatPoints)) - 1.0)) +
                           " m",
                       where_);
  }
  static constexpr long long kMaxSplatPoints = 32768;

 private:
  WaterSurfaceSettings s_;
  std::string where_;
};

// <Catalyst>'s parameters, as the scene writes them.
struct CatalystParams {
  std::string script;
  int every = 1;
  std::string live;
};

class CatalystModule : public Module {
 public:
  explicit CatalystModule(CatalystSettings s) : s_(std::move(s)) {}
  void configure(Simulation& sim) override { sim.settings.catalyst = s_; }

 private:
  CatalystSettings s_;
};

}  // namespace

void registerOutputElements(ModuleRegistry& r) {
  {
    ElementDecl decl("Camera",
                     "The view Doc/render.py (soak's ParaView script) draws this scene from; the simulation "
                     "ignores it.",
                     "Output");
    ParamBinding<CameraParams> camera(decl);
    camera.vector("position", &CameraParams::position, "m", "Where the camera is.")
        .vector("focus", &CameraParams::focus, "m", "The point it looks at.")
        .vector("up", &CameraParams::up, "", "Which way is up on the picture.")
        .real("viewAngle", &CameraParams::viewAngle, "deg", "Vertical field of view.", 1.0, 170.0);
    r.add(decl.makeUnique().create([](const ElementParams&) { return std::make_unique<CameraModule>(); }));
  }
  {
    ElementDecl decl("Output",
                     "How frames are written: the compressor of the VTK files, OpenVDB and PLY copies for "
                     "Houdini and Blender, and the background threads that write them while the simulation goes "
                     "on (Doc/output.md).",
                     "Output");
    ParamBinding<OutputSettings> output(decl);
    using O = OutputSettings;
    output
        .choice("compression", &O::compression,
                {{"lz4", Compression::LZ4}, {"zlib", Compression::ZLib}, {"lzma", Compression::LZMA},
                 {"none", Compression::None}},
                "Compressor of the .vtu/.vtp files (Doc/output.md measures MB and ms per frame of each).")
        .integer("writerThreads", &O::writerThreads,
                 "Threads that build and write frame files in the background; 0 writes them on the stepping "
                 "thread; -1 chooses: 8 when the simulation runs on the GPU, 1 on the CPU (Doc/output.md).",
                 -1, 64)
        .integer("queuedFrames", &O::queuedFrames, "Frames captured and not yet written before a step waits for the disk.",
                 1, 1000)
        .boolean("vdb", &O::vdb,
                 "Also write the water as OpenVDB, water_vdb/water_NNNNNN.vdb: a level set \"surface\" (the "
                 "<WaterSurface> splat and iso; without that element a cell of 0.7 r0 and iso 0.5) and a points "
                 "grid \"particles\" with v, pscale and id (Doc/output.md: loading in Houdini and Blender).")
        .boolean("ply", &O::ply,
                 "Also write each cloth as binary PLY, cloth_<name>_ply/cloth_<name>_NNNNNN.ply, with velocity, "
                 "every channel and a vertex colour per vertex.")
        .text("plyColour", &O::plyColour,
              "Channel the PLY vertex colours show, white at 0 to deep blue at 1 (empty: no colours; the "
              "default colours by saturation where the scene has that channel, and not at all otherwise).");
    r.add(decl.makeUnique().create(
        [output](const ElementParams& p) { return std::make_unique<OutputModule>(p, output.read(p)); }));
  }
  {
    ElementDecl decl("WaterSurface",
                     "Writes a water surface mesh per frame (water_surface.pvd): the particles' relative density "
                     "splatted on a grid and contoured with flying edges (VTK).",
                     "Output");
    ParamBinding<WaterSurfaceSettings> surface(decl);
    surface.real("cellSize", &WaterSurfaceSettings::cellSize, "m", "Grid cell (the paper: about 0.7 r0).", 0.0, 10.0, true)
        .real("iso", &WaterSurfaceSettings::iso, "", "Relative density (rho / rho0) of the surface.", 0.0, 10.0, true);
    r.add(decl.makeUnique().create([surface](const ElementParams& p) {
      return std::make_unique<WaterSurfaceModule>(surface.read(p), p.where());
    }));
  }
  {
    ElementDecl decl("Catalyst",
                     "Runs ParaView Catalyst Python scripts on the frames while the simulation goes on (pictures, "
                     "extracts, in situ), and connects to a ParaView GUI for Catalyst Live; `soak run --catalyst "
                     "SCRIPT.py --live HOST:PORT` does the same (Doc/paraview.md, \"In situ and live\").",
                     "Output");
    ParamBinding<CatalystParams> catalyst(decl);
    catalyst
        .inputFile("script", &CatalystParams::script,
                   "Catalyst Python script (ParaView 5.9+: File > Save Catalyst State, or by hand), relative to the "
                   "scene; empty: none (Live only).")
        .integer("every", &CatalystParams::every, "Run the scripts (and send Live) on every N-th output frame.", 1,
                 1000000)
        .text("live", &CatalystParams::live,
              "HOST:PORT of a ParaView GUI listening on Catalyst > Connect (port 22222 by default); empty: no Live.");
    r.add(decl.makeUnique().create([catalyst](const ElementParams& p) {
      const CatalystParams c = catalyst.read(p);
      CatalystSettings s;
      if (!c.script.empty()) s.scripts.push_back(p.resolvePath(c.script));
      s.every = c.every;
      s.live = c.live;
      s.where = p.where();
      if (!s.live.empty()) parseLiveAddress(s.live, p.where());
      if (!s.wanted())
        throw InputError("<Catalyst> needs a script, a live address, or both", p.where());
      return std::make_unique<CatalystModule>(s);
    }));
  }
}

}  // namespace soak
