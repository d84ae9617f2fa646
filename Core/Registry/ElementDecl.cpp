#include "Registry/ElementDecl.h"

#include "Base/ReadInput.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

#include "Base/MessageText.h"
#include "Base/SafeName.h"

namespace soak {

const char* paramTypeName(ParamType t) {
  switch (t) {
    case ParamType::Real: return "real";
    case ParamType::Integer: return "integer";
    case ParamType::Boolean: return "boolean";
    case ParamType::Vector: return "vector";
    case ParamType::Text: return "text";
    case ParamType::Choice: return "choice";
    case ParamType::IntegerList: return "integer list";
  }
  return "?";
}


std::string ParamDecl::rangeText() const {
  if (type == ParamType::Choice) {
    std::string s = "one of: ";
    for (std::size_t i = 0; i < choices.size(); ++i) s += (i ? ", " : "") + choices[i];
    return s;
  }
  if (type == ParamType::Boolean) return "true or false";
  if (type == ParamType::Text && textKind == TextKind::Name)
    return "letters, digits, _ - . (at most " + std::to_string(kMaxNameLength) + ", not starting with .)";
  if (type != ParamType::Real && type != ParamType::Integer) return "";
  bool lo = std::isfinite(min) && min > -1e299, hi = std::isfinite(max) && max < 1e299;
  if (type == ParamType::Integer) {
    lo = lo && min > -2147483648.0;  // the full 32-bit range is not worth printing
    hi = hi && max < 2147483647.0;
  }
  if (!lo && !hi) return "any";
  std::string s = lo ? (minExclusive ? "(" : "[") + formatNumber(min) : "(-inf";
  s += ", ";
  s += hi ? formatNumber(max) + "]" : "inf)";
  return s;
}

namespace {
ParamDecl& addParam(std::vector<ParamDecl>& params, const std::string& name, ParamType type, const std::string& unit,
                    const std::string& def, const std::string& desc) {
  ParamDecl p;
  p.name = name;
  p.type = type;
  p.unit = unit;
  p.defaultValue = def;
  p.description = desc;
  params.push_back(p);
  return params.back();
}
}  // namespace

ElementDecl& ElementDecl::real(const std::string& n, const std::string& unit, const std::string& def,
                               const std::string& desc, double lo, double hi, bool loExclusive) {
  ParamDecl& p = addParam(params, n, ParamType::Real, unit, def, desc);
  p.min = lo;
  p.max = hi;
  p.minExclusive = loExclusive;
  return *this;
}
ElementDecl& ElementDecl::integer(const std::string& n, const std::string& def, const std::string& desc, double lo,
                                  double hi) {
  ParamDecl& p = addParam(params, n, ParamType::Integer, "", def, desc);
  p.min = lo;
  p.max = hi;
  return *this;
}
ElementDecl& ElementDecl::boolean(const std::string& n, const std::string& def, const std::string& desc) {
  addParam(params, n, ParamType::Boolean, "", def, desc);
  return *this;
}
ElementDecl& ElementDecl::vector(const std::string& n, const std::string& unit, const std::string& def,
                                 const std::string& desc) {
  addParam(params, n, ParamType::Vector, unit, def, desc);
  return *this;
}
ElementDecl& ElementDecl::text(const std::string& n, const std::string& def, const std::string& desc, bool required) {
  addParam(params, n, ParamType::Text, "", def, desc).required = required;
  return *this;
}
ElementDecl& ElementDecl::fileSafeName(const std::string& n, const std::string& def, const std::string& desc) {
  addParam(params, n, ParamType::Text, "", def, desc).textKind = TextKind::Name;
  return *this;
}
ElementDecl& ElementDecl::inputFile(const std::string& n, const std::string& def, const std::string& desc) {
  addParam(params, n, ParamType::Text, "", def, desc).textKind = TextKind::InputFile;
  return *this;
}
ElementDecl& ElementDecl::choice(const std::string& n, const std::vector<std::string>& choices,
                                 const std::string& def, const std::string& desc) {
  addParam(params, n, ParamType::Choice, "", def, desc).choices = choices;
  return *this;
}
ElementDecl& ElementDecl::integerList(const std::string& n, const std::string& def, const std::string& desc) {
  addParam(params, n, ParamType::IntegerList, "", def, desc);
  return *this;
}

const ParamDecl* ElementDecl::find(const std::string& paramName) const {
  for (const ParamDecl& p : params)
    if (p.name == paramName) return &p;
  return nullptr;
}

void ElementParams::set(const std::string& n, ParamValue v, bool given) {
  values_[n] = std::move(v);
  given_[n] = given;
}

const ParamValue& ElementParams::get(const std::string& n, ParamType t) const {
  auto it = values_.find(n);
  if (it == values_.end())
    throw std::logic_error("parameter '" + n + "' is not declared for <" + (decl_ ? decl_->name : "?") + ">");
  if (it->second.type != t)
    throw std::logic_error("parameter '" + n + "' read as " + paramTypeName(t) + " but declared " +
                           paramTypeName(it->second.type));
  return it->second;
}

double ElementParams::real(const std::string& n) const { return get(n, ParamType::Real).real; }
long long ElementParams::integer(const std::string& n) const { return get(n, ParamType::Integer).integer; }
bool ElementParams::boolean(const std::string& n) const { return get(n, ParamType::Boolean).boolean; }
Vec3 ElementParams::vector(const std::string& n) const { return get(n, ParamType::Vector).vector; }
const std::string& ElementParams::text(const std::string& n) const {
  auto it = values_.find(n);
  if (it != values_.end() && it->second.type == ParamType::Choice) return it->second.text;
  return get(n, ParamType::Text).text;
}
const std::vector<long long>& ElementParams::integerList(const std::string& n) const {
  return get(n, ParamType::IntegerList).list;
}
bool ElementParams::given(const std::string& n) const {
  auto it = given_.find(n);
  return it != given_.end() && it->second;
}

std::string ElementParams::resolvePath(const std::string& file) const {
  const auto colon = where_.rfind(':');  // where_ is "scene file:line"
  return pathBesideScene(colon == std::string::npos ? where_ : where_.substr(0, colon), file);
}

}  // namespace soak
