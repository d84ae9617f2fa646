#pragma once
#include <functional>
#include <map>
#include <memory>
#include <string>
#include <vector>

#include "Registry/Param.h"

namespace soak {

class Module;
class ElementParams;

using ModuleFactory = std::function<std::unique_ptr<Module>(const ElementParams&)>;

// A scene element (<Plane .../>, <WetCloth .../>): its parameters and the
// factory that turns a validated element into a module. Built with the
// chained helpers below, e.g.
//   ElementDecl("Sphere", "Static sphere collider")
//     .vector("center", "m", "0 0 0", "Centre of the sphere")
//     .real("radius", "m", "0.1", "Radius", 0.0, 1e3, true);
struct ElementDecl {
  std::string name;
  std::string description;
  std::string group;        // section of the reference page (e.g. "Colliders")
  bool unique = false;      // at most once per scene
  std::string provider = "Core";  // plugin name for plugin elements
  std::vector<ParamDecl> params;
  ModuleFactory factory;

  ElementDecl() = default;
  ElementDecl(std::string name_, std::string description_, std::string group_ = "General")
      : name(std::move(name_)), description(std::move(description_)), group(std::move(group_)) {}

  ElementDecl& real(const std::string& n, const std::string& unit, const std::string& def, const std::string& desc,
                    double lo = -1e300, double hi = 1e300, bool loExclusive = false);
  ElementDecl& integer(const std::string& n, const std::string& def, const std::string& desc,
                       double lo = -2147483648.0, double hi = 2147483647.0);
  ElementDecl& boolean(const std::string& n, const std::string& def, const std::string& desc);
  ElementDecl& vector(const std::string& n, const std::string& unit, const std::string& def, const std::string& desc);
  ElementDecl& text(const std::string& n, const std::string& def, const std::string& desc, bool required = false);
  // A name that becomes part of file names (letters, digits, _ - .).
  ElementDecl& fileSafeName(const std::string& n, const std::string& def, const std::string& desc);
  // A path of a file the run reads, relative to the scene's folder.
  ElementDecl& inputFile(const std::string& n, const std::string& def, const std::string& desc);
  ElementDecl& choice(const std::string& n, const std::vector<std::string>& choices, const std::string& def,
                      const std::string& desc);
  ElementDecl& integerList(const std::string& n, const std::string& def, const std::string& desc);
  ElementDecl& makeUnique() { unique = true; return *this; }
  ElementDecl& create(ModuleFactory f) { factory = std::move(f); return *this; }

  const ParamDecl* find(const std::string& paramName) const;
};

// Validated values of one element, by parameter name. Every declared
// parameter is present (the default fills what the scene left out).
class ElementParams {
 public:
  ElementParams() = default;
  ElementParams(const ElementDecl* decl, std::string where) : decl_(decl), where_(std::move(where)) {}

  double real(const std::string& n) const;
  float realf(const std::string& n) const { return static_cast<float>(real(n)); }
  long long integer(const std::string& n) const;
  bool boolean(const std::string& n) const;
  Vec3 vector(const std::string& n) const;
  const std::string& text(const std::string& n) const;
  const std::vector<long long>& integerList(const std::string& n) const;
  // True if the scene wrote this attribute (false: default used).
  bool given(const std::string& n) const;

  const std::string& where() const { return where_; }  // "file:line" of the element
  // `file` relative to the folder of the scene file (unless absolute).
  std::string resolvePath(const std::string& file) const;
  const ElementDecl& decl() const { return *decl_; }

  void set(const std::string& n, ParamValue v, bool given);

 private:
  const ParamValue& get(const std::string& n, ParamType t) const;
  const ElementDecl* decl_ = nullptr;
  std::string where_;
  std::map<std::string, ParamValue> values_;
  std::map<std::string, bool> given_;
};

}  // namespace soak
