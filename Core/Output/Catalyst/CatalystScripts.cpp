#include <Python.h>  // first, as Python asks

#include "CatalystScripts.h"

#include <cerrno>
#include <cstring>
#include <fstream>
#include <sstream>

#include "Base/Error.h"

namespace soak {

namespace {
std::string readText(const std::string& path) {
  std::ifstream in(path);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}
}  // namespace

void checkScriptReadable(const std::string& path) {
  std::ifstream in(path);
  if (!in) throw InputError(std::string("cannot read the Catalyst script: ") + std::strerror(errno), path);
}

bool scriptDrawsPictures(const std::string& path) {
  const std::string text = readText(path);
  for (const char* word : {"CreateView(", "GetRenderView(", "CreateRenderView(", "SaveScreenshot(", "Render("})
    if (text.find(word) != std::string::npos) return true;
  return false;
}

std::string pythonSyntaxError(const std::string& path) {
  // compile() of the file's text, and on failure the exception as
  // traceback.format_exception_only words it.
  const char* code =
      "def _soak_check(path):\n"
      "    import traceback\n"
      "    try:\n"
      "        with open(path, encoding='utf-8') as f:\n"
      "            compile(f.read(), path, 'exec')\n"
      "    except SyntaxError as e:\n"
      "        return ''.join(traceback.format_exception_only(type(e), e))\n"
      "    return ''\n";
  PyObject* globals = PyDict_New();
  PyDict_SetItemString(globals, "__builtins__", PyEval_GetBuiltins());
  std::string result;
  PyObject* defined = PyRun_String(code, Py_file_input, globals, globals);
  PyObject* check = defined ? PyDict_GetItemString(globals, "_soak_check") : nullptr;
  PyObject* message = check ? PyObject_CallFunction(check, "s", path.c_str()) : nullptr;
  if (message && PyUnicode_Check(message)) result = PyUnicode_AsUTF8(message);
  if (!message) {
    PyErr_Clear();
    result = "could not check the script's syntax";
  }
  Py_XDECREF(message);
  Py_XDECREF(defined);
  Py_DECREF(globals);
  return result;
}

void setPythonEnvironment(const std::string& name, const std::string& value) {
  PyObject* os = PyImport_ImportModule("os");
  PyObject* environ = os ? PyObject_GetAttrString(os, "environ") : nullptr;
  PyObject* text = PyUnicode_FromString(value.c_str());
  if (!environ || !text || PyMapping_SetItemString(environ, name.c_str(), text) != 0) PyErr_Clear();
  Py_XDECREF(text);
  Py_XDECREF(environ);
  Py_XDECREF(os);
}

}  // namespace soak
