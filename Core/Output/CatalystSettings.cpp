#include "Output/CatalystSettings.h"

#include <cstdlib>

#include "Base/Error.h"

namespace soak {

LiveAddress parseLiveAddress(const std::string& text, const std::string& where) {
  LiveAddress a;
  const std::size_t colon = text.rfind(':');
  const std::string host = colon == std::string::npos ? text : text.substr(0, colon);
  if (!host.empty()) a.host = host;
  if (colon != std::string::npos) {
    const std::string port = text.substr(colon + 1);
    char* end = nullptr;
    const long p = std::strtol(port.c_str(), &end, 10);
    if (port.empty() || *end || p < 1 || p > 65535)
      throw InputError("Catalyst Live address '" + text + "': the port must be a number from 1 to 65535 (HOST:PORT; "
                       "ParaView's Catalyst > Connect listens on 22222 by default)",
                       where);
    a.port = int(p);
  }
  if (a.host.find_first_of(" \t/") != std::string::npos)
    throw InputError("Catalyst Live address '" + text + "' is not HOST:PORT", where);
  return a;
}

}  // namespace soak
