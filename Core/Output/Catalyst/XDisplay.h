#pragma once
// Debian's ParaView renders through X (GLX): a script that draws pictures
// needs a display, and without one ParaView aborts the process. The run
// checks first and says so instead.
#include <string>

namespace soak {

// Whether an X display can be opened ($DISPLAY); `why` says why not.
bool canOpenXDisplay(std::string* why);

}  // namespace soak
