// Registration of the Wring test plugin: its element, and its stage table
// (one row: the stage, where it goes, the function that runs it).
#include "Pipeline/StageTable.h"
#include "Plugins/PluginApi.h"
#include "Registry/ParamBinding.h"
#include "Simulation/Simulation.h"
#include "Stages/WetStages.h"
#include "Wring.h"

namespace {

const soak::StageRow<wring::WringState> kWringStages[] = {
    {"wring.squeeze", soak::Place::After, soak::wet::kDiffuseStage, wring::runSqueeze},
};

class WringModule : public soak::Module {
 public:
  explicit WringModule(const wring::WringState& state) : state_(state) {}
  void addStages(soak::Pipeline& pipeline, soak::Simulation&) override {
    soak::addStageTable(pipeline, state_, kWringStages);
  }

 private:
  wring::WringState state_;
};

}  // namespace

SOAK_PLUGIN(Wring) {
  soak::ElementDecl decl("Wring", "Wrings cloth above a saturation into its emission buffer (test plugin).", "Plugins");
  soak::ParamBinding<wring::WringState> params(decl);
  params.real("cap", &wring::WringState::cap, "", "The most saturation a cloth particle keeps after wet.diffuse.", 0.0,
              1.0);
  registry.add(decl.makeUnique().create(
      [params](const soak::ElementParams& p) { return std::make_unique<WringModule>(params.read(p)); }));
}
