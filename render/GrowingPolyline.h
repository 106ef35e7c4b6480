// GrowingPolyline.h -- a line that grows by appending points in place (no rebuild per frame), with a
// minimum spacing so that slow motion does not pile up points, and a cap on the number kept.
#pragma once
#include "render/ViewOptions.h"

#include <vtkSmartPointer.h>

class vtkActor;
class vtkPolyData;
class vtkRenderer;

namespace rv {

class GrowingPolyline {
public:
  /// minSpacing: points closer than this to the last one are skipped (the newest is still shown).
  /// asPoints: draw every appended point as a dot, unconnected (the iterates of a map).
  GrowingPolyline(double minSpacing, long maxPoints, bool asPoints = false);
  void attach(vtkRenderer* renderer);
  void setAppearance(const Rgb& color, double lineWidth, double opacity, bool visible);
  void append(double x, double y, double z);
  void clear();
  long size() const;
  vtkActor* actor() const;

private:
  double minSpacing2_;
  long maxPoints_;
  bool asPoints_;
  bool lastIsProvisional_ = false;
  vtkSmartPointer<vtkPolyData> data_;
  vtkSmartPointer<vtkActor> actor_;
};

} // namespace rv
