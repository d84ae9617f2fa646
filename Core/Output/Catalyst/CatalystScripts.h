#pragma once
// Checks on a run's Catalyst scripts before the first frame, so that a
// script that cannot run stops the run before anything is written (exit 2)
// with the script's file and line.
#include <string>

namespace soak {

// InputError unless `path` is a readable file.
void checkScriptReadable(const std::string& path);

// Whether the script draws (creates a view or saves a screenshot): it then
// needs an X display (XDisplay.h).
bool scriptDrawsPictures(const std::string& path);

// Python's SyntaxError for the script, as Python words it (file, line, the
// line itself, the caret); empty when it compiles. Needs the Python
// interpreter initialized and the GIL held.
std::string pythonSyntaxError(const std::string& path);

// Sets os.environ[name] in Python (a Python program took its copy of the
// environment when it started). Needs the GIL.
void setPythonEnvironment(const std::string& name, const std::string& value);

}  // namespace soak
