#include "Scene/Scene.h"

#include <algorithm>
#include <fstream>
#include <map>
#include <set>
#include <pugixml.hpp>
#include <sstream>

#include "Base/Error.h"
#include "Base/MessageText.h"
#include "Base/ReadInput.h"
#include "Scene/Suggest.h"
#include "Scene/ValueParse.h"

namespace soak {

namespace {

// Maps pugixml's character offsets to 1-based line numbers. A line ends at
// "\n", "\r\n" or a lone "\r" (old Mac files), as XML 1.0 Section 2.11 reads them.
class LineIndex {
 public:
  explicit LineIndex(const std::string& text) {
    for (std::size_t i = 0; i < text.size(); ++i)
      if (text[i] == '\n' || (text[i] == '\r' && (i + 1 == text.size() || text[i + 1] != '\n')))
        newlines_.push_back(static_cast<long>(i));
  }
  int lineOf(std::ptrdiff_t offset) const {
    if (offset < 0) return 0;
    auto it = std::lower_bound(newlines_.begin(), newlines_.end(), static_cast<long>(offset));
    return static_cast<int>(it - newlines_.begin()) + 1;
  }

 private:
  std::vector<long> newlines_;
};

struct Override {
  std::string element;
  int index = -1;  // -1: the only one
  std::string attribute;
  std::string value;
  std::string text;
};

// An override as its messages name it, cut like any value.
std::string overrideBlame(const std::string& text) { return "--set '" + clipForMessage(text) + "'"; }

Override parseOverride(const std::string& s) {
  Override o;
  o.text = s;
  std::size_t eq = s.find('=');
  std::size_t dot = s.rfind('.', eq);
  if (eq == std::string::npos || dot == std::string::npos || dot == 0 || dot + 1 >= eq)
    throw InputError(overrideBlame(s) + ": expected Element.attribute=value or Element[i].attribute=value");
  std::string el = s.substr(0, dot);
  o.attribute = s.substr(dot + 1, eq - dot - 1);
  o.value = s.substr(eq + 1);
  std::size_t br = el.find('[');
  if (br != std::string::npos) {
    if (el.back() != ']') throw InputError(overrideBlame(s) + ": bad index in '" + clipForMessage(el) + "'");
    try {
      o.index = std::stoi(el.substr(br + 1, el.size() - br - 2));
    } catch (...) {
      throw InputError(overrideBlame(s) + ": bad index in '" + clipForMessage(el) + "'");
    }
    if (o.index < 0) throw InputError(overrideBlame(s) + ": index must be >= 0");
    el = el.substr(0, br);
  }
  o.element = el;
  return o;
}

// Where a value given by --set is blamed: the option itself, not the line of
// the element it lands on (or line 0 of an element it had to add).
using OverrideOrigins = std::map<std::pair<const void*, std::string>, std::string>;

void applyOverride(pugi::xml_node root, const Override& o, const ModuleRegistry& registry,
                   OverrideOrigins& origins) {
  const ElementDecl* decl = registry.find(o.element);
  if (!decl)
    throw InputError(overrideBlame(o.text) + ": unknown element <" + clipForMessage(o.element) + ">" +
                     suggestionText(o.element, registry.names()));
  std::vector<pugi::xml_node> matches;
  for (pugi::xml_node n : root.children(o.element.c_str())) matches.push_back(n);
  pugi::xml_node target;
  if (o.index >= 0) {
    if (o.index >= static_cast<int>(matches.size()))
      throw InputError(overrideBlame(o.text) + ": the scene has " + std::to_string(matches.size()) + " <" +
                       o.element + "> element(s)");
    target = matches[o.index];
  } else if (matches.size() == 1) {
    target = matches[0];
  } else if (matches.empty() && decl->unique) {
    // A settings element the scene left out: add it so the override applies.
    target = root.append_child(o.element.c_str());
  } else if (matches.empty()) {
    throw InputError(overrideBlame(o.text) + ": the scene has no <" + o.element + "> element");
  } else {
    throw InputError(overrideBlame(o.text) + ": the scene has " + std::to_string(matches.size()) + " <" +
                     o.element + "> elements; write " + o.element + "[0]." + o.attribute + "=... to pick one");
  }
  pugi::xml_attribute a = target.attribute(o.attribute.c_str());
  if (!a) a = target.append_attribute(o.attribute.c_str());
  a.set_value(o.value.c_str());
  origins[{target.internal_object(), o.attribute}] = overrideBlame(o.text);
  // The element itself, when an override had to add it.
  if (target.offset_debug() < 0) origins.emplace(std::make_pair(target.internal_object(), std::string()), overrideBlame(o.text));
}

// pugixml keeps a repeated attribute (and reads the first); XML 1.0
// (Section 3.1, "Unique Att Spec") makes it malformed.
void refuseRepeatedAttributes(pugi::xml_node n, const std::string& where) {
  std::set<std::string> names;
  for (pugi::xml_attribute a : n.attributes())
    if (!names.insert(a.name()).second)
      throw InputError("malformed XML: <" + std::string(n.name()) + "> has attribute '" + std::string(a.name()) +
                           "' twice (XML allows each attribute once per element)",
                       where);
}

std::vector<std::string> paramNames(const ElementDecl& d) {
  std::vector<std::string> n;
  for (const ParamDecl& p : d.params) n.push_back(p.name);
  return n;
}

}  // namespace

Scene Scene::load(const std::string& path, const std::vector<std::string>& overrides, ModuleRegistry& registry,
                  const PluginRequest& loadPlugin) {
  return parse(readInputFile(path, kMaxSceneBytes, "scene file"), path, overrides, registry, loadPlugin);
}

Scene Scene::parse(const std::string& text, const std::string& path, const std::vector<std::string>& overrides,
                   ModuleRegistry& registry, const PluginRequest& loadPlugin) {
  Scene scene;
  scene.path_ = path;
  scene.inputFiles_.push_back(path);
  LineIndex lines(text);
  auto where = [&](int line) { return path + ":" + std::to_string(line); };

  const std::size_t nul = text.find('\0');
  if (nul != std::string::npos)
    throw InputError("not a text file: byte " + std::to_string(nul) + " is NUL; a scene is XML text",
                     where(lines.lineOf(int(nul))));
  pugi::xml_document doc;
  pugi::xml_parse_result res = doc.load_buffer(text.data(), text.size(), pugi::parse_default | pugi::parse_comments);
  if (res.status == pugi::status_no_document_element)
    throw InputError("empty scene: expected a <Scene> root element", where(1));
  if (!res) throw InputError(std::string("malformed XML: ") + res.description(), where(lines.lineOf(res.offset)));
  pugi::xml_node root = doc.document_element();
  if (!root) throw InputError("empty scene: expected a <Scene> root element", where(1));
  if (std::string(root.name()) != "Scene")
    throw InputError("root element is <" + std::string(root.name()) + ">, expected <Scene>",
                     where(lines.lineOf(root.offset_debug())));
  refuseRepeatedAttributes(root, where(lines.lineOf(root.offset_debug())));
  for (pugi::xml_attribute a : root.attributes())
    if (std::string(a.name()) != "name" && std::string(a.name()) != "description")
      throw InputError("<Scene>: unknown attribute '" + std::string(a.name()) + "'" +
                           suggestionText(a.name(), {"name", "description"}),
                       where(lines.lineOf(root.offset_debug())));

  // Plugins first, so that their elements are known when the rest is checked.
  for (pugi::xml_node n : root.children("Plugin")) {
    std::string w = where(lines.lineOf(n.offset_debug()));
    refuseRepeatedAttributes(n, w);
    std::string p = n.attribute("path").as_string(), name = n.attribute("name").as_string();
    for (pugi::xml_attribute a : n.attributes())
      if (std::string(a.name()) != "path" && std::string(a.name()) != "name")
        throw InputError("<Plugin>: unknown attribute '" + std::string(a.name()) + "'" +
                             suggestionText(a.name(), {"name", "path"}), w);
    if (p.empty() && name.empty()) throw InputError("<Plugin> needs name=\"...\" or path=\"...\"", w);
    if (!loadPlugin) throw InputError("<Plugin>: plugins cannot be loaded here", w);
    if (!p.empty()) {
      const std::string resolved = pathBesideScene(scene.path_, p);
      scene.inputFiles_.push_back(resolved);
      loadPlugin(resolved, true, w);
    } else {
      loadPlugin(name, false, w);
    }
  }

  OverrideOrigins origins;
  for (const std::string& s : overrides) applyOverride(root, parseOverride(s), registry, origins);

  std::map<std::string, int> seen;
  for (pugi::xml_node n = root.first_child(); n; n = n.next_sibling()) {
    if (n.type() == pugi::node_comment) continue;
    const int line = lines.lineOf(n.offset_debug());
    // Where this element's errors point: its line, or the --set that added it.
    const auto addedBy = origins.find({n.internal_object(), std::string()});
    const std::string elementWhere = addedBy != origins.end() ? addedBy->second : where(line);
    auto attributeWhere = [&](const std::string& attribute) {
      const auto it = origins.find({n.internal_object(), attribute});
      return it != origins.end() ? it->second : elementWhere;
    };
    if (n.type() != pugi::node_element) {
      std::string t = n.value();
      if (t.find_first_not_of(" \t\r\n") == std::string::npos) continue;
      const std::size_t first = t.find_first_not_of(" \t\r\n");
      std::string shown = t.substr(first, 40);
      shown = shown.substr(0, shown.find_first_of("\r\n"));
      throw InputError("unexpected text inside <Scene>: '" + shown + "' (elements only)", where(lines.lineOf(int(n.offset_debug() + first))));
    }
    const std::string name = n.name();
    const ElementDecl* decl = registry.find(name);
    if (!decl) {
      // A typo, or a plugin's element whose plugin is not loaded.
      throw InputError("unknown element <" + clipForMessage(name) + ">" + suggestionText(name, registry.names()) +
                           "; if a plugin provides it, put the plugin in the plugin directory or load it with "
                           "<Plugin name=\"...\"/> or --plugin",
                       where(line));
    }
    if (decl->unique && seen[name]++ > 0)
      throw InputError("<" + name + "> may appear only once per scene", where(line));
    // Child elements and text, CDATA sections included, are refused alike.
    for (pugi::xml_node c = n.first_child(); c; c = c.next_sibling())
      if (c.type() == pugi::node_element ||
          ((c.type() == pugi::node_pcdata || c.type() == pugi::node_cdata) &&
           std::string(c.value()).find_first_not_of(" \t\r\n") != std::string::npos))
        throw InputError("<" + name + "> takes attributes only, no child elements or text",
                         where(lines.lineOf(c.offset_debug())));
    SceneElement el;
    el.decl = decl;
    el.line = line;
    el.params = ElementParams(decl, elementWhere);
    refuseRepeatedAttributes(n, elementWhere);
    for (pugi::xml_attribute a : n.attributes()) {
      if (!decl->find(a.name()))
        throw InputError("<" + name + ">: unknown attribute '" + clipForMessage(a.name()) + "'" +
                             suggestionText(a.name(), paramNames(*decl)),
                         attributeWhere(a.name()));
    }
    for (const ParamDecl& p : decl->params) {
      pugi::xml_attribute a = n.attribute(p.name.c_str());
      if (!a && p.required)
        throw InputError("<" + name + ">: attribute '" + p.name + "' is required (" + p.description + ")",
                         elementWhere);
      ParamValue v;
      std::string error;
      if (!parseParamValue(p, a ? a.value() : p.defaultValue, v, error)) {
        if (!a) throw std::logic_error("default of <" + name + "> " + p.name + " is invalid: " + error);
        throw InputError("<" + name + ">: attribute '" + p.name + "': " + error, attributeWhere(p.name));
      }
      if (p.type == ParamType::Text && p.textKind == TextKind::InputFile && !v.text.empty())
        scene.inputFiles_.push_back(el.params.resolvePath(v.text));
      el.params.set(p.name, v, bool(a));
    }
    scene.elements_.push_back(std::move(el));
  }

  std::ostringstream out;
  doc.save(out, "  ");
  scene.textAsRun_ = out.str();
  return scene;
}

}  // namespace soak
