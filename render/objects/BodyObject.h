// BodyObject.h -- a rigid body (ball, ellipsoid, paraboloid, or a mesh read from a file) drawn from its mesh
// in its own frame and placed by the pose; textured so that turning and spinning are visible, with a dark
// disc on the plane under the contact point (a cheap depth cue on software GL). Its "grid" style is meridians
// and parallels, not the triangles of the mesh.
#pragma once
#include "dynamics/core/Model.h"
#include "render/objects/VisualObject.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;

namespace rv {

class BodyObject final : public VisualObject {
public:
  /// The geometry's shape, or `mesh` (in the body's frame) when given: then the "grid" style is its edges.
  BodyObject(std::string name, const BodyGeometry& geometry,
             const vtkSmartPointer<vtkPolyData>& mesh = nullptr);
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  void show(const FrameState& s) override;

private:
  double size_;
  bool textured_ = true; ///< the surface has texture coordinates
  vtkSmartPointer<vtkActor> body_, shadow_;
  vtkSmartPointer<vtkActor> grid_; ///< meridians and parallels: the "grid" and "both" styles
};

} // namespace rv
