#include "Pipeline/Pipeline.h"

#include <chrono>
#include <stdexcept>

#include "Registry/Module.h"

namespace soak {

double StatsRow::get(const std::string& column) const {
  for (const auto& v : values_)
    if (v.first == column) return v.second;
  throw std::out_of_range("no stats column '" + column + "'");
}

void Pipeline::insertAt(std::size_t index, Stage stage) {
  if (has(stage.name)) throw std::invalid_argument("stage '" + stage.name + "' is already in the step");
  timings_.insert(timings_.begin() + static_cast<long>(index), StageTiming{stage.name});
  stages_.insert(stages_.begin() + static_cast<long>(index), std::move(stage));
}

void Pipeline::append(Stage stage) { insertAt(stages_.size(), std::move(stage)); }

std::size_t Pipeline::indexOf(const std::string& anchor) const {
  for (std::size_t i = 0; i < stages_.size(); ++i)
    if (stages_[i].name == anchor) return i;
  std::string valid;
  for (const Stage& s : stages_) valid += (valid.empty() ? "" : ", ") + s.name;
  throw std::invalid_argument("no stage '" + anchor + "' to anchor on (stages: " + valid + ")");
}

void Pipeline::insertBefore(const std::string& anchor, Stage stage) { insertAt(indexOf(anchor), std::move(stage)); }
void Pipeline::insertAfter(const std::string& anchor, Stage stage) { insertAt(indexOf(anchor) + 1, std::move(stage)); }

bool Pipeline::has(const std::string& name) const {
  for (const Stage& s : stages_)
    if (s.name == name) return true;
  return false;
}

std::vector<std::string> Pipeline::names() const {
  std::vector<std::string> n;
  for (const Stage& s : stages_) n.push_back(s.name);
  return n;
}

void Pipeline::run(Simulation& sim, Device device, bool profile,
                   const std::function<void(const std::string&)>& afterStage) {
  using Clock = std::chrono::steady_clock;
  if (profile && (!marks_ || marks_->device() != device)) marks_ = std::make_unique<DeviceMarks>(device);
  for (std::size_t i = 0; i < stages_.size(); ++i) {
    auto t0 = Clock::now();
    const unsigned long long launchesBefore = launches();
    if (profile) marks_->mark(2 * int(i));
    stages_[i].run(sim);
    if (profile) marks_->mark(2 * int(i) + 1);
    else timings_[i].totalMs += std::chrono::duration<double, std::milli>(Clock::now() - t0).count();
    timings_[i].launches += launches() - launchesBefore;
    ++timings_[i].calls;
    if (afterStage) afterStage(stages_[i].name);
  }
  if (profile)
    for (std::size_t i = 0; i < stages_.size(); ++i) timings_[i].totalMs += marks_->elapsedMs(2 * int(i), 2 * int(i) + 1);
}

void Pipeline::resetTimings() {
  for (StageTiming& t : timings_) {
    t.totalMs = 0.0;
    t.calls = 0;
    t.launches = 0;
  }
}

}  // namespace soak
