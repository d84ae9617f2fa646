#include <Python.h>  // first, as Python asks

#include "CatalystAdaptor.h"

#include <vtkCPDataDescription.h>
#include <vtkCPInputDataDescription.h>
#include <vtkCPProcessor.h>
#include <vtkCPPythonScriptV2Pipeline.h>
#include <vtkNew.h>
#include <vtkObject.h>
#include <vtkPolyData.h>
#include <vtkPythonInterpreter.h>

#include <chrono>
#include <cstdio>
#include <cstdlib>

#include "Base/Error.h"
#include "CatalystScripts.h"
#include "XDisplay.h"

namespace soak {

namespace {
// The GIL for one call into ParaView's Python: held by this thread for the
// call, whether soak's own thread started Python or a Python program
// (the soak module) did.
struct HoldGil {
  PyGILState_STATE state = PyGILState_Ensure();
  ~HoldGil() { PyGILState_Release(state); }
};
}  // namespace

CatalystAdaptor::CatalystAdaptor(const CatalystSettings& settings, const std::string& runDirectory)
    : settings_(settings), runDirectory_(runDirectory) {
  if (settings_.every < 1) settings_.every = 1;
  if (!settings_.live.empty()) parseLiveAddress(settings_.live, settings_.where);
  for (const std::string& script : settings_.scripts) {
    checkScriptReadable(script);
    std::string why;
    if (scriptDrawsPictures(script) && !canOpenXDisplay(&why))
      throw InputError("the Catalyst script draws pictures, and Debian's ParaView draws through X: " + why +
                           "; run under a display (xvfb-run -a soak run ...)",
                       script);
  }
  // Scripts find the run's folder here (Doc/paraview.md).
  ::setenv("SOAK_OUTPUT", runDirectory_.c_str(), 1);
  thread_ = std::thread([this] { threadMain(); });
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return initialized_ || error_; });
  if (error_) {
    stopping_ = true;
    lock.unlock();
    changed_.notify_all();
    thread_.join();
    std::rethrow_exception(error_);
  }
}

CatalystAdaptor::~CatalystAdaptor() {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    stopping_ = true;
  }
  changed_.notify_all();
  if (thread_.joinable()) thread_.join();
}

void CatalystAdaptor::start(const OutputLayout& layout) {
  std::lock_guard<std::mutex> lock(mutex_);
  channels_ = std::make_unique<CatalystChannels>(layout);
}

void CatalystAdaptor::consume(std::shared_ptr<const SinkFrame> frame) {
  std::unique_lock<std::mutex> lock(mutex_);
  if (error_) std::rethrow_exception(error_);
  if (queue_.size() >= kQueuedFrames) {
    waited_ = true;
    changed_.wait(lock, [&] { return queue_.size() < kQueuedFrames || error_; });
    if (error_) std::rethrow_exception(error_);
  }
  queue_.push_back(std::move(frame));
  lock.unlock();
  changed_.notify_all();
}

void CatalystAdaptor::finish() {
  std::unique_lock<std::mutex> lock(mutex_);
  changed_.wait(lock, [&] { return (queue_.empty() && !busy_) || error_; });
  if (error_) std::rethrow_exception(error_);
}

bool CatalystAdaptor::waited() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return waited_;
}

void CatalystAdaptor::threadMain() {
  try {
    initialize();
    std::lock_guard<std::mutex> lock(mutex_);
    initialized_ = true;
  } catch (...) {
    std::lock_guard<std::mutex> lock(mutex_);
    error_ = std::current_exception();
  }
  changed_.notify_all();
  for (;;) {
    std::shared_ptr<const SinkFrame> frame;
    {
      std::unique_lock<std::mutex> lock(mutex_);
      changed_.wait(lock, [&] { return stopping_ || !queue_.empty(); });
      if (queue_.empty() || error_) break;
      frame = queue_.front();
      busy_ = true;
    }
    try {
      const auto start = std::chrono::steady_clock::now();
      process(*frame);
      secondsSpent_ += std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      ++framesDone_;
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex_);
      if (!error_) error_ = std::current_exception();
    }
    {
      std::lock_guard<std::mutex> lock(mutex_);
      queue_.pop_front();
      busy_ = false;
    }
    changed_.notify_all();
  }
  try {
    shutDown();
  } catch (...) {
  }
  std::lock_guard<std::mutex> lock(mutex_);
  queue_.clear();
  changed_.notify_all();
}

void CatalystAdaptor::initialize() {
  // In a Python program (the soak module) ParaView sets itself up in that
  // program's Python: with its GIL.
  std::unique_ptr<HoldGil> hostGil;
  if (Py_IsInitialized()) hostGil = std::make_unique<HoldGil>();
  processor_ = vtkSmartPointer<vtkCPProcessor>::New();
  if (!processor_->Initialize())
    throw InputError("ParaView Catalyst did not initialize (vtkCPProcessor)", settings_.where);
  if (!settings_.live.empty()) live_ = std::make_unique<LiveConnection>(parseLiveAddress(settings_.live));
  if (settings_.scripts.empty()) return;
  startedPython_ = !Py_IsInitialized();
  vtkPythonInterpreter::Initialize(0);  // 0: soak keeps its own SIGINT handling
  HoldGil gil;
  setPythonEnvironment("SOAK_OUTPUT", runDirectory_);
  for (const std::string& script : settings_.scripts) {
    const std::string syntax = pythonSyntaxError(script);
    if (!syntax.empty()) throw InputError("the Catalyst script does not compile:\n" + syntax, script);
    auto pipeline = vtkSmartPointer<vtkCPPythonScriptV2Pipeline>::New();
    if (!pipeline->Initialize(script.c_str()))
      throw InputError("ParaView could not load the Catalyst script (messages above)", script);
    pipelines_.push_back(pipeline);
  }
}

void CatalystAdaptor::process(const SinkFrame& frame) {
  if (!channels_) return;
  const std::vector<CatalystChannel> channels = channels_->build(frame);
  const double time = frame.data.time;
  const long long step = frame.data.step;
  if (!pipelines_.empty()) {
    HoldGil gil;
    vtkNew<vtkCPDataDescription> description;
    for (const CatalystChannel& c : channels) {
      description->AddInput(c.name.c_str());
      description->AddInput(channelFileName(c.name).c_str());
    }
    description->SetTimeData(time, step);
    for (std::size_t k = 0; k < pipelines_.size(); ++k) {
      const std::string& script = settings_.scripts[k];
      const std::string when = " at frame " + std::to_string(frame.frame) + " (t = " + std::to_string(time) +
                               " s, step " + std::to_string(step) + ")";
      if (!pipelines_[k]->RequestDataDescription(description))
        throw CatalystScriptError("the Catalyst script failed" + when + "; its Python traceback is above", script);
      bool needed = false;
      for (const CatalystChannel& c : channels)
        for (const std::string& name : {c.name, channelFileName(c.name)}) {
          vtkCPInputDataDescription* input = description->GetInputDescriptionByName(name.c_str());
          if (input && input->GetIfGridIsNecessary()) {
            input->SetGrid(c.data);
            needed = true;
          }
        }
      if (needed && !pipelines_[k]->CoProcess(description))
        throw CatalystScriptError("the Catalyst script failed" + when + "; its Python traceback is above", script);
    }
  }
  if (live_) {
    std::unique_ptr<HoldGil> gil;
    if (Py_IsInitialized()) gil = std::make_unique<HoldGil>();
    live_->update(channels, time, step);
  }
}

void CatalystAdaptor::shutDown() {
  if (framesDone_ > 0)
    std::fprintf(stderr, "soak: Catalyst: %d frames, %.1f ms per frame on its own thread (scripts%s)\n", framesDone_,
                 1e3 * secondsSpent_ / framesDone_, live_ ? " and Live" : "");
  {
    std::unique_ptr<HoldGil> gil;
    if (Py_IsInitialized()) gil = std::make_unique<HoldGil>();
    live_.reset();
    for (auto& p : pipelines_) p->Finalize();
    pipelines_.clear();
  }
  // The processor may end Python itself; Python ends on the thread that
  // started it, not at the program's exit on another.
  if (processor_) processor_->Finalize();
  processor_ = nullptr;
  if (startedPython_ && Py_IsInitialized()) vtkPythonInterpreter::Finalize();
}

}  // namespace soak
