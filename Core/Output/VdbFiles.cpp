#include "Output/VdbFiles.h"

#include <cerrno>

#include "Output/StorageFailure.h"

#include <openvdb/openvdb.h>
#include <openvdb/points/PointConversion.h>
#include <openvdb/tools/LevelSetRebuild.h>

#include <cstdio>
#include <mutex>
#include <stdexcept>

namespace soak {

namespace {

void initializeOpenVdb() {
  static std::once_flag once;
  std::call_once(once, [] { openvdb::initialize(); });
}

// The splat as a scalar grid phi = iso - density (negative inside, the
// level-set convention), then rebuilt by OpenVDB into a narrow band of
// signed distances around its zero crossing. Grid points the splat never
// touched hold the background (density 0: phi = iso) and stay inactive.
openvdb::FloatGrid::Ptr surfaceLevelSet(const RelativeDensityGrid& splat, const WaterSurfaceSettings& s) {
  if (splat.values.empty()) {
    openvdb::FloatGrid::Ptr empty = openvdb::createLevelSet<openvdb::FloatGrid>(s.cellSize, kVdbHalfWidthVoxels);
    return empty;
  }
  openvdb::FloatGrid::Ptr phi = openvdb::FloatGrid::create(s.iso);
  openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(splat.cell);
  xform->postTranslate(openvdb::Vec3d(splat.lo.x, splat.lo.y, splat.lo.z));
  phi->setTransform(xform);
  openvdb::FloatGrid::Accessor acc = phi->getAccessor();
  for (int k = 0; k < splat.nz; ++k)
    for (int j = 0; j < splat.ny; ++j)
      for (int i = 0; i < splat.nx; ++i) {
        const float density = splat.values[(std::size_t(k) * splat.ny + j) * splat.nx + i];
        if (density > 0.f) acc.setValue(openvdb::Coord(i, j, k), s.iso - density);
      }
  openvdb::FloatGrid::Ptr sdf = openvdb::tools::levelSetRebuild(*phi, 0.f, kVdbHalfWidthVoxels);
  sdf->setGridClass(openvdb::GRID_LEVEL_SET);
  return sdf;
}

// The particles: a points grid with about eight points a voxel at rest
// (voxel edge 2 r0).
openvdb::points::PointDataGrid::Ptr particleGrid(const WaterVdbFrame& f) {
  using namespace openvdb::points;
  const double voxel = 2.0 * double(f.spacing);
  openvdb::math::Transform::Ptr xform = openvdb::math::Transform::createLinearTransform(voxel);
  std::vector<openvdb::Vec3R> p(f.position.size());
  for (std::size_t i = 0; i < p.size(); ++i) p[i] = openvdb::Vec3R(f.position[i].x, f.position[i].y, f.position[i].z);
  const PointAttributeVector<openvdb::Vec3R> positions(p);
  openvdb::tools::PointIndexGrid::Ptr index =
      openvdb::tools::createPointIndexGrid<openvdb::tools::PointIndexGrid>(positions, *xform);
  PointDataGrid::Ptr grid = createPointDataGrid<NullCodec, PointDataGrid>(*index, positions, *xform);
  std::vector<openvdb::Vec3f> v(f.velocity.size());
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = openvdb::Vec3f(f.velocity[i].x, f.velocity[i].y, f.velocity[i].z);
  const std::vector<openvdb::Int32> id(f.id.begin(), f.id.end());
  appendAttribute<openvdb::Vec3f>(grid->tree(), "v");
  populateAttribute(grid->tree(), index->tree(), "v", PointAttributeVector<openvdb::Vec3f>(v));
  appendAttribute<float>(grid->tree(), "pscale");
  populateAttribute(grid->tree(), index->tree(), "pscale", PointAttributeVector<float>(f.pointRadius));
  appendAttribute<openvdb::Int32>(grid->tree(), "id");
  populateAttribute(grid->tree(), index->tree(), "id", PointAttributeVector<openvdb::Int32>(id));
  return grid;
}

}  // namespace

void writeWaterVdb(const std::string& path, const WaterVdbFrame& frame, const RelativeDensityGrid& splat,
                   const WaterSurfaceSettings& s) {
  initializeOpenVdb();
  openvdb::GridPtrVec grids;
  openvdb::FloatGrid::Ptr surface = surfaceLevelSet(splat, s);
  surface->setName("surface");
  grids.push_back(surface);
  openvdb::points::PointDataGrid::Ptr particles = particleGrid(frame);
  particles->setName("particles");
  grids.push_back(particles);
  const std::string tmp = path + ".tmp";
  try {
    openvdb::io::File file(tmp);
    file.write(grids);
    file.close();
  } catch (const openvdb::Exception&) {
    throw storageFailure(path, 0, tmp);  // OpenVDB's text names no reason: the folder says it
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw storageFailure(path, errno, tmp);
}

}  // namespace soak
