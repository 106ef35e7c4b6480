#include "render/BodyMeshes.h"

#include "dynamics/core/BodyShapes.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/FileNames.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <functional>
#include <string>
#include <vtkAlgorithm.h>
#include <vtkCellArray.h>
#include <vtkContourFilter.h>
#include <vtkDoubleArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkOBJReader.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>
#include <vtkSTLReader.h>
#include <vtkTransform.h>
#include <vtkTransformPolyDataFilter.h>
#include <vtkTriangleFilter.h>

namespace rv {

namespace {
// a (nu x nv) grid of points p(u, v), u the longitude in [0, 1] (seam duplicated), v in [0, 1]
template <class F>
vtkSmartPointer<vtkPolyData> grid(int nu, int nv, F point, double repeatU = 1, double repeatV = 1) {
  vtkNew<vtkPoints> pts;
  vtkNew<vtkFloatArray> tc;
  tc->SetNumberOfComponents(2);
  for (int j = 0; j <= nv; ++j)
    for (int i = 0; i <= nu; ++i) {
      const double u = double(i) / nu, v = double(j) / nv;
      const Eigen::Vector3d p = point(u, v);
      pts->InsertNextPoint(p[0], p[1], p[2]);
      tc->InsertNextTuple2(u * repeatU, v * repeatV);
    }
  vtkNew<vtkCellArray> tris;
  for (int j = 0; j < nv; ++j)
    for (int i = 0; i < nu; ++i) {
      const vtkIdType a = j * (nu + 1) + i, b = a + 1, c = a + nu + 1, d = c + 1;
      const vtkIdType t1[3] = {a, b, d}, t2[3] = {a, d, c};
      tris->InsertNextCell(3, t1);
      tris->InsertNextCell(3, t2);
    }
  vtkNew<vtkPolyData> raw;
  raw->SetPoints(pts);
  raw->SetPolys(tris);
  raw->GetPointData()->SetTCoords(tc);
  vtkNew<vtkPolyDataNormals> normals; // smooth shading; keep the seam's texture coordinates
  normals->SetInputData(raw);
  normals->SplittingOff();
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOff();
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  return out;
}
} // namespace

vtkSmartPointer<vtkPolyData> makeSurfaceMesh(const SupportSurface& surface) {
  return grid(
      128, 64, [&](double u, double v) { return surface.point(u, v); }, 8, 4);
}

vtkSmartPointer<vtkPolyData> readBodyMesh(const BodyMeshFile& file) {
  vtkSmartPointer<vtkAlgorithm> reader;
  const bool stlFile = hasExtension(file.path, ".stl");
  if (stlFile) {
    auto stl = vtkSmartPointer<vtkSTLReader>::New();
    stl->SetFileName(file.path.c_str());
    reader = stl;
  } else if (hasExtension(file.path, ".obj")) {
    auto obj = vtkSmartPointer<vtkOBJReader>::New();
    obj->SetFileName(file.path.c_str());
    reader = obj;
  } else {
    throw InputError(file.path + ": a mesh is an STL or OBJ file (.stl, .obj)");
  }
  if (!std::filesystem::is_regular_file(file.path)) throw InputError(file.path + ": no such mesh file");
  vtkNew<vtkTriangleFilter> triangles; // OBJ faces may be polygons
  triangles->SetInputConnection(reader->GetOutputPort());
  vtkNew<vtkTransform> scale;
  scale->Scale(file.scale, file.scale, file.scale);
  vtkNew<vtkTransformPolyDataFilter> scaled;
  scaled->SetTransform(scale);
  scaled->SetInputConnection(triangles->GetOutputPort());
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(scaled->GetOutputPort());
  normals->SetFeatureAngle(50); // sharp edges stay sharp
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  if (out->GetNumberOfPolys() == 0)
    throw InputError(file.path + ": the mesh holds no triangles (not a readable " +
                     (stlFile ? "STL" : "OBJ") + " file?)");
  return out;
}

vtkSmartPointer<vtkPolyData> sampleImplicitSurface(const ImplicitSurface& surface, const std::string& what) {
  constexpr int kSamples = 56; // per axis: smooth enough at a body's size on screen, ~0.2 s
  const double reach = 1.25 * surface.size, step = 2 * reach / (kSamples - 1);
  vtkNew<vtkImageData> grid;
  grid->SetDimensions(kSamples, kSamples, kSamples);
  grid->SetOrigin(-reach, -reach, -reach);
  grid->SetSpacing(step, step, step);
  vtkNew<vtkDoubleArray> values;
  values->SetNumberOfValues(static_cast<vtkIdType>(kSamples) * kSamples * kSamples);
  vtkIdType id = 0;
  for (int k = 0; k < kSamples; ++k) // x fastest, as vtkImageData orders its points
    for (int j = 0; j < kSamples; ++j)
      for (int i = 0; i < kSamples; ++i) {
        const double F = surface.F(Eigen::Vector3d(-reach + i * step, -reach + j * step, -reach + k * step));
        values->SetValue(id++, std::isfinite(F) ? F : 1.0);
      }
  grid->GetPointData()->SetScalars(values);
  vtkNew<vtkContourFilter> contour;
  contour->SetInputData(grid);
  contour->SetValue(0, 0.0);
  vtkNew<vtkPolyDataNormals> normals;
  normals->SetInputConnection(contour->GetOutputPort());
  normals->ConsistencyOn();
  normals->AutoOrientNormalsOn(); // outward, whatever the contour's orientation
  normals->Update();
  vtkSmartPointer<vtkPolyData> out = normals->GetOutput();
  if (out->GetNumberOfPolys() == 0)
    throw InputError(what + " F = 0 is not within " + std::to_string(reach) +
                     " of its centre: give its \"size\"");
  return out;
}

vtkSmartPointer<vtkPolyData> sampleImplicitSupport(const ImplicitSurface& surface) {
  vtkSmartPointer<vtkPolyData> mesh = sampleImplicitSurface(surface, "the support's surface");
  vtkNew<vtkFloatArray> uv;
  uv->SetNumberOfComponents(2);
  uv->SetNumberOfTuples(mesh->GetNumberOfPoints());
  const double period = 2.5 * surface.size / 8;
  for (vtkIdType i = 0; i < mesh->GetNumberOfPoints(); ++i) {
    double p[3];
    mesh->GetPoint(i, p);
    uv->SetTuple2(i, p[0] / period, p[1] / period);
  }
  mesh->GetPointData()->SetTCoords(uv);
  return mesh;
}

BodyGeometry boundingGeometry(vtkPolyData* mesh) {
  double b[6];
  mesh->GetBounds(b);
  BodyGeometry g{.shape = BodyShape::Ellipsoid};
  g.centre = {(b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2};
  g.semiAxes = {(b[1] - b[0]) / 2, (b[3] - b[2]) / 2, (b[5] - b[4]) / 2};
  return g;
}

double bodySize(const BodyGeometry& g) {
  switch (g.shape) {
  case BodyShape::Ball:
  case BodyShape::Ellipsoid:
    return g.semiAxes.maxCoeff();
  case BodyShape::Paraboloid:
    return std::max({std::sqrt(2 * g.p * g.height), std::sqrt(2 * g.q * g.height), g.height});
  case BodyShape::None:
    break;
  }
  return 1.0;
}

namespace {
// the body's surface p(u, v) (u the longitude) sampled nu x nv for its mesh; no function for None
struct BodySurface {
  int nu = 0, nv = 0;
  std::function<Eigen::Vector3d(double, double)> point;
};

BodySurface bodySurface(const BodyGeometry& g) {
  const auto point = [g](double u, double v) { return shapePoint(g, u, v); };
  if (g.shape == BodyShape::Ball || g.shape == BodyShape::Ellipsoid) return {96, 48, point};
  if (g.shape == BodyShape::Paraboloid) return {96, 32, point};
  return {};
}
} // namespace

vtkSmartPointer<vtkPolyData> makeBodyMesh(const BodyGeometry& g) {
  const BodySurface s = bodySurface(g);
  return s.point ? grid(s.nu, s.nv, s.point) : vtkSmartPointer<vtkPolyData>::New();
}

vtkSmartPointer<vtkPolyData> makeBodyGridLines(const BodyGeometry& g, int meridians, int parallels) {
  const BodySurface s = bodySurface(g);
  vtkNew<vtkPoints> pts;
  vtkNew<vtkCellArray> lines;
  if (s.point) {
    const auto line = [&](int samples, const auto& at) { // a polyline through at(0..1)
      lines->InsertNextCell(samples + 1);
      for (int k = 0; k <= samples; ++k) {
        const Eigen::Vector3d p = at(double(k) / samples);
        lines->InsertCellPoint(pts->InsertNextPoint(p[0], p[1], p[2]));
      }
    };
    for (int m = 0; m < meridians; ++m)
      line(s.nv, [&](double v) { return s.point(double(m) / meridians, v); });
    for (int k = 1; k <= parallels; ++k) // the poles (and the paraboloid's vertex) are points, not circles
      line(s.nu, [&](double u) { return s.point(u, double(k) / (parallels + 1)); });
  }
  vtkNew<vtkPolyData> out;
  out->SetPoints(pts);
  out->SetLines(lines);
  return out;
}

} // namespace rv
