#pragma once
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "Backend/Device.h"
#include "Backend/DeviceMarks.h"

namespace soak {

class Simulation;

// A named piece of a step.
struct Stage {
  std::string name;
  std::function<void(Simulation&)> run;
};

// Per-stage timing, accumulated over the steps run so far.
struct StageTiming {
  std::string name;
  double totalMs = 0.0;
  long long calls = 0;
  unsigned long long launches = 0;  // operations queued on the device (launches())
  double meanMs() const { return calls ? totalMs / double(calls) : 0.0; }
  double meanLaunches() const { return calls ? double(launches) / double(calls) : 0.0; }
};

// The step: an ordered list of named, timed stages. Core adds the dry
// stages (predict, neighbours, ..., finalize; StageNames.h); modules insert
// theirs relative to a named anchor (any stage's name, core's or another
// module's).
class Pipeline {
 public:
  void append(Stage stage);
  // Outside collectFor/placeWaiting: throws std::invalid_argument naming
  // the valid anchors if `anchor` is absent, or if the stage's name is taken.
  void insertBefore(const std::string& anchor, Stage stage);
  void insertAfter(const std::string& anchor, Stage stage);

  // While the modules add their stages (Simulation::initialize), a stage
  // whose anchor is not in the step yet waits for it, so that elements may
  // stand in any order in the scene: collectFor names the element (its
  // file:line) whose stages follow; placeWaiting then places each waiting
  // stage once its anchor is in, and reports an anchor that no stage
  // provides, or a name taken twice, as bad input at that element.
  void collectFor(const std::string& where);
  void placeWaiting();
  bool has(const std::string& name) const;
  std::vector<std::string> names() const;

  // Runs every stage once. With `profile`, each stage's time is the
  // device's, between marks put on its queue before and after the stage
  // (DeviceMarks), read once the step is done: the stages' times add up to
  // the step's. Without, a stage's time is the host's time in its call (on
  // the GPU, mostly the time to queue its work).
  // `afterStage`, where given, is called with each stage's name after it ran.
  void run(Simulation& sim, Device device, bool profile,
           const std::function<void(const std::string&)>& afterStage = {});

  const std::vector<StageTiming>& timings() const { return timings_; }
  void resetTimings();

 private:
  std::size_t indexOf(const std::string& anchor) const;
  void insertAt(std::size_t index, Stage stage);
  void insertNextTo(const std::string& anchor, bool after, Stage stage);
  std::string stageList() const;
  struct Waiting {
    std::string anchor;
    bool after = false;
    Stage stage;
    std::string where;
  };
  bool collecting_ = false;
  std::string requester_;
  std::vector<Waiting> waiting_;
  std::vector<Stage> stages_;
  std::vector<StageTiming> timings_;
  std::unique_ptr<DeviceMarks> marks_;  // profile runs; made again if the device changes
};

}  // namespace soak
