#include "Pipeline/Pipeline.h"

#include <chrono>
#include <stdexcept>

#include "Base/Error.h"
#include "Registry/Module.h"

namespace soak {

double StatsRow::get(const std::string& column) const {
  for (const auto& v : values_)
    if (v.first == column) return v.second;
  throw std::out_of_range("no stats column '" + column + "'");
}

void Pipeline::insertAt(std::size_t index, Stage stage) {
  if (has(stage.name)) {
    const std::string message = "stage '" + stage.name + "' is already in the step";
    if (collecting_) throw InputError(message + " (an element that adds it appears twice?)", requester_);
    throw std::invalid_argument(message);
  }
  timings_.insert(timings_.begin() + static_cast<long>(index), StageTiming{stage.name});
  stages_.insert(stages_.begin() + static_cast<long>(index), std::move(stage));
}

void Pipeline::append(Stage stage) { insertAt(stages_.size(), std::move(stage)); }

std::string Pipeline::stageList() const {
  std::string valid;
  for (const Stage& s : stages_) valid += (valid.empty() ? "" : ", ") + s.name;
  return valid;
}

std::size_t Pipeline::indexOf(const std::string& anchor) const {
  for (std::size_t i = 0; i < stages_.size(); ++i)
    if (stages_[i].name == anchor) return i;
  throw std::invalid_argument("no stage '" + anchor + "' to anchor on (stages: " + stageList() + ")");
}

void Pipeline::insertNextTo(const std::string& anchor, bool after, Stage stage) {
  if (collecting_ && !has(anchor)) {
    waiting_.push_back({anchor, after, std::move(stage), requester_});
    return;
  }
  insertAt(indexOf(anchor) + (after ? 1 : 0), std::move(stage));
}

void Pipeline::insertBefore(const std::string& anchor, Stage stage) { insertNextTo(anchor, false, std::move(stage)); }
void Pipeline::insertAfter(const std::string& anchor, Stage stage) { insertNextTo(anchor, true, std::move(stage)); }

void Pipeline::collectFor(const std::string& where) {
  collecting_ = true;
  requester_ = where;
}

// Rounds over the waiting stages, in the order they were asked for: each
// round places those whose anchor is in; a round that places none leaves
// only anchors that nothing provides.
void Pipeline::placeWaiting() {
  for (bool placed = true; placed && !waiting_.empty();) {
    placed = false;
    for (std::size_t i = 0; i < waiting_.size();) {
      if (!has(waiting_[i].anchor)) {
        ++i;
        continue;
      }
      Waiting w = std::move(waiting_[i]);
      waiting_.erase(waiting_.begin() + static_cast<long>(i));
      requester_ = w.where;
      insertAt(indexOf(w.anchor) + (w.after ? 1 : 0), std::move(w.stage));
      placed = true;
    }
  }
  collecting_ = false;
  if (waiting_.empty()) return;
  const Waiting& w = waiting_.front();
  const std::string message = "stage '" + w.stage.name + "' goes " + (w.after ? "after" : "before") + " '" +
                              w.anchor + "', which no stage of this scene is (stages: " + stageList() + ")";
  const std::string where = w.where;
  waiting_.clear();
  throw InputError(message, where);
}

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
