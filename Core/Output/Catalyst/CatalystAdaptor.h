#pragma once
// The Catalyst adaptor: a frame sink (Output/FrameSink.h) that runs ParaView
// Catalyst Python scripts on the frames and serves Catalyst Live, on a
// thread of its own. Every ParaView and Python call happens on that thread;
// the writer hands it frames through a short queue and waits only when the
// queue is full (consume), so Catalyst runs beside the simulation.
#include <condition_variable>
#include <deque>
#include <exception>
#include <memory>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

#include <vtkSmartPointer.h>

#include "Base/Error.h"
#include "CatalystChannels.h"
#include "LiveConnection.h"
#include "Output/CatalystSettings.h"
#include "Output/FrameSink.h"

class vtkCPProcessor;
class vtkCPPythonScriptV2Pipeline;

namespace soak {

// A user's script failed while the run went on: its Python traceback is on
// stderr above the message. Exit 2, as bad input (Demos/soak).
class CatalystScriptError : public InputError {
 public:
  using InputError::InputError;
};

class CatalystAdaptor : public FrameSink {
 public:
  // Starts the thread, loads ParaView, checks and loads the scripts; throws
  // InputError (nothing written yet) when any of that fails.
  CatalystAdaptor(const CatalystSettings& settings, const std::string& runDirectory);
  ~CatalystAdaptor() override;

  void start(const OutputLayout& layout) override;
  bool wants(int frame) const override { return frame % settings_.every == 0; }
  void consume(std::shared_ptr<const SinkFrame> frame) override;
  void finish() override;
  bool waited() const override;

  // Frames a script may lag behind before the writer waits.
  static constexpr std::size_t kQueuedFrames = 2;

 private:
  void threadMain();
  void initialize();  // on the thread
  void process(const SinkFrame& frame);
  void shutDown();    // on the thread

  CatalystSettings settings_;
  std::string runDirectory_;
  std::unique_ptr<CatalystChannels> channels_;

  // Used on the thread only.
  vtkSmartPointer<vtkCPProcessor> processor_;
  std::vector<vtkSmartPointer<vtkCPPythonScriptV2Pipeline>> pipelines_;
  std::unique_ptr<LiveConnection> live_;
  bool startedPython_ = false;
  int framesDone_ = 0;
  double secondsSpent_ = 0.0;  // in process(), for the closing line  // this thread started Python (not a Python program)

  mutable std::mutex mutex_;
  std::condition_variable changed_;
  std::deque<std::shared_ptr<const SinkFrame>> queue_;
  bool busy_ = false, stopping_ = false, initialized_ = false, waited_ = false;
  std::exception_ptr error_;
  std::thread thread_;
};

}  // namespace soak
