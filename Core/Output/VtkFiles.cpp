#include "Output/VtkFiles.h"

#include <fcntl.h>
#include <unistd.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkIdTypeArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkUnstructuredGrid.h>
#include <vtkXMLPolyDataWriter.h>
#include <vtkXMLUnstructuredGridWriter.h>

#include <vtkErrorCode.h>
#include <vtkObject.h>

#include <cerrno>
#include <cstdio>

#include "Base/Error.h"
#include "Output/StorageFailure.h"
#include "Output/VtkPolyData.h"

namespace soak {

namespace {
vtkNew<vtkPoints> makePoints(const std::vector<Vec3>& points) {
  vtkNew<vtkPoints> pts;
  pts->SetDataTypeToFloat();
  pts->SetNumberOfPoints(static_cast<vtkIdType>(points.size()));
  for (std::size_t i = 0; i < points.size(); ++i)
    pts->SetPoint(static_cast<vtkIdType>(i), points[i].x, points[i].y, points[i].z);
  return pts;
}

void addPointData(vtkPointData* pd, const std::vector<PointArray>& data, std::size_t n) {
  for (const PointArray& a : data) {
    if (a.values.size() != n * static_cast<std::size_t>(a.components))
      throw std::logic_error("point array '" + a.name + "' has the wrong size");
    vtkNew<vtkFloatArray> arr;
    arr->SetName(a.name.c_str());
    arr->SetNumberOfComponents(a.components);
    arr->SetNumberOfTuples(static_cast<vtkIdType>(n));
    std::copy(a.values.begin(), a.values.end(), arr->GetPointer(0));
    pd->AddArray(arr);
  }
}

template <class Writer>
void configureAndWrite(Writer* w, const std::string& path, Compression compression) {
  std::string tmp = path + ".tmp";
  w->SetFileName(tmp.c_str());
  w->SetDataModeToAppended();
  w->EncodeAppendedDataOff();  // raw binary appended
  switch (compression) {
    case Compression::None: w->SetCompressorTypeToNone(); break;
    case Compression::LZ4: w->SetCompressorTypeToLZ4(); break;
    case Compression::ZLib: w->SetCompressorTypeToZLib(); break;
    case Compression::LZMA: w->SetCompressorTypeToLZMA(); break;
  }
  // VTK reports a failed write on its own output window, which would print
  // its text beside ours: the failure is reported as a StorageError instead.
  vtkObject::GlobalWarningDisplayOff();
  if (!w->Write())
    throw storageFailure(path, w->GetErrorCode() == vtkErrorCode::OutOfDiskSpaceError ? ENOSPC : 0, tmp);
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw storageFailure(path, errno, tmp);
}
// One vertex cell per point (the particles).
vtkSmartPointer<vtkCellArray> vertexCells(std::size_t count) {
  const vtkIdType n = static_cast<vtkIdType>(count);
  vtkNew<vtkIdTypeArray> offsets, conn;
  offsets->SetNumberOfValues(n + 1);
  conn->SetNumberOfValues(n);
  for (vtkIdType i = 0; i < n; ++i) {
    offsets->SetValue(i, i);
    conn->SetValue(i, i);
  }
  offsets->SetValue(n, n);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  cells->SetData(offsets, conn);
  return cells;
}
}  // namespace

void writeParticlesVtu(const std::string& path, const std::vector<Vec3>& points, const std::vector<PointArray>& data,
                       Compression compression) {
  vtkNew<vtkUnstructuredGrid> grid;
  grid->SetPoints(makePoints(points));
  grid->SetCells(VTK_VERTEX, vertexCells(points.size()));
  addPointData(grid->GetPointData(), data, points.size());
  vtkNew<vtkXMLUnstructuredGridWriter> w;
  w->SetInputData(grid);
  configureAndWrite(w.GetPointer(), path, compression);
}

vtkSmartPointer<vtkPolyData> meshPolyData(const std::vector<Vec3>& points,
                                          const std::vector<std::array<int, 3>>& triangles,
                                          const std::vector<PointArray>& data) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(makePoints(points));
  vtkNew<vtkCellArray> polys;
  polys->AllocateExact(vtkIdType(triangles.size()), 3 * vtkIdType(triangles.size()));
  for (const auto& t : triangles) {
    vtkIdType ids[3] = {t[0], t[1], t[2]};
    polys->InsertNextCell(3, ids);
  }
  poly->SetPolys(polys);
  addPointData(poly->GetPointData(), data, points.size());
  return poly;
}

vtkSmartPointer<vtkPolyData> particlesPolyData(const std::vector<Vec3>& points, const std::vector<PointArray>& data) {
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(makePoints(points));
  poly->SetVerts(vertexCells(points.size()));
  addPointData(poly->GetPointData(), data, points.size());
  return poly;
}

void writeMeshVtp(const std::string& path, const std::vector<Vec3>& points,
                  const std::vector<std::array<int, 3>>& triangles, const std::vector<PointArray>& data,
                  Compression compression) {
  vtkSmartPointer<vtkPolyData> poly = meshPolyData(points, triangles, data);
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(poly);
  configureAndWrite(w.GetPointer(), path, compression);
}

void writePolyDataVtp(const std::string& path, vtkPolyData* poly, Compression compression) {
  vtkNew<vtkXMLPolyDataWriter> w;
  w->SetInputData(poly);
  configureAndWrite(w.GetPointer(), path, compression);
}

void writeFileAtomically(const std::string& path, const std::string& content, bool durable) {
  std::string tmp = path + ".tmp";
  int fd = ::open(tmp.c_str(), O_WRONLY | O_CREAT | O_TRUNC | O_CLOEXEC, 0644);
  if (fd < 0) throw storageFailure(path, errno);
  const char* p = content.data();
  std::size_t left = content.size();
  while (left > 0) {
    ssize_t k = ::write(fd, p, left);
    if (k <= 0) {
      const int e = k < 0 ? errno : ENOSPC;
      ::close(fd);
      throw storageFailure(path, e, tmp);
    }
    p += k;
    left -= static_cast<std::size_t>(k);
  }
  if ((durable && ::fsync(fd) != 0) || ::close(fd) != 0) {
    const int e = errno;
    throw storageFailure(path, e, tmp);
  }
  if (std::rename(tmp.c_str(), path.c_str()) != 0) throw storageFailure(path, errno, tmp);
}

}  // namespace soak
