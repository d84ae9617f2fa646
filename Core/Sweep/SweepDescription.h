#pragma once
// A sweep description (Doc/sweeps.md): a scene, the scene values that vary
// and those fixed for every point, the run's length and how often it keeps a
// checkpoint. Written as a small text file, one setting a line:
//
//   # fit the strip's diffusivity
//   scene = ../Scenes/wicking_strip.xml      (relative to this file)
//   frames = 50                              (or: time = 5)
//   checkpoint_every = 10
//   repeats = 1
//   device = cpu
//   set Simulation.frameRate = 10            (the same for every point)
//   vary WetCloth.diffusivity = log 0.002 0.02 5
//   vary Cloth.model = list pbd chebyshev
//
// or given as options (soak sweep plan --scene ... --vary ...), which build
// the same lines. Every mistake is an InputError naming the file and line.
#include <string>
#include <vector>

namespace soak {

// One scene value that varies: its --set name and the values it takes.
struct SweepParameter {
  std::string name;                 // "WetCloth.diffusivity", "Cloth[1].model"
  std::vector<std::string> values;  // as --set will write them
  std::string where;                // "file:line" of its `vary` line
};

// A fixed override (`set` line): applied to every point.
struct SweepSetting {
  std::string name;
  std::string value;
  std::string where;
};

struct SweepDescription {
  std::string scene;            // absolute path
  int frames = -1;              // run length: frames after frame 0, or
  double time = -1.0;           // simulated seconds (one of the two)
  int checkpointEvery = 10;     // frames between checkpoints (every point can resume)
  int repeats = 1;              // runs per combination of values
  std::string device = "auto";  // soak run --device
  std::vector<SweepSetting> fixed;
  std::vector<SweepParameter> parameters;
  std::string source;           // the file it was read from, for messages
};

// Most points one sweep may expand to.
constexpr long long kMaxSweepPoints = 100000;

// Reads a description; `path` names it in messages and resolves `scene`.
SweepDescription parseSweepDescription(const std::string& text, const std::string& path);
SweepDescription readSweepDescription(const std::string& path);

// The values a range expands to: "list a b c", "linear FROM TO COUNT",
// "log FROM TO COUNT" (COUNT values, both ends included). Numbers of linear
// and log ranges are written with six significant digits. InputError at `where`.
std::vector<std::string> expandSweepRange(const std::string& spec, const std::string& where);

// The description as lines the parser reads back to the same description
// (the scene absolute, ranges expanded to lists): what a sweep folder keeps.
std::string sweepDescriptionText(const SweepDescription& d);

// The part that every point's run shares (scene, length, fixed values,
// device): two descriptions with the same runFingerprint run each common
// point the same way.
std::string sweepRunFingerprint(const SweepDescription& d);

}  // namespace soak
