// The water surface mesh (issue 5): a block of particles gives a closed
// surface around the block's volume.
#include <gtest/gtest.h>

#include <vtkMassProperties.h>
#include <vtkPolyData.h>
#include <vtkTriangleFilter.h>

#include "Output/WaterSurface.h"

using namespace soak;

TEST(WaterSurface, BlockOfParticlesEnclosesItsVolume) {
  // 10 x 10 x 10 particles at the water spacing: a 0.2 m cube of water
  // (each particle stands for r0^3). The surface at half the rest density
  // lies near the block's faces: its volume is within 15 % of 0.2^3 m^3 and
  // its bounds within one spacing of the block's.
  const float r0 = 0.02f, h = 0.04f, m = 0.0082f;
  std::vector<Vec3> x;
  for (int k = 0; k < 10; ++k)
    for (int j = 0; j < 10; ++j)
      for (int i = 0; i < 10; ++i) x.emplace_back((i + 0.5f) * r0, (j + 0.5f) * r0, (k + 0.5f) * r0);
  std::vector<float> mass(x.size(), m), radius(x.size(), h);
  WaterSurfaceSettings s;
  vtkSmartPointer<vtkPolyData> surface = buildWaterSurface(x, mass, radius, 1000.f, s);
  ASSERT_GT(surface->GetNumberOfPolys(), 100);
  vtkNew<vtkTriangleFilter> tri;
  tri->SetInputData(surface);
  vtkNew<vtkMassProperties> props;
  props->SetInputConnection(tri->GetOutputPort());
  props->Update();
  double b[6];
  surface->GetBounds(b);
  std::printf("surface: %lld triangles, volume %.5f m^3 (block 0.00800), area %.4f m^2 (block 0.24), x in [%.4f, %.4f]\n",
              (long long)surface->GetNumberOfPolys(), props->GetVolume(), props->GetSurfaceArea(), b[0], b[1]);
  EXPECT_NEAR(props->GetVolume(), 0.008, 0.15 * 0.008);
  for (int a = 0; a < 3; ++a) {
    EXPECT_NEAR(b[2 * a], 0.0, r0);
    EXPECT_NEAR(b[2 * a + 1], 0.2, r0);
  }
}

TEST(WaterSurface, NoWaterNoSurface) {
  WaterSurfaceSettings s;
  EXPECT_EQ(buildWaterSurface({}, {}, {}, 1000.f, s)->GetNumberOfPoints(), 0);
}
