// Hostile but realistic input through the soak program: a refused resume
// leaves the run as it was, names cannot become paths, the output folder
// cannot replace the input, option values are range-checked, and files that
// are not files are not read. (The rest of the hostile classes are cases of
// the bad-input corpus, Tests/BadInput/cases.txt.)
#include <gtest/gtest.h>

#include <regex>
#include <string>
#include <vector>

#include "SoakProcess.h"

using namespace soak::test;

namespace {

// A 4 x 4-vertex square of cloth as an OBJ mesh, its vertices scaled by `s`.
std::string squareObj(float s) {
  std::string obj;
  for (int j = 0; j < 4; ++j)
    for (int i = 0; i < 4; ++i)
      obj += "v " + std::to_string(s * 0.1f * float(i)) + " 1 " + std::to_string(s * 0.1f * float(j)) + "\n";
  for (int j = 0; j < 3; ++j)
    for (int i = 0; i < 3; ++i) {
      const int a = 1 + j * 4 + i, b = a + 1, c = a + 4, d = a + 5;
      obj += "f " + std::to_string(a) + " " + std::to_string(b) + " " + std::to_string(d) + "\n";
      obj += "f " + std::to_string(a) + " " + std::to_string(d) + " " + std::to_string(c) + "\n";
    }
  return obj;
}

const char* kMeshScene = R"(<Scene>
  <Simulation timeStep="0.015" frameRate="30"/>
  <Water/>
  <Cloth name="square" mesh="square.obj" pin="0 3"/>
  <WaterBlock min="0.05 1.1 0.05" max="0.15 1.2 0.15"/>
  <Plane/>
</Scene>
)";

int countLines(const std::string& text) {
  int n = 0;
  for (char c : text) n += c == '\n';
  return n;
}
int countEntries(const std::string& pvd) {
  const std::regex entry("<DataSet ");
  return int(std::distance(std::sregex_iterator(pvd.begin(), pvd.end(), entry), std::sregex_iterator()));
}

// A folder with the mesh scene and its OBJ.
std::string meshSceneFolder(const std::string& name) {
  const std::string dir = freshTempPath(name);
  std::system(("mkdir -p '" + dir + "'").c_str());
  writeWholeFile(dir + "/scene.xml", kMeshScene);
  writeWholeFile(dir + "/square.obj", squareObj(1.f));
  return dir;
}

}  // namespace

// A run with frames 0-4 on disk and its checkpoint at frame 2 (as a run
// killed after frame 4 leaves it). A resume refused for any reason must
// leave stats.csv and every .pvd exactly as they were.
TEST(HostileInput, ARefusedResumeLeavesTheRunItRefusesAsItWas) {
  const std::string in = meshSceneFolder("hostile_resume_in");
  const std::string run = in + "/out";
  ASSERT_EQ(runSoak("run " + in + "/scene.xml -o " + run + " --frames 2 --checkpoint-every 2 --device cpu --quiet")
                .code, 0);
  const std::string atFrame2 = readWholeFile(run + "/checkpoint.soak");
  ASSERT_EQ(runSoak("run --resume " + run + " --frames 4 --device cpu --quiet").code, 0);
  writeWholeFile(run + "/checkpoint.soak", atFrame2);
  const std::string stats = readWholeFile(run + "/stats.csv");
  const std::string water = readWholeFile(run + "/water.pvd"), cloth = readWholeFile(run + "/cloth_square.pvd");
  ASSERT_EQ(countLines(stats), 6);  // header + frames 0-4
  ASSERT_EQ(countEntries(water), 5);
  auto expectUntouched = [&](const std::string& why) {
    EXPECT_EQ(readWholeFile(run + "/water.pvd"), water) << why;
    EXPECT_EQ(readWholeFile(run + "/cloth_square.pvd"), cloth) << why;
  };

  // The mesh changed since the run started: its vertex count differs.
  writeWholeFile(in + "/square.obj", squareObj(1.f) + "v 9 9 9\n");
  SoakResult r = runSoak("run --resume " + run + " --frames 4 --device cpu --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_EQ(readWholeFile(run + "/stats.csv"), stats) << "a refused resume cut stats.csv";
  expectUntouched("mesh changed");
  writeWholeFile(in + "/square.obj", squareObj(1.f));

  // stats.csv is missing.
  std::rename((run + "/stats.csv").c_str(), (run + "/stats.moved").c_str());
  r = runSoak("run --resume " + run + " --frames 4 --device cpu --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("stats.csv"), std::string::npos) << r.output;
  expectUntouched("stats.csv missing");
  std::rename((run + "/stats.moved").c_str(), (run + "/stats.csv").c_str());

  // A frame file the checkpoint lists is gone.
  std::rename((run + "/water/water_000001.vtu").c_str(), (run + "/water_000001.moved").c_str());
  r = runSoak("run --resume " + run + " --frames 4 --device cpu --quiet");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("water_000001.vtu"), std::string::npos) << r.output;
  EXPECT_EQ(readWholeFile(run + "/stats.csv"), stats);
  expectUntouched("frame file missing");
  std::rename((run + "/water_000001.moved").c_str(), (run + "/water/water_000001.vtu").c_str());

  // With everything back, the same resume goes through and rewrites frames 3-4.
  r = runSoak("run --resume " + run + " --frames 4 --device cpu --quiet");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_EQ(countLines(readWholeFile(run + "/stats.csv")), 6);
}

TEST(HostileInput, ANameThatIsAPathIsRefusedBeforeAnythingIsWritten) {
  const std::string in = meshSceneFolder("hostile_names");
  const std::string out = in + "/out";
  for (const std::string& name : std::vector<std::string>{"x/../../OUT", "a/b", "..", ".hidden", "a b", std::string(65, 'n')}) {
    std::string scene = kMeshScene;
    scene.replace(scene.find("name=\"square\""), 13, "name=\"" + name + "\"");
    writeWholeFile(in + "/named.xml", scene);
    SoakResult r = runSoak("run " + in + "/named.xml -o " + out + " --frames 1 --device cpu --quiet");
    EXPECT_EQ(r.code, 2) << name << ": " << r.output;
    EXPECT_NE(r.output.find("named.xml:4"), std::string::npos) << name << ": no file and line: " << r.output;
    EXPECT_NE(r.output.find("not a usable name"), std::string::npos) << r.output;
    EXPECT_FALSE(pathExists(out)) << name << ": output written before the name was refused";
  }
  EXPECT_FALSE(pathExists(freshTempPath("OUT"))) << "a folder outside the output folder was made";
  SoakResult r = runSoak("run " + in + "/scene.xml -o " + out + " --set Cloth.name=a/b --frames 1 --device cpu");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_FALSE(pathExists(out));
  // Names that are fine stay fine.
  r = runSoak("run " + in + "/scene.xml -o " + out + " --set Cloth.name=Sheet-2.b_c --frames 1 --device cpu --quiet");
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(pathExists(out + "/cloth_Sheet-2.b_c.pvd"));
}

TEST(HostileInput, TheOutputFolderMayNotHoldOrReplaceTheInput) {
  const std::string in = meshSceneFolder("hostile_output");
  const std::string scene = readWholeFile(in + "/scene.xml");
  // -o the scene's own folder, by several spellings.
  for (const std::string& out : std::vector<std::string>{in, in + "/", in + "/.", in + "/out/.."}) {
    SoakResult r = runSoak("run " + in + "/scene.xml -o " + out + " --frames 1 --device cpu --quiet");
    EXPECT_EQ(r.code, 2) << out << ": " << r.output;
    EXPECT_NE(r.output.find("holds the input scene"), std::string::npos) << r.output;
    EXPECT_EQ(readWholeFile(in + "/scene.xml"), scene) << "the user's scene was replaced";
    EXPECT_FALSE(pathExists(in + "/water.pvd"));
  }
  // A mesh where the run would write its frames: the VTK, PLY or VDB folders.
  // cloth_other: another run's cloth folder, which --overwrite would remove.
  for (const std::string folder : {"cloth_square", "cloth_square_ply", "water_vdb", "cloth_other"}) {
    std::system(("mkdir -p '" + in + "/run/" + folder + "'").c_str());
    writeWholeFile(in + "/run/" + folder + "/square.obj", squareObj(1.f));
    std::string meshInRun = scene;
    meshInRun.replace(meshInRun.find("mesh=\"square.obj\""), 17, "mesh=\"run/" + folder + "/square.obj\"");
    writeWholeFile(in + "/mesh_in_run.xml", meshInRun);
    SoakResult r = runSoak("run " + in + "/mesh_in_run.xml -o " + in + "/run --frames 1 --device cpu --quiet");
    EXPECT_EQ(r.code, 2) << folder << ": " << r.output;
    EXPECT_NE(r.output.find("would replace"), std::string::npos) << r.output;
    EXPECT_FALSE(pathExists(in + "/run/water.pvd"));
    r = runSoak("run " + in + "/mesh_in_run.xml -o " + in + "/run --frames 1 --device cpu --quiet --overwrite");
    EXPECT_EQ(r.code, 2) << folder << ": " << r.output;
    EXPECT_TRUE(pathExists(in + "/run/" + folder + "/square.obj")) << "--overwrite removed an input";
  }
  // A subfolder of the scene's folder is fine.
  SoakResult r = runSoak("run " + in + "/scene.xml -o " + in + "/out --frames 1 --device cpu --quiet");
  EXPECT_EQ(r.code, 0) << r.output;
}

TEST(HostileInput, OptionValuesAreRangeChecked) {
  const std::string in = meshSceneFolder("hostile_options");
  const std::string out = in + "/out";
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--threads 100000", "--threads must be an integer in [1, 1024]"},
      {"--threads 0", "--threads must be an integer"},
      {"-o ''", "needs a folder name"},
      {"--time inf", "not a finite number"},
      {"--time nan", "not a finite number"},
      {"--time 1e10", "at most 10000000 frames"},
      {"--frames 1e12", "--frames must be an integer in [0, 10000000]"},
      {"--frames 2.5", "--frames must be an integer"},
      {"--checkpoint-every 0", "--checkpoint-every must be an integer"},
  };
  for (const auto& c : cases) {
    SoakResult r = runSoak("run " + in + "/scene.xml -o " + out + " " + c.first + " --device cpu --quiet");
    EXPECT_EQ(r.code, 2) << c.first << ": " << r.output;
    EXPECT_NE(r.output.find(c.second), std::string::npos) << c.first << ": " << r.output;
    EXPECT_FALSE(pathExists(out)) << c.first << ": output written";
  }
  EXPECT_EQ(runSoak("run --resume '' --device cpu").code, 2);
}

// A checkpoint that is a folder, or a link to an endless device, is refused
// as bad input (exit 2, naming it) before a byte is read, and the run it
// belongs to is left as it was.
TEST(HostileInput, ACheckpointThatIsNotAFileIsRefused) {
  const std::string in = meshSceneFolder("hostile_checkpoint_kind");
  const std::string run = in + "/out";
  ASSERT_EQ(runSoak("run " + in + "/scene.xml -o " + run + " --frames 1 --device cpu --quiet").code, 0);
  const std::string stats = readWholeFile(run + "/stats.csv");
  std::system(("mkdir -p '" + run + "/checkpoint.soak'").c_str());
  SoakResult r = runSoakLimited("run --resume " + run + " --frames 2 --device cpu --quiet", 60, 4096);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("checkpoint.soak: checkpoint is a folder"), std::string::npos) << r.output;
  std::system(("rmdir '" + run + "/checkpoint.soak' && ln -s /dev/zero '" + run + "/checkpoint.soak'").c_str());
  r = runSoakLimited("run --resume " + run + " --frames 2 --device cpu --quiet", 60, 4096);
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("checkpoint is not a regular file"), std::string::npos) << r.output;
  EXPECT_EQ(readWholeFile(run + "/stats.csv"), stats);
}

// An OBJ's mtllib naming an endless device is not followed: materials are
// not read, so the mesh loads from its own text.
TEST(HostileInput, AnObjMaterialLibraryIsNotRead) {
  const std::string in = meshSceneFolder("hostile_mtllib");
  writeWholeFile(in + "/square.obj", "mtllib /dev/zero\nusemtl x\n" + squareObj(1.f));
  const SoakResult r =
      runSoakLimited("run " + in + "/scene.xml -o " + in + "/out --frames 1 --device cpu --quiet", 60, 4096);
  EXPECT_EQ(r.code, 0) << r.output;
  EXPECT_TRUE(pathExists(in + "/out/cloth_square.pvd"));
}
