#pragma once
// A plugin's stages as a table: each row names a stage, where it goes in the
// step (before or after an anchor: a core stage, StageNames.h, or a stage of
// a row above), the function that runs it with the module's state, and
// whether the scene switches it on. Adding a stage to a plugin is then one
// file (the stage's function) and one row (Doc/plugins.md, "A second stage").
//
//   const StageRow<MyState> kRows[] = {
//       {"my.first", Place::Before, stage::kCoupling, runFirst},
//       {"my.second", Place::After, "my.first", runSecond, [](const MyState& s) { return s.on; }},
//   };
//   addStageTable(pipeline, state, kRows);   // in Module::addStages
#include <cstddef>

#include "Pipeline/Pipeline.h"

namespace soak {

enum class Place { Before, After };

template <class State>
struct StageRow {
  const char* name;
  Place place;
  const char* anchor;
  void (*run)(State& state, Simulation& sim);
  bool (*enabled)(const State& state) = nullptr;  // null: always on
};

// Inserts the enabled rows in order; `state` must outlive the pipeline.
// An anchor no stage provides is reported by the pipeline (bad input, at
// the element that asked).
template <class State, std::size_t N>
void addStageTable(Pipeline& pipeline, State& state, const StageRow<State> (&rows)[N]) {
  for (const StageRow<State>& row : rows) {
    if (row.enabled && !row.enabled(state)) continue;
    State* s = &state;
    auto run = row.run;
    Stage stage{row.name, [s, run](Simulation& sim) { run(*s, sim); }};
    if (row.place == Place::Before)
      pipeline.insertBefore(row.anchor, std::move(stage));
    else
      pipeline.insertAfter(row.anchor, std::move(stage));
  }
}

}  // namespace soak
