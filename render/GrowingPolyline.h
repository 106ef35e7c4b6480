// GrowingPolyline.h -- a line that grows by appending points in place (no rebuild per frame), simplified as
// it grows so that long traces stay cheap to draw, with a cap on the number of vertices kept. The
// simplification is a streaming form of Douglas & Peucker (Cartographica 10(2), 1973): a point is dropped
// while the chord from the last kept vertex to the newest point passes within `tolerance` of every point
// dropped since; a smooth curve of radius r then keeps one vertex per ~sqrt(8 r tolerance) of its length.
#pragma once
#include "render/ViewOptions.h"

#include <Eigen/Core>
#include <vector>

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace rv {

class GrowingPolyline {
public:
  /// tolerance: how far the drawn line may pass from a dropped point (0 keeps every point); the newest point
  /// is always the line's end. asPoints: draw every appended point as a dot, unconnected (the iterates of a
  /// map).
  GrowingPolyline(double tolerance, long maxPoints, bool asPoints = false);
  void attach(vtkRenderer* renderer);
  void setAppearance(const Rgb& color, double lineWidth, double opacity, bool visible);
  void append(double x, double y, double z);
  void clear();
  /// Vertices drawn.
  long size() const;
  /// Vertex i (0 <= i < size()).
  Eigen::Vector3d vertex(long i) const;
  vtkActor* actor() const;

private:
  bool chordPassesNearDropped(const Eigen::Vector3d& end) const;
  double tolerance_;
  long maxPoints_;
  bool asPoints_;
  Eigen::Vector3d anchor_ = Eigen::Vector3d::Zero();      ///< the last vertex that stays
  Eigen::Vector3d provisional_ = Eigen::Vector3d::Zero(); ///< the newest point, the line's end
  std::vector<Eigen::Vector3d> samples_; ///< points dropped since the anchor, every tolerance / 2
  vtkSmartPointer<vtkPolyData> data_;
  vtkSmartPointer<vtkActor> actor_;
};

} // namespace rv
