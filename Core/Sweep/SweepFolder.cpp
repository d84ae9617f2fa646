#include "Sweep/SweepFolder.h"

#include <signal.h>
#include <sys/stat.h>
#include <unistd.h>

#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <map>
#include <pugixml.hpp>
#include <sstream>

#include "Base/Error.h"
#include "Base/ReadInput.h"
#include "Output/RunFolder.h"
#include "Plugins/PluginLoader.h"
#include "Scene/Scene.h"
#include "Simulation/LoadedScene.h"

namespace soak {

namespace {

bool exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

void makeFolders(const std::string& path) {
  std::string partial;
  std::istringstream parts(path);
  if (!path.empty() && path[0] == '/') partial = "/";
  for (std::string part; std::getline(parts, part, '/');) {
    if (part.empty()) continue;
    partial += part + "/";
    if (::mkdir(partial.c_str(), 0777) != 0 && errno != EEXIST) throw StorageError(partial, errno, std::strerror(errno));
  }
}

void writeFileAtomically(const std::string& path, const std::string& text) {
  const std::string tmp = path + ".tmp";
  {
    std::ofstream out(tmp, std::ios::binary | std::ios::trunc);
    out << text;
    out.flush();
    if (!out) throw StorageError(tmp, errno, std::strerror(errno));
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw StorageError(path, errno, std::strerror(errno));
}

std::string readText(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream o;
  o << in.rdbuf();
  return o.str();
}

std::string absolutePath(const std::string& path) {
  char* real = ::realpath(path.c_str(), nullptr);
  if (!real) throw InputError("the scene file '" + path + "' does not exist", path);
  std::string r(real);
  std::free(real);
  return r;
}

// The scene as run, with every file it reads (meshes, plugin libraries)
// named by absolute path: the point's scene.xml lives in another folder
// than the scene it came from.
std::string withAbsoluteInputPaths(const std::string& text, const std::string& scenePath,
                                   const ModuleRegistry& registry) {
  pugi::xml_document doc;
  if (!doc.load_buffer(text.data(), text.size(), pugi::parse_default | pugi::parse_comments)) return text;
  bool changed = false;
  auto absolute = [&](pugi::xml_attribute a) {
    const std::string v = a.as_string();
    if (v.empty() || v[0] == '/') return;
    a.set_value(pathBesideScene(scenePath, v).c_str());
    changed = true;
  };
  for (pugi::xml_node n : doc.document_element().children()) {
    if (n.type() != pugi::node_element) continue;
    if (std::string(n.name()) == "Plugin") {
      if (pugi::xml_attribute a = n.attribute("path")) absolute(a);
      continue;
    }
    const ElementDecl* decl = registry.find(n.name());
    if (!decl) continue;
    for (const ParamDecl& p : decl->params)
      if (p.type == ParamType::Text && p.textKind == TextKind::InputFile)
        if (pugi::xml_attribute a = n.attribute(p.name.c_str())) absolute(a);
  }
  if (!changed) return text;
  std::ostringstream o;
  doc.save(o, "  ", pugi::format_default | pugi::format_no_declaration);
  return o.str();
}

bool pointStarted(const SweepLayout& layout, const std::string& id) {
  if (readPointRecord(layout.record(id)).attempts > 0) return true;
  const RunFolderContents run = inspectRunFolder(layout.runDir(id));
  return run.exists && !run.empty();
}

bool processAlive(long long pid) { return pid > 0 && (::kill(pid_t(pid), 0) == 0 || errno == EPERM); }

}  // namespace

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n\r") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s) q += c == '"' ? std::string("\"\"") : std::string(1, c);
  return q + "\"";
}

PlanSummary planSweep(const SweepDescription& given, const std::string& dir, const std::vector<std::string>& plugins) {
  SweepDescription d = given;
  d.scene = absolutePath(d.scene);
  const SweepLayout layout{dir};
  const std::vector<SweepPoint> points = sweepPoints(d);

  if (exists(layout.description())) {
    const SweepState before = loadSweep(dir);
    if (sweepRunFingerprint(before.description) != sweepRunFingerprint(d))
      for (const SweepPoint& p : before.points)
        if (pointStarted(layout, p.id))
          throw InputError(dir + " holds a sweep whose points run differently (another scene, run length, device, "
                               "fixed value or set of varying values) and point " + p.id +
                               " of it has run; plan this description into another folder",
                           d.source);
  } else if (exists(dir) && !exists(dir + "/points")) {
    struct stat st {};
    if (::stat(dir.c_str(), &st) == 0 && !S_ISDIR(st.st_mode)) throw InputError(dir + " is a file, not a folder");
  }

  ModuleRegistry registry;
  registerCoreElements(registry);
  PluginLoader loader(registry);
  loadStandardPlugins(loader, plugins);
  const PluginRequest request = [&](const std::string& what, bool isPath, const std::string& where) {
    if (isPath) loader.loadFile(what, where);
    else loader.loadByName(what, where);
  };
  const std::string sceneText = readInputFile(d.scene, kMaxSceneBytes, "scene file");

  // Every point's scene first: a description that the scene refuses
  // everywhere writes nothing.
  PlanSummary summary;
  std::vector<std::string> texts, errors;
  for (const SweepPoint& p : points) {
    std::string text, error;
    try {
      const Scene scene = Scene::parse(sceneText, d.scene, sweepPointOverrides(d, p), registry, request);
      text = withAbsoluteInputPaths(scene.textAsRun(), d.scene, registry);
    } catch (const InputError& e) {
      error = e.what();
      ++summary.invalid;
    }
    if (error.empty() && exists(layout.pointScene(p.id)) && readText(layout.pointScene(p.id)) != text &&
        pointStarted(layout, p.id))
      throw InputError("point " + p.id + " has run with another scene.xml than the scene gives it now (was " + d.scene +
                           " edited?); plan into another folder to run the new one",
                       layout.pointScene(p.id));
    texts.push_back(text);
    errors.push_back(error);
  }
  summary.points = int(points.size());
  if (summary.invalid == summary.points)
    throw InputError("the scene refuses every point of the sweep; the first: " + errors.front(), d.source);

  for (std::size_t i = 0; i < points.size(); ++i) {
    const std::string& id = points[i].id;
    if (!exists(layout.pointDir(id))) ++summary.added;
    makeFolders(layout.pointDir(id));
    PointRecord record = readPointRecord(layout.record(id));
    if (!errors[i].empty()) {
      record.status = "invalid";
      record.exitCode = 2;
      record.error = errors[i];
      writePointRecord(layout.record(id), record);
      continue;
    }
    if (readText(layout.pointScene(id)) != texts[i]) writeFileAtomically(layout.pointScene(id), texts[i]);
    if (record.status == "invalid") writePointRecord(layout.record(id), PointRecord{});
  }
  makeFolders(dir);
  writeFileAtomically(layout.description(), sweepDescriptionText(d));
  writeManifest(loadSweep(dir));
  return summary;
}

SweepState loadSweep(const std::string& dir) {
  SweepState s;
  s.layout = SweepLayout{dir};
  if (!exists(s.layout.description()))
    throw InputError(dir + " is not a planned sweep (no sweep.txt): run soak sweep plan first");
  s.description = readSweepDescription(s.layout.description());
  s.points = sweepPoints(s.description);
  for (const SweepPoint& p : s.points)
    s.records.push_back(sweepRecordNow(s.layout, p.id, readPointRecord(s.layout.record(p.id))));
  return s;
}

PointRecord sweepRecordNow(const SweepLayout& layout, const std::string& id, const PointRecord& r) {
  if (r.status != "running") return r;
  if (!runFolderHolder(layout.runDir(id)).empty()) return r;
  if (r.host != thisHostName() || processAlive(r.pid)) return r;
  PointRecord now = r;
  now.status = "interrupted";
  if (now.error.empty()) now.error = "its run ended without saying how (killed, or its machine stopped)";
  return now;
}

void writeManifest(const SweepState& s) {
  std::ostringstream o;
  o << "point,repeat";
  for (const SweepParameter& p : s.description.parameters) o << "," << csvField(p.name);
  o << ",status,exit_code,wall_s,attempts,error\n";
  for (std::size_t i = 0; i < s.points.size(); ++i) {
    const SweepPoint& p = s.points[i];
    const PointRecord& r = s.records[i];
    o << p.id << "," << p.repeat;
    for (const std::string& v : p.values) o << "," << csvField(v);
    char wall[32];
    std::snprintf(wall, sizeof(wall), "%.3f", r.wallSeconds);
    o << "," << r.status << "," << (r.exitCode >= 0 ? std::to_string(r.exitCode) : "") << "," << wall << ","
      << r.attempts << "," << csvField(r.error) << "\n";
  }
  writeFileAtomically(s.layout.manifest(), o.str());
}

std::string statusCounts(const SweepState& s) {
  std::map<std::string, int> counts;
  for (const PointRecord& r : s.records) ++counts[r.status];
  std::string text;
  for (const char* status : {"done", "running", "failed", "interrupted", "invalid", "planned"}) {
    if (!counts.count(status)) continue;
    text += (text.empty() ? "" : ", ") + std::to_string(counts[status]) + " " + status;
    counts.erase(status);
  }
  for (const auto& other : counts) text += (text.empty() ? "" : ", ") + std::to_string(other.second) + " " + other.first;
  return text;
}

}  // namespace soak
