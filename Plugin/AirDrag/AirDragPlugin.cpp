// Registration of the AirDrag plugin: declares <AirDrag> and inserts its
// stage before "predict".
#include "AirDrag.h"
#include "Pipeline/Pipeline.h"
#include "Pipeline/StageNames.h"
#include "Plugins/PluginApi.h"
#include "Registry/ParamBinding.h"
#include "Simulation/Simulation.h"

namespace {

// <AirDrag>'s parameters, with their defaults.
struct AirDragParams {
  float coefficient = 0.5f;  // 1/s
};

class AirDragModule : public soak::Module {
 public:
  explicit AirDragModule(const AirDragParams& params) : k_(params.coefficient) {}
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
  soak::ElementDecl decl("AirDrag", "Linear air drag on every free particle (example plugin).", "Plugins");
  soak::ParamBinding<AirDragParams> params(decl);
  params.real("coefficient", &AirDragParams::coefficient, "1/s", "Drag rate k in dv/dt = -k v.", 0.0, 1e4);
  registry.add(decl.makeUnique().create([params](const soak::ElementParams& p) {
    return std::make_unique<AirDragModule>(params.read(p));
  }));
}
