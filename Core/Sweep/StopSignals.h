#pragma once
// SIGINT and SIGTERM while an executor waits for its runs: counted, not
// fatal, so that the executor can pass them on to its runs (which finish the
// frame under way, write a checkpoint and exit 130) and record how each
// ended. The handlers in place before are restored on destruction (Python's
// own, when a sweep runs from Python).
namespace soak {

class StopSignals {
 public:
  StopSignals();
  ~StopSignals();
  StopSignals(const StopSignals&) = delete;
  StopSignals& operator=(const StopSignals&) = delete;
  // Signals received since construction.
  int count() const;
  // The last one received (SIGINT or SIGTERM), 0 before any.
  int last() const;
};

}  // namespace soak
