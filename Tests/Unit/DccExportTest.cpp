// Export for Houdini and Blender (issue 26): the .vdb and .ply files read
// back through libraries (OpenVDB; VTK's PLY library and its reader), with
// the counts and values the simulation had.
#include <gtest/gtest.h>

#include <openvdb/openvdb.h>
#include <openvdb/points/PointCount.h>
#include <openvdb/points/PointDataGrid.h>
#include <openvdb/tools/Interpolation.h>
#include <vtkFloatArray.h>
#include <vtkPLY.h>
#include <vtkPLYReader.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkUnsignedCharArray.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataReader.h>
#include <vtkXMLUnstructuredGridReader.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <map>

#include "Output/PlyFiles.h"
#include "Output/VdbFiles.h"
#include "Output/WaterSurface.h"
#include "SoakProcess.h"

using namespace soak;

namespace {

struct VdbPoint {
  Vec3 position, velocity;
  float pscale = 0.f;
};

struct VdbContents {
  openvdb::FloatGrid::Ptr surface;
  std::map<int, VdbPoint> points;  // by id
  openvdb::Index64 pointCount = 0;
};

VdbContents readVdb(const std::string& path) {
  openvdb::initialize();
  VdbContents out;
  openvdb::io::File file(path);
  file.open();
  out.surface = openvdb::gridPtrCast<openvdb::FloatGrid>(file.readGrid("surface"));
  auto points = openvdb::gridPtrCast<openvdb::points::PointDataGrid>(file.readGrid("particles"));
  file.close();
  if (!out.surface || !points) return out;
  out.pointCount = openvdb::points::pointCount(points->tree());
  for (auto leaf = points->tree().cbeginLeaf(); leaf; ++leaf) {
    openvdb::points::AttributeHandle<openvdb::Vec3f> p(leaf->constAttributeArray("P"));
    openvdb::points::AttributeHandle<openvdb::Vec3f> v(leaf->constAttributeArray("v"));
    openvdb::points::AttributeHandle<float> pscale(leaf->constAttributeArray("pscale"));
    openvdb::points::AttributeHandle<openvdb::Int32> id(leaf->constAttributeArray("id"));
    for (auto index = leaf->beginIndexOn(); index; ++index) {
      const openvdb::Vec3d world =
          points->transform().indexToWorld(p.get(*index) + index.getCoord().asVec3d());
      const openvdb::Vec3f vel = v.get(*index);
      out.points[id.get(*index)] = {Vec3(float(world.x()), float(world.y()), float(world.z())),
                                    Vec3(vel.x(), vel.y(), vel.z()), pscale.get(*index)};
    }
  }
  return out;
}

float sampleWorld(const openvdb::FloatGrid& grid, const Vec3& x) {
  return openvdb::tools::BoxSampler::sample(grid.tree(), grid.transform().worldToIndex(openvdb::Vec3d(x.x, x.y, x.z)));
}

// A PLY file's vertex properties by name, and its faces, through vtkPLY.
struct PlyContents {
  std::map<std::string, std::vector<float>> vertex;
  std::vector<std::vector<int>> faces;
};

PlyContents readPly(const std::string& path, const std::vector<std::string>& names) {
  PlyContents out;
  int elementCount = 0;
  char** elementNames = nullptr;
  PlyFile* ply = vtkPLY::ply_open_for_reading(path.c_str(), &elementCount, &elementNames);
  if (!ply) return out;
  for (int e = 0; e < elementCount; ++e) {
    int count = 0, props = 0;
    vtkPLY::ply_get_element_description(ply, elementNames[e], &count, &props);
    if (std::string(elementNames[e]) == "vertex") {
      std::vector<PlyProperty> wanted;
      for (std::size_t k = 0; k < names.size(); ++k)
        wanted.push_back({names[k].c_str(), PLY_FLOAT, PLY_FLOAT, int(k * sizeof(float)), 0, 0, 0, 0});
      for (PlyProperty& p : wanted) vtkPLY::ply_get_property(ply, "vertex", &p);
      std::vector<float> record(names.size());
      for (int i = 0; i < count; ++i) {
        vtkPLY::ply_get_element(ply, record.data());
        for (std::size_t k = 0; k < names.size(); ++k) out.vertex[names[k]].push_back(record[k]);
      }
    } else if (std::string(elementNames[e]) == "face") {
      struct Face {
        unsigned char count;
        int* vertices;
      };
      PlyProperty list{"vertex_indices", PLY_INT,   PLY_INT,  int(offsetof(Face, vertices)),
                       1,                PLY_UCHAR, PLY_UCHAR, int(offsetof(Face, count))};
      vtkPLY::ply_get_property(ply, "face", &list);
      for (int i = 0; i < count; ++i) {
        Face f{};
        vtkPLY::ply_get_element(ply, &f);
        out.faces.emplace_back(f.vertices, f.vertices + f.count);
        std::free(f.vertices);  // the library mallocs each list for its caller
      }
    }
  }
  vtkPLY::ply_close(ply);
  for (int e = 0; e < elementCount; ++e) std::free(elementNames[e]);
  std::free(elementNames);
  return out;
}

// soak run Scenes/fig1_jet.xml on the CPU into `dir` with `options` added.
test::SoakResult runFig1(const std::string& dir, const std::string& options) {
  return test::runSoak("run " + std::string(SOAK_SOURCE_DIR) + "/Scenes/fig1_jet.xml -o " + dir +
                       " --device cpu --quiet " + options);
}

}  // namespace

TEST(DccExport, VdbPointsCarryEveryParticleAndTheLevelSetEnclosesTheWater) {
  // A 0.2 m cube of particles at the water spacing, moving at (1, 2, 3) * id.
  const float r0 = 0.02f, h = 0.04f, m = 0.0082f;
  WaterVdbFrame f;
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i) {
        const int id = int(f.position.size());
        f.position.emplace_back((i + 0.5f) * r0, (j + 0.5f) * r0, (k + 0.5f) * r0);
        f.velocity.emplace_back(0.001f * id, 0.002f * id, 0.003f * id);
        f.id.push_back(id + 7);
        f.pointRadius.push_back(0.01f + 1e-5f * id);
      }
  const std::vector<float> mass(f.position.size(), m), supportRadius(f.position.size(), h);
  WaterSurfaceSettings s;
  const std::string path = test::freshTempPath("vdb_block") + ".vdb";
  writeWaterVdb(path, f, splatRelativeDensity(f.position, mass, supportRadius, 1000.f, s), s);
  const VdbContents read = readVdb(path);
  ASSERT_TRUE(read.surface);
  EXPECT_EQ(read.surface->getGridClass(), openvdb::GRID_LEVEL_SET);
  EXPECT_NEAR(read.surface->voxelSize()[0], s.cellSize, 1e-6);
  ASSERT_EQ(read.pointCount, f.position.size());
  ASSERT_EQ(read.points.size(), f.position.size());
  for (std::size_t n = 0; n < f.position.size(); ++n) {
    const auto it = read.points.find(f.id[n]);
    ASSERT_NE(it, read.points.end()) << "id " << f.id[n];
    EXPECT_LT(length(it->second.position - f.position[n]), 1e-5f) << n;
    EXPECT_LT(length(it->second.velocity - f.velocity[n]), 1e-6f) << n;
    EXPECT_FLOAT_EQ(it->second.pscale, f.pointRadius[n]) << n;
  }
  // Negative inside, positive outside, and the zero crossing along x through
  // the middle where the VTK mesh of the same splat has its faces.
  const openvdb::FloatGrid& phi = *read.surface;
  EXPECT_LT(sampleWorld(phi, Vec3(0.1f, 0.1f, 0.1f)), 0.f);
  EXPECT_GT(sampleWorld(phi, Vec3(0.1f, 0.1f, 0.32f)), 0.f);
  float crossing = NAN;
  for (float x = 0.1f; x < 0.3f; x += 0.0005f)
    if (sampleWorld(phi, Vec3(x, 0.1f, 0.1f)) >= 0.f) {
      crossing = x;
      break;
    }
  double bounds[6];
  buildWaterSurface(f.position, mass, supportRadius, 1000.f, s)->GetBounds(bounds);
  std::printf("level set zero at x = %.4f m, mesh face at x = %.4f m (block face 0.2)\n", crossing, bounds[1]);
  EXPECT_NEAR(crossing, bounds[1], 0.5 * s.cellSize);
  // The level set is a distance: one cell further out, phi grows by about a cell.
  const float outside = sampleWorld(phi, Vec3(crossing + 2 * s.cellSize, 0.1f, 0.1f));
  EXPECT_NEAR(outside, 2 * s.cellSize, 0.5 * s.cellSize);
}

TEST(DccExport, VdbWithoutWaterHoldsEmptyGrids) {
  const std::string path = test::freshTempPath("vdb_empty") + ".vdb";
  writeWaterVdb(path, WaterVdbFrame{}, RelativeDensityGrid{}, WaterSurfaceSettings{});
  const VdbContents read = readVdb(path);
  ASSERT_TRUE(read.surface);
  EXPECT_EQ(read.surface->activeVoxelCount(), 0u);
  EXPECT_EQ(read.pointCount, 0u);
}

TEST(DccExport, PlyCarriesPositionsVelocitiesChannelsColoursAndFaces) {
  ClothPlyFrame f;
  f.position = {Vec3(0, 0, 0), Vec3(1, 0, 0), Vec3(0, 1, 0), Vec3(1, 1, 0.5f)};
  f.velocity = {Vec3(0.1f, 0, 0), Vec3(0, 0.2f, 0), Vec3(0, 0, 0.3f), Vec3(-1, -2, -3)};
  f.triangles = {{0, 1, 2}, {1, 3, 2}};
  f.channels = {{"held_water", 1, {0.f, 1e-4f, 2e-4f, 3e-4f}}, {"saturation", 1, {0.f, 0.25f, 1.f, 2.f}}};
  f.colourChannel = 1;
  const std::string path = test::freshTempPath("cloth") + ".ply";
  writeClothPly(path, f);
  const PlyContents read = readPly(path, {"x", "y", "z", "vx", "vy", "vz", "held_water", "saturation"});
  ASSERT_EQ(read.vertex.at("x").size(), 4u);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(read.vertex.at("z")[i], f.position[i].z);
    EXPECT_EQ(read.vertex.at("vy")[i], f.velocity[i].y);
    EXPECT_EQ(read.vertex.at("held_water")[i], f.channels[0].values[i]);
    EXPECT_EQ(read.vertex.at("saturation")[i], f.channels[1].values[i]);
  }
  ASSERT_EQ(read.faces.size(), 2u);
  EXPECT_EQ(read.faces[1], (std::vector<int>{1, 3, 2}));
  // VTK's reader (what ParaView opens a PLY with) sees the mesh and colours:
  // white where dry, deep blue where saturated (clamped above 1).
  vtkNew<vtkPLYReader> reader;
  reader->SetFileName(path.c_str());
  reader->Update();
  vtkPolyData* poly = reader->GetOutput();
  EXPECT_EQ(poly->GetNumberOfPoints(), 4);
  EXPECT_EQ(poly->GetNumberOfPolys(), 2);
  auto* rgb = vtkUnsignedCharArray::SafeDownCast(poly->GetPointData()->GetScalars());
  ASSERT_NE(rgb, nullptr);
  EXPECT_EQ(rgb->GetTypedComponent(0, 0), 255);
  EXPECT_EQ(rgb->GetTypedComponent(2, 2), wetnessColour(1.f)[2]);
  EXPECT_EQ(rgb->GetTypedComponent(3, 0), wetnessColour(1.f)[0]);
  EXPECT_LT(wetnessColour(1.f)[0], wetnessColour(0.25f)[0]);
}

TEST(DccExport, Fig1SequencesMatchTheVtkFrames) {
  // Scenes/fig1_jet.xml for 3 frames with both exports on: every .vdb holds
  // the frame's water particles (ids, positions, velocities of the .vtu) and
  // every .ply the cloth vertices with the .vtp's saturation.
  const std::string dir = test::freshTempPath("fig1_export");
  const test::SoakResult r = runFig1(dir, "--frames 3 --set Output.vdb=true --set Output.ply=true");
  ASSERT_EQ(r.code, 0) << r.output;
  int framesWithWater = 0;
  for (int frame = 0; frame <= 3; ++frame) {
    char name[64];
    std::snprintf(name, sizeof(name), "%06d", frame);
    vtkNew<vtkXMLUnstructuredGridReader> vtu;
    vtu->SetFileName((dir + "/water/water_" + name + ".vtu").c_str());
    vtu->Update();
    vtkUnstructuredGrid* water = vtu->GetOutput();
    const VdbContents vdb = readVdb(dir + "/water_vdb/water_" + name + ".vdb");
    ASSERT_TRUE(vdb.surface) << frame;
    ASSERT_EQ(vdb.pointCount, openvdb::Index64(water->GetNumberOfPoints())) << frame;
    auto* ids = vtkFloatArray::SafeDownCast(water->GetPointData()->GetArray("id"));
    auto* vel = vtkFloatArray::SafeDownCast(water->GetPointData()->GetArray("velocity"));
    for (vtkIdType i = 0; i < water->GetNumberOfPoints(); ++i) {
      const auto it = vdb.points.find(int(ids->GetValue(i)));
      ASSERT_NE(it, vdb.points.end()) << frame << " id " << ids->GetValue(i);
      double p[3];
      water->GetPoint(i, p);
      EXPECT_LT(length(it->second.position - Vec3(float(p[0]), float(p[1]), float(p[2]))), 1e-5f);
      EXPECT_NEAR(it->second.velocity.y, vel->GetComponent(i, 1), 1e-6);
    }
    if (water->GetNumberOfPoints() > 0) {
      ++framesWithWater;
      EXPECT_GT(vdb.surface->activeVoxelCount(), 0u) << frame;
    }

    vtkNew<vtkXMLPolyDataReader> vtp;
    vtp->SetFileName((dir + "/cloth_sheet/cloth_sheet_" + name + ".vtp").c_str());
    vtp->Update();
    vtkPolyData* cloth = vtp->GetOutput();
    const PlyContents ply = readPly(dir + "/cloth_sheet_ply/cloth_sheet_" + name + ".ply", {"y", "saturation"});
    ASSERT_EQ(ply.vertex.at("y").size(), std::size_t(cloth->GetNumberOfPoints())) << frame;
    EXPECT_EQ(ply.faces.size(), std::size_t(cloth->GetNumberOfPolys())) << frame;
    auto* saturation = vtkFloatArray::SafeDownCast(cloth->GetPointData()->GetArray("saturation"));
    ASSERT_NE(saturation, nullptr);
    for (vtkIdType i = 0; i < cloth->GetNumberOfPoints(); ++i) {
      EXPECT_EQ(ply.vertex.at("y")[std::size_t(i)], float(cloth->GetPoint(i)[1]));
      EXPECT_EQ(ply.vertex.at("saturation")[std::size_t(i)], saturation->GetValue(i));
    }
  }
  EXPECT_GE(framesWithWater, 3);
}

TEST(DccExport, UnknownColourChannelIsRefusedWithTheChannelsThereAre) {
  const std::string dir = test::freshTempPath("ply_colour");
  const test::SoakResult r = runFig1(dir, "--frames 1 --set Output.ply=true --set Output.plyColour=wetness");
  EXPECT_EQ(r.code, 2) << r.output;
  EXPECT_NE(r.output.find("plyColour 'wetness'"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("saturation"), std::string::npos) << r.output;
  EXPECT_FALSE(test::pathExists(dir + "/cloth_sheet_ply")) << "frames written for a refused scene";
}
