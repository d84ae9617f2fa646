#pragma once
// ParaView Catalyst in situ and Catalyst Live (<Catalyst>, `soak run
// --catalyst SCRIPT.py --live HOST:PORT`; Doc/paraview.md, "In situ and
// live"). The adaptor is its own library, libsoak_catalyst.so, loaded only
// when a run asks for it (Output/CatalystLoader.h).
#include <string>
#include <vector>

namespace soak {

struct CatalystSettings {
  std::vector<std::string> scripts;  // Catalyst Python scripts (ParaView 5.9+ "v2" form), run in this order
  int every = 1;                     // run them on every N-th output frame (frame 0 included)
  std::string live;                  // "host:port" of a ParaView GUI listening on Catalyst > Connect; empty: none
  std::string where;                 // <Catalyst>'s file:line, for messages (empty from the command line)

  bool wanted() const { return !scripts.empty() || !live.empty(); }
};

// The port ParaView's Catalyst > Connect listens on unless told otherwise.
constexpr int kCatalystLiveDefaultPort = 22222;

// "host:port", "host" or ":port" (host localhost, port 22222 where left
// out): InputError at `where` for anything else.
struct LiveAddress {
  std::string host = "localhost";
  int port = kCatalystLiveDefaultPort;
};
LiveAddress parseLiveAddress(const std::string& text, const std::string& where = {});

}  // namespace soak
