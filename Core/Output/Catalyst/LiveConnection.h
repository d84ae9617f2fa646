#pragma once
// Catalyst Live from the run's side: the channels as producers that the
// Catalyst pipelines read, and a link to a ParaView GUI listening on
// Catalyst > Connect. Each frame it offers the GUI the new data; while the GUI has
// the run paused (Catalyst > Pause Simulation) it waits, and so, once the
// frame queue is full, do the steps. Without a listener the run goes on,
// says so once, and connects when a GUI starts listening.
#include <memory>
#include <string>
#include <vector>

#include <vtkSmartPointer.h>

#include "CatalystChannels.h"
#include "Output/CatalystSettings.h"

class vtkLiveInsituLink;
class vtkSMProxy;

namespace soak {

class LiveConnection {
 public:
  explicit LiveConnection(const LiveAddress& address);
  ~LiveConnection();
  // On the Catalyst thread, after vtkCPProcessor::Initialize.
  void update(const std::vector<CatalystChannel>& channels, double time, long long step);

 private:
  void createProducers(const std::vector<CatalystChannel>& channels, double time);
  void say(const std::string& text);

  LiveAddress address_;
  vtkSmartPointer<vtkLiveInsituLink> link_;
  std::vector<vtkSmartPointer<vtkSMProxy>> producers_;
  bool toldNoListener_ = false, connected_ = false;
};

}  // namespace soak
