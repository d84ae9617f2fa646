#include "Sweep/StopSignals.h"

#include <csignal>

namespace soak {

namespace {
volatile std::sig_atomic_t g_count = 0;
volatile std::sig_atomic_t g_last = 0;
struct sigaction g_oldInt, g_oldTerm;

void onStop(int signal) {
  g_count = g_count + 1;
  g_last = signal;
}
}  // namespace

StopSignals::StopSignals() {
  g_count = 0;
  g_last = 0;
  struct sigaction a {};
  a.sa_handler = onStop;
  sigemptyset(&a.sa_mask);
  sigaction(SIGINT, &a, &g_oldInt);
  sigaction(SIGTERM, &a, &g_oldTerm);
}

StopSignals::~StopSignals() {
  sigaction(SIGINT, &g_oldInt, nullptr);
  sigaction(SIGTERM, &g_oldTerm, nullptr);
}

int StopSignals::count() const { return g_count; }
int StopSignals::last() const { return g_last; }

}  // namespace soak
