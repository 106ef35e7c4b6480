// BodyMeshes.h -- surfaces of the rolling bodies in their own frame, with texture coordinates (longitude,
// latitude) so that one pattern shows their turning: ball, ellipsoid, paraboloid.
#pragma once
#include "dynamics/core/BodyShapes.h"
#include "dynamics/core/Model.h"

#include <string>
#include <vtkSmartPointer.h>

class vtkPolyData;

namespace rv {

/// A triangulated surface with normals and texture coordinates for the geometry (None: an empty mesh).
vtkSmartPointer<vtkPolyData> makeBodyMesh(const BodyGeometry& geometry);

/// The body's "grid" style: `meridians` lines of constant longitude and `parallels` of constant latitude
/// (height, for a paraboloid) on its surface, in its own frame.
vtkSmartPointer<vtkPolyData> makeBodyGridLines(const BodyGeometry& geometry, int meridians = 24,
                                               int parallels = 11);

/// The fixed surface as a grid of (u, v) in [0, 1]^2, textured with a repeating pattern (8 x 4 repeats).
vtkSmartPointer<vtkPolyData> makeSurfaceMesh(const SupportSurface& surface);

/// A body's mesh read from its file by VTK's STL or OBJ reader, its coordinates scaled, with normals for
/// smooth shading. Throws InputError naming the file when it holds no triangles.
vtkSmartPointer<vtkPolyData> readBodyMesh(const BodyMeshFile& file);

/// The ellipsoid of a mesh's bounding box (centre, half-extents): the size and axes the view gives it.
BodyGeometry boundingGeometry(vtkPolyData* mesh);

/// The surface F = 0 of an implicit body (or support: `what` names it in the message) sampled on a grid over
/// [-1.25 size, 1.25 size]^3 (marching cubes, outward normals); InputError when F has no zero there.
vtkSmartPointer<vtkPolyData> sampleImplicitSurface(const ImplicitSurface& surface,
                                                   const std::string& what = "the body's surface");

/// An implicit support's surface, sampled as sampleImplicitSurface does, with texture coordinates from the
/// world's x and y (8 repeats across its size) for the support's pattern.
vtkSmartPointer<vtkPolyData> sampleImplicitSupport(const ImplicitSurface& surface);

/// A length that sets the scene's scale: the largest half-extent of the body.
double bodySize(const BodyGeometry& geometry);

} // namespace rv
