#include "LiveConnection.h"

#include <vtkLiveInsituLink.h>
#include <vtkNew.h>
#include <vtkPVTrivialProducer.h>
#include <vtkPolyData.h>
#include <vtkSMParaViewPipelineController.h>
#include <vtkSMProxy.h>
#include <vtkSMProxyManager.h>
#include <vtkSMSessionProxyManager.h>

#include <cstdio>

namespace soak {

LiveConnection::LiveConnection(const LiveAddress& address) : address_(address) {}

LiveConnection::~LiveConnection() = default;

void LiveConnection::say(const std::string& text) { std::fprintf(stderr, "\nsoak: Catalyst Live: %s\n", text.c_str()); }

// What ParaView's own Catalyst does for a script's inputs: a trivial
// producer proxy per channel, registered under the channel's name, which
// the GUI lists and can extract.
void LiveConnection::createProducers(const std::vector<CatalystChannel>& channels, double time) {
  vtkSMSessionProxyManager* pxm = vtkSMProxyManager::GetProxyManager()->GetActiveSessionProxyManager();
  vtkNew<vtkSMParaViewPipelineController> controller;
  for (const CatalystChannel& c : channels) {
    vtkSmartPointer<vtkSMProxy> producer;
    producer.TakeReference(pxm->NewProxy("sources", "PVTrivialProducer2"));
    controller->InitializeProxy(producer);
    if (auto* tp = vtkPVTrivialProducer::SafeDownCast(producer->GetClientSideObject())) tp->SetOutput(c.data, time);
    producer->UpdateVTKObjects();
    controller->RegisterPipelineProxy(producer, c.name.c_str());
    producers_.push_back(producer);
  }
  link_ = vtkSmartPointer<vtkLiveInsituLink>::New();
  link_->SetHostname(address_.host.c_str());
  link_->SetInsituPort(address_.port);
}

void LiveConnection::update(const std::vector<CatalystChannel>& channels, double time, long long step) {
  if (!link_) createProducers(channels, time);
  for (std::size_t k = 0; k < producers_.size() && k < channels.size(); ++k) {
    if (auto* tp = vtkPVTrivialProducer::SafeDownCast(producers_[k]->GetClientSideObject()))
      tp->SetOutput(channels[k].data, time);
    producers_[k]->MarkModified(producers_[k]);
  }
  const std::string where = address_.host + ":" + std::to_string(address_.port);
  vtkSMSessionProxyManager* pxm = vtkSMProxyManager::GetProxyManager()->GetActiveSessionProxyManager();
  if (!link_->Initialize(pxm)) {  // tries to connect again each frame
    if (!toldNoListener_)
      say("nothing listens on " + where + " (ParaView: Catalyst > Connect, port " + std::to_string(address_.port) +
          "); the run goes on and connects when a ParaView listens");
    toldNoListener_ = true;
    connected_ = false;
    return;
  }
  if (!connected_) say("connected to ParaView at " + where);
  connected_ = true;
  bool toldPaused = false;
  do {
    link_->InsituUpdate(time, step);
    link_->InsituPostProcess(time, step);
    if (link_->GetSimulationPaused() && !toldPaused) {
      say("paused from ParaView at t = " + std::to_string(time) + " s (Catalyst > Continue goes on)");
      toldPaused = true;
    }
  } while (link_->GetSimulationPaused() && link_->WaitForLiveChange() == 0);
  if (toldPaused) say("continued");
}

}  // namespace soak
