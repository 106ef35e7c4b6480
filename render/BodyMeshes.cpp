#include "render/BodyMeshes.h"

#include <algorithm>
#include <cmath>
#include <functional>
#include <numbers>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataNormals.h>

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
  constexpr double pi = std::numbers::pi;
  if (g.shape == BodyShape::Ball || g.shape == BodyShape::Ellipsoid)
    return {96, 48, [g](double u, double v) {
              const double lon = 2 * pi * u, lat = pi * (v - 0.5);
              return Eigen::Vector3d(g.centre[0] + g.semiAxes[0] * std::cos(lat) * std::cos(lon),
                                     g.centre[1] + g.semiAxes[1] * std::cos(lat) * std::sin(lon),
                                     g.centre[2] + g.semiAxes[2] * std::sin(lat));
            }};
  if (g.shape == BodyShape::Paraboloid) // r3 = vertex + (r1^2 / p + r2^2 / q) / 2, up to `height`
    return {96, 32, [g](double u, double v) {
              const double lon = 2 * pi * u, s = v * std::sqrt(g.height); // s^2 = height above the vertex
              return Eigen::Vector3d(g.centre[0] + std::sqrt(2 * g.p) * s * std::cos(lon),
                                     g.centre[1] + std::sqrt(2 * g.q) * s * std::sin(lon),
                                     g.centre[2] + s * s);
            }};
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
