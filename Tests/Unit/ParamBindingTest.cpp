// Parameters bound to struct members (Registry/ParamBinding.h): the
// declared default is the member's, read back exactly (through a unit
// scale too); a scene's values fill the members; choices map to enums.
#include <gtest/gtest.h>

#include <memory>
#include <string>

#include "Registry/ParamBinding.h"
#include "Scene/Scene.h"
#include "Support/TestScenes.h"

using namespace soak;

namespace {

enum class Shape { Round, Square };

struct Knobs {
  float rate = 0.1f;      // per 0.015 s, declared per second
  float weight = 0.4f;
  int passes = 3;
  bool on = true;
  Shape shape = Shape::Square;
  std::string label = "plain";
  Vec3 offset{0.f, 1.5f, 0.f};
};

struct KnobsModule : Module {
  explicit KnobsModule(const Knobs& k) : knobs(k) {}
  Knobs knobs;
};

// Registers <Knobs> in `reg`; the last module it makes is left in *made.
void declareKnobs(test::TestRegistry& reg, Knobs* made) {
  ElementDecl decl("Knobs", "Test element.", "Test");
  ParamBinding<Knobs> bind(decl);
  bind.real("ratePerSecond", &Knobs::rate, "1/s", "A rate.", 0.0, 1e3, false, 0.015)
      .real("weight", &Knobs::weight, "", "A weight.", 0.0, 1.0)
      .integer("passes", &Knobs::passes, "Passes.", 0, 100)
      .boolean("on", &Knobs::on, "Switch.")
      .choice<Shape>("shape", &Knobs::shape, {{"round", Shape::Round}, {"square", Shape::Square}}, "Shape.")
      .text("label", &Knobs::label, "A name.")
      .vector("offset", &Knobs::offset, "m", "An offset.");
  reg.registry.add(decl.create([bind, made](const ElementParams& e) {
    *made = bind.read(e);
    return std::make_unique<KnobsModule>(*made);
  }));
}

Knobs parse(const std::string& element) {
  test::TestRegistry reg;
  Knobs made;
  declareKnobs(reg, &made);
  Scene s = Scene::parse("<Scene>" + element + "</Scene>", "scene.xml", {}, reg.registry, nullptr);
  const ElementDecl* decl = reg.registry.find("Knobs");
  decl->factory(s.elements().at(0).params);
  return made;
}

}  // namespace

TEST(ParamBinding, DefaultsAreTheMembersAndReadBackExactly) {
  test::TestRegistry reg;
  Knobs unused;
  declareKnobs(reg, &unused);
  const ElementDecl* decl = reg.registry.find("Knobs");
  ASSERT_NE(decl, nullptr);
  EXPECT_EQ(decl->find("weight")->defaultValue, "0.4");
  EXPECT_EQ(decl->find("passes")->defaultValue, "3");
  EXPECT_EQ(decl->find("on")->defaultValue, "true");
  EXPECT_EQ(decl->find("shape")->defaultValue, "square");
  EXPECT_EQ(decl->find("label")->defaultValue, "plain");
  EXPECT_EQ(decl->find("offset")->defaultValue, "0 1.5 0");
  EXPECT_EQ(decl->find("ratePerSecond")->defaultValue, "6.666667");  // 0.1 per 0.015 s
  const Knobs d = parse("<Knobs/>"), defaults;
  EXPECT_EQ(d.rate, defaults.rate);  // the same bits after the scale and back
  EXPECT_EQ(d.weight, defaults.weight);
  EXPECT_EQ(d.passes, defaults.passes);
  EXPECT_EQ(d.on, defaults.on);
  EXPECT_EQ(d.shape, defaults.shape);
  EXPECT_EQ(d.label, defaults.label);
  EXPECT_EQ(d.offset.y, defaults.offset.y);
}

TEST(ParamBinding, SceneValuesFillTheMembers) {
  const Knobs k =
      parse("<Knobs ratePerSecond='20' weight='0.25' passes='7' on='false' shape='round' label='' offset='1 2 3'/>");
  EXPECT_EQ(k.label, "");
  EXPECT_EQ(k.offset.z, 3.f);
  EXPECT_EQ(k.rate, float(20.0 * 0.015));
  EXPECT_EQ(k.weight, 0.25f);
  EXPECT_EQ(k.passes, 7);
  EXPECT_FALSE(k.on);
  EXPECT_EQ(k.shape, Shape::Round);
}
