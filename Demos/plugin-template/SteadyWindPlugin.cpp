// Registration of the SteadyWind plugin: the <SteadyWind> element, its
// parameters, and its stage, run before the core's "predict".
#include "Pipeline/Pipeline.h"
#include "Pipeline/StageNames.h"
#include "Plugins/PluginApi.h"
#include "Simulation/Simulation.h"
#include "SteadyWind.h"

namespace {

class SteadyWindModule : public soak::Module {
 public:
  SteadyWindModule(soak::Vec3 wind, float rate) : wind_(wind), rate_(rate) {}
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
  registry.add(soak::ElementDecl("SteadyWind", "A steady wind that free particles relax toward (template plugin).",
                                 "Plugins")
                   .vector("velocity", "m/s", "1 0 0", "Wind velocity w.")
                   .real("rate", "1/s", "2", "Relaxation rate k in dv/dt = k (w - v).", 0.0, 1e4)
                   .makeUnique()
                   .create([](const soak::ElementParams& p) {
                     return std::make_unique<SteadyWindModule>(p.vector("velocity"), p.realf("rate"));
                   }));
}
