// Registration of the AirDrag plugin: declares <AirDrag> and inserts its
// stage before "predict".
#include "AirDrag.h"
#include "Pipeline/Pipeline.h"
#include "Pipeline/StageNames.h"
#include "Plugins/PluginApi.h"
#include "Simulation/Simulation.h"

namespace {

class AirDragModule : public soak::Module {
 public:
  explicit AirDragModule(float k) : k_(k) {}
  void addStages(soak::Pipeline& pipeline, soak::Simulation&) override {
    const float k = k_;
    pipeline.insertBefore(soak::stage::kPredict, {"airdrag.apply", [k](soak::Simulation& s) {
                                        soak::airdrag::applyAirDrag(s.device(), s.particles.view(), k,
                                                                    s.settings.timeStep);
                                      }});
  }

 private:
  float k_;
};

}  // namespace

SOAK_PLUGIN(AirDrag) {
  registry.add(soak::ElementDecl("AirDrag", "Linear air drag on every free particle (example plugin).", "Plugins")
                   .real("coefficient", "1/s", "0.5", "Drag rate k in dv/dt = -k v.", 0.0, 1e4)
                   .makeUnique()
                   .create([](const soak::ElementParams& p) {
                     return std::make_unique<AirDragModule>(p.realf("coefficient"));
                   }));
}
