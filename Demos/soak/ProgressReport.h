#pragma once
#include "Simulation/Runner.h"

namespace soak::cli {

// A progress bar on a terminal, plain lines (about every 10 %) otherwise.
class ProgressReport {
 public:
  explicit ProgressReport(bool quiet);
  void update(const RunProgress& p);
  void finish();

 private:
  bool quiet_;
  bool tty_;
  int lastDecile_ = -1;
  bool drawn_ = false;
};

}  // namespace soak::cli
