// Sweep descriptions and plans (Core/Sweep): ranges expand as written,
// mistakes name their file and line, point ids depend only on the values,
// and planning again keeps what is there.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>

#include "Base/Error.h"
#include "Sweep/SweepCollect.h"
#include "Sweep/SweepFolder.h"
#include "SoakProcess.h"

using namespace soak;
using namespace soak::test;

namespace {

const std::string kScene = std::string(SOAK_SOURCE_DIR) + "/Tests/Sweep/wet_sheet.xml";

std::string errorOf(const std::string& text) {
  try {
    parseSweepDescription(text, "sweep.txt");
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

SweepDescription twoByTwo() {
  return parseSweepDescription("scene = " + kScene +
                                   "\nframes = 2\nvary Nozzle.speed = list 1 2\nvary WetCloth.initialSaturation = "
                                   "linear 0.2 0.4 2\n",
                               "sweep.txt");
}

}  // namespace

TEST(SweepPlan, RangesExpandToTheirValues) {
  EXPECT_EQ(expandSweepRange("list a 2 3.5", "x"), (std::vector<std::string>{"a", "2", "3.5"}));
  EXPECT_EQ(expandSweepRange("linear 0 1 5", "x"), (std::vector<std::string>{"0", "0.25", "0.5", "0.75", "1"}));
  EXPECT_EQ(expandSweepRange("log 0.001 1 4", "x"), (std::vector<std::string>{"0.001", "0.01", "0.1", "1"}));
  EXPECT_EQ(expandSweepRange("log 0.002 0.02 3", "x"), (std::vector<std::string>{"0.002", "0.00632456", "0.02"}));
  EXPECT_EQ(expandSweepRange("linear 3 3 1", "x"), (std::vector<std::string>{"3"}));
}

TEST(SweepPlan, MistakesNameTheFileAndLine) {
  EXPECT_EQ(errorOf("scene = a.xml\n\nvary X.y = lin 1 2 3\n").rfind("sweep.txt:3: unknown range 'lin'", 0), 0u)
      << errorOf("scene = a.xml\n\nvary X.y = lin 1 2 3\n");
  EXPECT_NE(errorOf("scene = a.xml\nvary X.y = linar 1 2 3\n").find("did you mean 'linear'"), std::string::npos);
  EXPECT_EQ(errorOf("scene = a.xml\nvary X.y = log -1 2 3\n").rfind("sweep.txt:2: 'log' needs FROM and TO above zero", 0),
            0u);
  EXPECT_EQ(errorOf("scene = a.xml\nvary X.y = linear 1 2 2.5\n").rfind("sweep.txt:2: linear COUNT must be an integer", 0),
            0u);
  EXPECT_EQ(errorOf("scene = a.xml\n# fine\nframs = 3\n").rfind("sweep.txt:3: unknown setting 'frams'", 0), 0u);
  EXPECT_EQ(errorOf("scene = a.xml\nvary Xy = list 1\n").rfind("sweep.txt:2: 'Xy' is not a scene value name", 0), 0u);
  EXPECT_EQ(errorOf("scene = a.xml\nset X.y = 1\nvary X.y = list 2\n").rfind("sweep.txt:3: X.y is named twice", 0), 0u);
  EXPECT_EQ(errorOf("scene = a.xml\nvary X.y = list 1 1\n").rfind("sweep.txt:2: 'list' names the value 1 twice", 0), 0u);
  EXPECT_EQ(errorOf("scene = a.xml\nframes = 2\ntime = 1\n").rfind("sweep.txt: give frames or time, not both", 0), 0u);
  EXPECT_EQ(errorOf("frames = 2\n").rfind("sweep.txt: no 'scene = FILE' line", 0), 0u);
  EXPECT_EQ(errorOf("scene = a.xml\ndevice = gpu\n").rfind("sweep.txt:2: device must be auto, cpu or cuda", 0), 0u);
  EXPECT_EQ(errorOf("scene = a.xml\nvary X.y = linear 0 1 400\nvary X.z = linear 0 1 400\n")
                .rfind("sweep.txt:3: the sweep expands to more than 100000 points", 0),
            0u);
}

TEST(SweepPlan, PointIdsDependOnlyOnTheValuesAndTheRepeat) {
  const std::vector<SweepPoint> a = sweepPoints(twoByTwo());
  ASSERT_EQ(a.size(), 4u);
  EXPECT_EQ(a[0].values, (std::vector<std::string>{"1", "0.2"}));
  EXPECT_EQ(a[1].values, (std::vector<std::string>{"1", "0.4"}));
  EXPECT_EQ(a[3].values, (std::vector<std::string>{"2", "0.4"}));
  for (std::size_t i = 0; i < a.size(); ++i)
    for (std::size_t j = i + 1; j < a.size(); ++j) EXPECT_NE(a[i].id, a[j].id);
  EXPECT_EQ(a[0].id.size(), 13u);
  EXPECT_EQ(a[0].id[0], 'p');

  // The same values in another order of lines, with one more value and
  // repeats: the points both have keep their ids.
  const SweepDescription b = parseSweepDescription("scene = " + kScene +
                                                       "\nrepeats = 2\nvary WetCloth.initialSaturation = list 0.2 "
                                                       "0.4\nvary Nozzle.speed = list 1 2 3\n",
                                                   "other.txt");
  const std::vector<SweepPoint> pb = sweepPoints(b);
  ASSERT_EQ(pb.size(), 12u);
  EXPECT_EQ(pb[0].id, a[0].id);  // saturation 0.2, speed 1, repeat 0
  EXPECT_EQ(pb[0].repeat, 0);
  EXPECT_NE(pb[1].id, pb[0].id);  // repeat 1 of the same values
  EXPECT_EQ(pb[1].repeat, 1);
  EXPECT_EQ(pb[1].values, pb[0].values);
  EXPECT_EQ(sweepPointId({"Nozzle.speed", "WetCloth.initialSaturation"}, {"2", "0.4"}, 0), a[3].id);
}

TEST(SweepPlan, PlanWritesEachPointsSceneAndPlanningAgainKeepsThem) {
  const std::string dir = freshTempPath("sweep_plan");
  const PlanSummary s = planSweep(twoByTwo(), dir);
  EXPECT_EQ(s.points, 4);
  EXPECT_EQ(s.added, 4);
  EXPECT_EQ(s.invalid, 0);
  const SweepState st = loadSweep(dir);
  ASSERT_EQ(st.points.size(), 4u);
  const std::string scene = readWholeFile(st.layout.pointScene(st.points[3].id));
  EXPECT_NE(scene.find("speed=\"2\""), std::string::npos) << scene;
  EXPECT_NE(scene.find("initialSaturation=\"0.4\""), std::string::npos) << scene;
  const std::string manifest = readWholeFile(dir + "/manifest.csv");
  EXPECT_EQ(manifest.substr(0, manifest.find('\n')),
            "point,repeat,Nozzle.speed,WetCloth.initialSaturation,status,exit_code,wall_s,attempts,error");
  EXPECT_NE(manifest.find(st.points[3].id + ",0,2,0.4,planned,"), std::string::npos) << manifest;

  // A file of the user's in a point folder stays; one more value adds one
  // column of points and keeps the others.
  writeWholeFile(st.layout.pointDir(st.points[0].id) + "/notes.txt", "mine");
  SweepDescription more = twoByTwo();
  more.parameters[0].values.push_back("3");
  const PlanSummary again = planSweep(more, dir);
  EXPECT_EQ(again.points, 6);
  EXPECT_EQ(again.added, 2);
  EXPECT_EQ(readWholeFile(st.layout.pointDir(st.points[0].id) + "/notes.txt"), "mine");
  EXPECT_EQ(loadSweep(dir).points[0].id, st.points[0].id);
}

TEST(SweepPlan, AValueTheSceneRefusesMakesThatPointInvalidAlone) {
  const std::string dir = freshTempPath("sweep_plan_invalid");
  const SweepDescription d =
      parseSweepDescription("scene = " + kScene + "\nvary WetCloth.initialSaturation = list 0.2 -3\n", "sweep.txt");
  const PlanSummary s = planSweep(d, dir);
  EXPECT_EQ(s.invalid, 1);
  const SweepState st = loadSweep(dir);
  EXPECT_EQ(st.records[0].status, "planned");
  EXPECT_EQ(st.records[1].status, "invalid");
  EXPECT_NE(st.records[1].error.find("--set 'WetCloth.initialSaturation=-3'"), std::string::npos) << st.records[1].error;
  EXPECT_NE(readWholeFile(dir + "/manifest.csv").find(",invalid,2,"), std::string::npos);

  // Every point refused (here: a name the scene does not have): nothing is written.
  const std::string none = freshTempPath("sweep_plan_none");
  const SweepDescription wrong =
      parseSweepDescription("scene = " + kScene + "\nvary WetCloth.saturaton = list 0.2 0.3\n", "wrong.txt");
  try {
    planSweep(wrong, none);
    FAIL() << "a sweep the scene refuses everywhere was planned";
  } catch (const InputError& e) {
    EXPECT_EQ(std::string(e.what()).rfind("wrong.txt: the scene refuses every point", 0), 0u) << e.what();
    EXPECT_NE(std::string(e.what()).find("initialSaturation"), std::string::npos) << "no suggestion: " << e.what();
  }
  EXPECT_FALSE(pathExists(none));
}

TEST(SweepPlan, FiguresComeFromStatsColumns) {
  StatsTable t;
  t.columns = {"frame", "held_water_mass", "strain_p99_a", "strain_p99_b"};
  t.rows = {{0, 1.0, 0.01, 0.03}, {1, 3.0, 0.02, 0.01}, {2, 2.0, 0.005, 0.004}};
  EXPECT_DOUBLE_EQ(sweepFigure("held", t, 0), 2.0);
  EXPECT_DOUBLE_EQ(sweepFigure("max:held_water_mass", t, 0), 3.0);
  EXPECT_DOUBLE_EQ(sweepFigure("mean:held_water_mass", t, 0), 2.0);
  EXPECT_DOUBLE_EQ(sweepFigure("min:held_water_mass", t, 0), 1.0);
  EXPECT_DOUBLE_EQ(sweepFigure("worst_strain", t, 0), 0.03);
  EXPECT_DOUBLE_EQ(sweepFigure("wall_s", t, 12.5), 12.5);
  EXPECT_TRUE(std::isnan(sweepFigure("drips", t, 0)));  // no such column in this run
  EXPECT_THROW(sweepFigure("hold", t, 0), InputError);
}
