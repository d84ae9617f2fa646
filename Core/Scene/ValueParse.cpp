#include "Scene/ValueParse.h"

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <limits>
#include <sstream>
#include <vector>

#include "Base/MessageText.h"
#include "Base/SafeName.h"

namespace soak {

namespace {
std::string trim(const std::string& s) {
  std::size_t b = s.find_first_not_of(" \t\r\n"), e = s.find_last_not_of(" \t\r\n");
  return b == std::string::npos ? std::string() : s.substr(b, e - b + 1);
}
std::vector<std::string> splitList(const std::string& s) {
  std::vector<std::string> parts;
  std::string cur;
  for (char c : s) {
    if (c == ',' || c == ' ' || c == '\t' || c == '\n' || c == '\r') {
      if (!cur.empty()) parts.push_back(cur);
      cur.clear();
    } else {
      cur += c;
    }
  }
  if (!cur.empty()) parts.push_back(cur);
  return parts;
}
bool toDouble(const std::string& s, double& v) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  v = std::strtod(s.c_str(), &end);
  return end == s.c_str() + s.size() && errno == 0 && std::isfinite(v);
}
bool toInteger(const std::string& s, long long& v) {
  if (s.empty()) return false;
  errno = 0;
  char* end = nullptr;
  v = std::strtoll(s.c_str(), &end, 10);
  return end == s.c_str() + s.size() && errno == 0;
}
std::string shown(const std::string& raw) { return "'" + clipForMessage(raw) + "'"; }
bool inRange(const ParamDecl& d, double v) {
  if (d.minExclusive ? !(v > d.min) : !(v >= d.min)) return false;
  return v <= d.max;
}
// Reals reach the kernels as 32-bit floats: a value must be checked in that
// type too (1e39 becomes inf, 1e-50 becomes 0).
bool fitsFloat(const ParamDecl& d, const std::string& text, double v, std::string& error) {
  const float f = static_cast<float>(v);
  if (!std::isfinite(f)) {
    error = "value " + clipForMessage(text) + " is beyond a 32-bit float (largest 3.4e38), the type it is stored in";
    return false;
  }
  if (!inRange(d, double(f))) {
    std::ostringstream s;
    s << "value " << clipForMessage(text) << " becomes " << f << " as a 32-bit float, the type it is stored in, "
      << "which is out of range; allowed: " << d.rangeText();
    error = s.str();
    return false;
  }
  return true;
}
// Integers are stored as 32-bit ints (counts, indices).
bool fitsInt(long long v) {
  return v >= std::numeric_limits<int>::min() && v <= std::numeric_limits<int>::max();
}
}  // namespace

bool parseParamValue(const ParamDecl& d, const std::string& raw, ParamValue& out, std::string& error) {
  const std::string text = trim(raw);
  out = ParamValue();
  out.type = d.type;
  switch (d.type) {
    case ParamType::Real: {
      if (!toDouble(text, out.real)) {
        error = shown(raw) + " is not a finite number";
        return false;
      }
      if (!inRange(d, out.real)) {
        error = "value " + clipForMessage(text) + " is out of range; allowed: " + d.rangeText();
        return false;
      }
      return fitsFloat(d, text, out.real, error);
    }
    case ParamType::Integer: {
      if (!toInteger(text, out.integer)) {
        error = shown(raw) + " is not an integer";
        return false;
      }
      if (!inRange(d, double(out.integer)) || !fitsInt(out.integer)) {
        error = "value " + clipForMessage(text) + " is out of range; allowed: " + d.rangeText();
        return false;
      }
      return true;
    }
    case ParamType::Boolean: {
      if (text == "true" || text == "1" || text == "yes" || text == "on") out.boolean = true;
      else if (text == "false" || text == "0" || text == "no" || text == "off") out.boolean = false;
      else {
        error = shown(raw) + " is not a boolean; allowed: true or false";
        return false;
      }
      return true;
    }
    case ParamType::Vector: {
      std::vector<std::string> parts = splitList(text);
      double c[3];
      if (parts.size() != 3 || !toDouble(parts[0], c[0]) || !toDouble(parts[1], c[1]) || !toDouble(parts[2], c[2])) {
        error = shown(raw) + " is not a vector of three finite numbers (e.g. \"0 -9.81 0\")";
        return false;
      }
      for (int k = 0; k < 3; ++k)
        if (!std::isfinite(float(c[k]))) {
          error = shown(raw) + ": component " + clipForMessage(parts[k]) + " is beyond a 32-bit float (largest 3.4e38)";
          return false;
        }
      out.vector = Vec3(float(c[0]), float(c[1]), float(c[2]));
      return true;
    }
    case ParamType::Text:
      out.text = text;
      if (d.textKind == TextKind::Name && !(text.empty() && d.defaultValue.empty()) &&
          !isSafeFileName(text, kMaxNameLength)) {
        error = shown(raw) + " is not a usable name; allowed: " + d.rangeText();
        return false;
      }
      return true;
    case ParamType::Choice: {
      for (const std::string& c : d.choices)
        if (c == text) {
          out.text = text;
          return true;
        }
      error = shown(raw) + " is not allowed; allowed: " + d.rangeText();
      return false;
    }
    case ParamType::IntegerList: {
      for (const std::string& p : splitList(text)) {
        long long v = 0;
        if (!toInteger(p, v) || !fitsInt(v)) {
          error = shown(p) + " in " + shown(raw) + " is not a 32-bit integer";
          return false;
        }
        out.list.push_back(v);
      }
      return true;
    }
  }
  error = "unknown parameter type";
  return false;
}

}  // namespace soak
