#include "Sweep/SweepDescription.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <set>
#include <sstream>

#include "Base/Error.h"
#include "Base/MessageText.h"
#include "Base/ReadInput.h"
#include "Scene/Suggest.h"
#include "Simulation/Runner.h"

namespace soak {

namespace {

const std::vector<std::string> kKeys = {"scene", "frames", "time", "checkpoint_every", "repeats", "device", "set", "vary"};

std::string trim(const std::string& s) {
  const std::size_t a = s.find_first_not_of(" \t\r");
  if (a == std::string::npos) return "";
  return s.substr(a, s.find_last_not_of(" \t\r") - a + 1);
}

std::vector<std::string> words(const std::string& s) {
  std::istringstream in(s);
  std::vector<std::string> w;
  for (std::string x; in >> x;) w.push_back(x);
  return w;
}

double number(const std::string& text, const std::string& what, const std::string& where) {
  char* end = nullptr;
  const double v = std::strtod(text.c_str(), &end);
  if (text.empty() || *end || !std::isfinite(v))
    throw InputError(what + ": '" + clipForMessage(text) + "' is not a finite number", where);
  return v;
}

int integer(const std::string& text, const std::string& what, long long lo, long long hi, const std::string& where) {
  const double v = number(text, what, where);
  if (v != std::floor(v) || v < double(lo) || v > double(hi))
    throw InputError(what + " must be an integer in [" + std::to_string(lo) + ", " + std::to_string(hi) + "], not " +
                         clipForMessage(text),
                     where);
  return int(v);
}

std::string sixDigits(double v) {
  char b[32];
  std::snprintf(b, sizeof(b), "%.6g", v);
  return b;
}

// "Element.attr" or "Element[i].attr": the shape --set takes (the scene
// checks the names themselves when the sweep is planned).
void checkValueName(const std::string& name, const std::string& where) {
  const std::size_t dot = name.find('.');
  if (name.empty() || dot == std::string::npos || dot == 0 || dot + 1 == name.size() ||
      name.find_first_of(" \t=,\"") != std::string::npos)
    throw InputError("'" + clipForMessage(name) + "' is not a scene value name: expected Element.attribute or "
                         "Element[i].attribute, as soak run --set names it",
                     where);
}

// "NAME = VALUE" after a `set` or `vary` keyword.
std::pair<std::string, std::string> nameAndValue(const std::string& rest, const std::string& keyword,
                                                 const std::string& where) {
  const std::size_t eq = rest.find('=');
  if (eq == std::string::npos)
    throw InputError(keyword + " needs 'Element.attribute = " + (keyword == "vary" ? "RANGE'" : "VALUE'"), where);
  std::pair<std::string, std::string> nv{trim(rest.substr(0, eq)), trim(rest.substr(eq + 1))};
  checkValueName(nv.first, where);
  if (nv.second.empty()) throw InputError(keyword + " " + nv.first + ": no value after '='", where);
  return nv;
}

}  // namespace

std::vector<std::string> expandSweepRange(const std::string& spec, const std::string& where) {
  const std::vector<std::string> w = words(spec);
  const std::string usage = "expected 'list V1 V2 ...', 'linear FROM TO COUNT' or 'log FROM TO COUNT'";
  if (w.empty()) throw InputError("empty range: " + usage, where);
  if (w[0] == "list") {
    if (w.size() < 2) throw InputError("'list' needs at least one value", where);
    std::vector<std::string> values(w.begin() + 1, w.end());
    std::set<std::string> seen;
    for (const std::string& v : values)
      if (!seen.insert(v).second) throw InputError("'list' names the value " + clipForMessage(v) + " twice", where);
    return values;
  }
  if (w[0] != "linear" && w[0] != "log")
    throw InputError("unknown range '" + clipForMessage(w[0]) + "'" + suggestionText(w[0], {"list", "linear", "log"}) +
                         ": " + usage,
                     where);
  if (w.size() != 4) throw InputError("'" + w[0] + "' takes FROM TO COUNT, got " + std::to_string(w.size() - 1) +
                                          " value(s)", where);
  const double from = number(w[1], w[0] + " FROM", where), to = number(w[2], w[0] + " TO", where);
  const int count = integer(w[3], w[0] + " COUNT", 1, kMaxSweepPoints, where);
  if (w[0] == "log" && !(from > 0 && to > 0))
    throw InputError("'log' needs FROM and TO above zero (got " + w[1] + " and " + w[2] + ")", where);
  std::vector<std::string> values;
  for (int i = 0; i < count; ++i) {
    const double s = count == 1 ? 0.0 : double(i) / double(count - 1);
    const double v = w[0] == "linear" ? from + s * (to - from) : from * std::pow(to / from, s);
    values.push_back(sixDigits(i == count - 1 ? to : v));
  }
  for (std::size_t i = 1; i < values.size(); ++i)
    if (values[i] == values[i - 1])
      throw InputError("'" + w[0] + "' gives the value " + values[i] + " twice at six significant digits: fewer "
                           "values or a wider range",
                       where);
  return values;
}

SweepDescription parseSweepDescription(const std::string& text, const std::string& path) {
  SweepDescription d;
  d.source = path;
  std::set<std::string> given, names;
  std::istringstream in(text);
  int lineNo = 0;
  for (std::string raw; std::getline(in, raw);) {
    ++lineNo;
    const std::string where = path + ":" + std::to_string(lineNo);
    const std::string line = trim(raw.substr(0, raw.find('#')));
    if (line.empty()) continue;
    const std::size_t split = line.find_first_of(" \t=");
    const std::string key = line.substr(0, split);
    const std::string rest = split == std::string::npos ? "" : trim(line.substr(split));
    if (key == "set" || key == "vary") {
      const auto nv = nameAndValue(rest, key, where);
      if (!names.insert(nv.first).second)
        throw InputError(nv.first + " is named twice (one set or vary line per scene value)", where);
      if (key == "set") d.fixed.push_back({nv.first, nv.second, where});
      else d.parameters.push_back({nv.first, expandSweepRange(nv.second, where), where});
      continue;
    }
    if (rest.empty() || rest[0] != '=')
      throw InputError(std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end()
                           ? "unknown setting '" + clipForMessage(key) + "'" + suggestionText(key, kKeys)
                           : "expected '" + key + " = VALUE'",
                       where);
    const std::string value = trim(rest.substr(1));
    if (std::find(kKeys.begin(), kKeys.end(), key) == kKeys.end())
      throw InputError("unknown setting '" + clipForMessage(key) + "'" + suggestionText(key, kKeys), where);
    if (!given.insert(key).second) throw InputError("'" + key + "' is given twice", where);
    if (value.empty()) throw InputError("'" + key + "' has no value", where);
    if (key == "scene") d.scene = pathBesideScene(path, value);
    else if (key == "frames") d.frames = integer(value, "frames", 1, kMaxRunFrames, where);
    else if (key == "time") {
      d.time = number(value, "time", where);
      if (!(d.time > 0)) throw InputError("time must be above zero", where);
    } else if (key == "checkpoint_every") d.checkpointEvery = integer(value, "checkpoint_every", 1, kMaxRunFrames, where);
    else if (key == "repeats") d.repeats = integer(value, "repeats", 1, 1000, where);
    else if (key == "device") {
      if (value != "auto" && value != "cpu" && value != "cuda")
        throw InputError("device must be auto, cpu or cuda, not '" + clipForMessage(value) + "'", where);
      d.device = value;
    }
  }
  if (d.scene.empty()) throw InputError("no 'scene = FILE' line: a sweep runs one scene", path);
  if (given.count("frames") && given.count("time")) throw InputError("give frames or time, not both", path);
  long long points = d.repeats;
  for (const SweepParameter& p : d.parameters) {
    points *= (long long)p.values.size();
    if (points > kMaxSweepPoints)
      throw InputError("the sweep expands to more than " + std::to_string(kMaxSweepPoints) + " points", p.where);
  }
  return d;
}

SweepDescription readSweepDescription(const std::string& path) {
  return parseSweepDescription(readInputFile(path, 1 << 20, "sweep description"), path);
}

std::string sweepRunFingerprint(const SweepDescription& d) {
  std::ostringstream o;
  o << "scene = " << d.scene << "\n";
  if (d.frames >= 0) o << "frames = " << d.frames << "\n";
  if (d.time >= 0) o << "time = " << sixDigits(d.time) << "\n";
  o << "device = " << d.device << "\n";
  for (const SweepSetting& s : d.fixed) o << "set " << s.name << " = " << s.value << "\n";
  for (const SweepParameter& p : d.parameters) o << "vary " << p.name << "\n";
  return o.str();
}

std::string sweepDescriptionText(const SweepDescription& d) {
  std::ostringstream o;
  o << "# The sweep as planned (soak sweep plan); ranges written out as lists.\n";
  o << "scene = " << d.scene << "\n";
  if (d.frames >= 0) o << "frames = " << d.frames << "\n";
  if (d.time >= 0) o << "time = " << sixDigits(d.time) << "\n";
  o << "checkpoint_every = " << d.checkpointEvery << "\n";
  o << "repeats = " << d.repeats << "\n";
  o << "device = " << d.device << "\n";
  for (const SweepSetting& s : d.fixed) o << "set " << s.name << " = " << s.value << "\n";
  for (const SweepParameter& p : d.parameters) {
    o << "vary " << p.name << " = list";
    for (const std::string& v : p.values) o << " " << v;
    o << "\n";
  }
  return o.str();
}

}  // namespace soak
