// BodyShapes.h -- the surfaces of the drawn shapes (ball, ellipsoid, paraboloid) as functions of two
// parameters, and their normals: one definition for the body meshes (render/BodyMeshes.cpp) and for the fixed
// surfaces a body written as equations rolls on (dynamics/models/EquationModel.cpp). Also the capability of a
// model whose body is drawn from a mesh file.
#pragma once
#include "dynamics/core/Model.h"

#include <functional>
#include <optional>
#include <string>

namespace rv {

/// A point of the shape's surface: u in [0, 1] the longitude (periodic), v in [0, 1] from the south pole to
/// the north pole (ball, ellipsoid) or from the vertex to `height` above it (paraboloid). Zero for None.
Eigen::Vector3d shapePoint(const BodyGeometry& g, double u, double v);

/// The unit normal of the shape's surface at (or, for a point off it, for the level surface through) x,
/// pointing out of the ellipsoid or up out of the paraboloid's bowl. e_z for None (the plane).
Eigen::Vector3d shapeNormal(const BodyGeometry& g, const Eigen::Vector3d& x);

/// A mesh file (STL or OBJ) a body is drawn from, in its own frame relative to the pose's centre.
struct BodyMeshFile {
  std::string path; ///< absolute, or relative to the working folder
  double scale = 1; ///< the mesh's coordinates are multiplied by it
};

/// A body's surface as F(p) = 0, F < 0 inside, p in the body's frame relative to the pose's centre (a rolling
/// body given by its implicit surface, scenes/RollingModel.h); `size` bounds |p| on the surface.
struct ImplicitSurface {
  std::function<double(const Eigen::Vector3d&)> F;
  double size = 1;
};

/// A capability of some models (those written as equations whose view names a mesh or an implicit surface),
/// found by dynamic_cast from a Model: the render layer reads the file, or samples the surface, and draws it
/// instead of the geometry's shape.
class DrawnFromMesh {
public:
  virtual ~DrawnFromMesh() = default;
  /// The body's mesh; nullopt when it has none.
  virtual std::optional<BodyMeshFile> bodyMesh() const = 0;
  /// The body's implicit surface; nullopt when it has none.
  virtual std::optional<ImplicitSurface> bodySurface() const { return std::nullopt; }
  /// The support's implicit surface in world axes (F < 0 in the support); nullopt when it has none.
  virtual std::optional<ImplicitSurface> supportSurface() const { return std::nullopt; }
};

} // namespace rv
