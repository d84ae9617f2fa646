#pragma once
// Parameters declared once and bound to the struct member they fill:
//
//   ParamBinding<WetParams> bind(decl);
//   bind.real("sMax", &WetParams::sMax, "", "S^MAX ...", 0.0, 1.0, true)
//       .real("absorptionRate", &WetParams::kappaA, "1/s", "...", 0.0, 1e4, false, kPaperTimeStep);
//   ...  decl.create([bind](const ElementParams& e) { WetParams w = bind.read(e); ... });
//
// Each call declares the parameter on the element (ElementDecl: parsing,
// validation, `soak params` and the docs) with the member's default in
// T{} as its default, and remembers how to fill the member from a validated
// element. A default is then written once (in T), a misspelt member is a
// compile error, and the scene's name, the member and the kernel's
// argument cannot drift apart. `scale` converts the scene's unit to the
// member's (member = scene value x scale).
#include <cstdio>
#include <cstdlib>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "Registry/ElementDecl.h"

namespace soak {

namespace detail {
// The default as the scene would write it: the decimal text of
// `value / scale`, with 6 significant digits (%g) or as many more as it
// takes to read back (x scale, as a float) to exactly `value`.
template <class V>
std::string sceneText(V value, double scale) {
  char b[40];
  for (int digits = 6; digits <= 17; ++digits) {
    std::snprintf(b, sizeof b, "%.*g", digits, double(value) / scale);
    if (V(std::strtod(b, nullptr) * scale) == value) break;
  }
  return b;
}
inline std::string sceneText(Vec3 v) {
  return sceneText(v.x, 1.0) + " " + sceneText(v.y, 1.0) + " " + sceneText(v.z, 1.0);
}
}  // namespace detail

template <class T>
class ParamBinding {
 public:
  explicit ParamBinding(ElementDecl& decl) : decl_(&decl) {}

  ParamBinding& real(const std::string& name, float T::*member, const std::string& unit, const std::string& desc,
                     double lo, double hi, bool loExclusive = false, double scale = 1.0) {
    decl_->real(name, unit, detail::sceneText(defaults_.*member, scale), desc, lo, hi, loExclusive);
    setters_.push_back([name, member, scale](const ElementParams& e, T& t) {
      t.*member = float(e.real(name) * scale);
    });
    return *this;
  }
  ParamBinding& real(const std::string& name, double T::*member, const std::string& unit, const std::string& desc,
                     double lo, double hi, bool loExclusive = false) {
    decl_->real(name, unit, detail::sceneText(defaults_.*member, 1.0), desc, lo, hi, loExclusive);
    setters_.push_back([name, member](const ElementParams& e, T& t) { t.*member = e.real(name); });
    return *this;
  }
  ParamBinding& vector(const std::string& name, Vec3 T::*member, const std::string& unit, const std::string& desc) {
    decl_->vector(name, unit, detail::sceneText(defaults_.*member), desc);
    setters_.push_back([name, member](const ElementParams& e, T& t) { t.*member = e.vector(name); });
    return *this;
  }
  template <class I>  // int, long long
  ParamBinding& integer(const std::string& name, I T::*member, const std::string& desc, double lo, double hi) {
    decl_->integer(name, std::to_string(defaults_.*member), desc, lo, hi);
    setters_.push_back([name, member](const ElementParams& e, T& t) { t.*member = I(e.integer(name)); });
    return *this;
  }
  ParamBinding& boolean(const std::string& name, bool T::*member, const std::string& desc) {
    decl_->boolean(name, defaults_.*member ? "true" : "false", desc);
    setters_.push_back([name, member](const ElementParams& e, T& t) { t.*member = e.boolean(name); });
    return *this;
  }
  ParamBinding& text(const std::string& name, std::string T::*member, const std::string& desc) {
    decl_->text(name, defaults_.*member, desc);
    return setText(name, member);
  }
  // A name that becomes part of file names (ElementDecl::fileSafeName).
  ParamBinding& fileSafeName(const std::string& name, std::string T::*member, const std::string& desc) {
    decl_->fileSafeName(name, defaults_.*member, desc);
    return setText(name, member);
  }
  // A file the run reads, as the scene writes it (ElementParams::resolvePath
  // makes it a path relative to the scene's folder).
  ParamBinding& inputFile(const std::string& name, std::string T::*member, const std::string& desc) {
    decl_->inputFile(name, defaults_.*member, desc);
    return setText(name, member);
  }
  ParamBinding& integerList(const std::string& name, std::vector<long long> T::*member, const std::string& desc) {
    std::string def;
    for (long long v : defaults_.*member) def += (def.empty() ? "" : " ") + std::to_string(v);
    decl_->integerList(name, def, desc);
    setters_.push_back([name, member](const ElementParams& e, T& t) { t.*member = e.integerList(name); });
    return *this;
  }
  // A choice of named values of an enum (or any comparable type).
  template <class E>
  ParamBinding& choice(const std::string& name, E T::*member, const std::vector<std::pair<std::string, E>>& options,
                       const std::string& desc) {
    std::vector<std::string> names;
    std::string def;
    for (const auto& o : options) {
      names.push_back(o.first);
      if (o.second == defaults_.*member) def = o.first;
    }
    decl_->choice(name, names, def, desc);
    setters_.push_back([name, member, options](const ElementParams& e, T& t) {
      const std::string& v = e.text(name);
      for (const auto& o : options)
        if (o.first == v) t.*member = o.second;
    });
    return *this;
  }

  // T{} with every bound member filled from the element.
  T read(const ElementParams& e) const {
    T t = defaults_;
    fill(e, t);
    return t;
  }
  // Only the bound members of `t` (the others keep their values).
  void fill(const ElementParams& e, T& t) const {
    for (const auto& set : setters_) set(e, t);
  }

 private:
  // The text kinds all fill a string from the element's text.
  ParamBinding& setText(const std::string& name, std::string T::*member) {
    setters_.push_back([name, member](const ElementParams& e, T& t) { t.*member = e.text(name); });
    return *this;
  }
  ElementDecl* decl_;  // declaring only: the binding may outlive it
  T defaults_{};
  std::vector<std::function<void(const ElementParams&, T&)>> setters_;
};

}  // namespace soak
