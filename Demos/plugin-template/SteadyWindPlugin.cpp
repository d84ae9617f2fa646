// Registration of the SteadyWind plugin: the <SteadyWind> element, its
// parameters, and its stage, run before the core's "predict".
#include "Pipeline/Pipeline.h"
#include "Pipeline/StageNames.h"
#include "Plugins/PluginApi.h"
#include "Registry/ParamBinding.h"
#include "Simulation/Simulation.h"
#include "SteadyWind.h"

namespace {

// <SteadyWind>'s parameters, with their defaults.
struct SteadyWindParams {
  soak::Vec3 velocity{1.f, 0.f, 0.f};  // m/s
  float rate = 2.f;                    // 1/s
};

class SteadyWindModule : public soak::Module {
 public:
  explicit SteadyWindModule(const SteadyWindParams& p) : wind_(p.velocity), rate_(p.rate) {}
  void addStages(soak::Pipeline& pipeline, soak::Simulation&) override {
    const soak::Vec3 wind = wind_;
    const float rate = rate_;
    pipeline.insertBefore(soak::stage::kPredict, {"wind.relax", [wind, rate](soak::Simulation& s) {
                                        steadywind::relaxTowardWind(s.device(), s.particles.view(), wind, rate,
                                                                    float(s.settings.timeStep));
                                      }});
  }

 private:
  soak::Vec3 wind_;
  float rate_;
};

}  // namespace

SOAK_PLUGIN(SteadyWind) {
  soak::ElementDecl decl("SteadyWind", "A steady wind that free particles relax toward (template plugin).", "Plugins");
  soak::ParamBinding<SteadyWindParams> params(decl);
  params.vector("velocity", &SteadyWindParams::velocity, "m/s", "Wind velocity w.")
      .real("rate", &SteadyWindParams::rate, "1/s", "Relaxation rate k in dv/dt = k (w - v).", 0.0, 1e4);
  registry.add(decl.makeUnique().create([params](const soak::ElementParams& p) {
    return std::make_unique<SteadyWindModule>(params.read(p));
  }));
}
