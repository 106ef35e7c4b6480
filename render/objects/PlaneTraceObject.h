// PlaneTraceObject.h -- the path of the contact point on the plane, drawn just above it.
#pragma once
#include "render/GrowingPolyline.h"
#include "render/objects/VisualObject.h"

namespace rv {

class PlaneTraceObject final : public VisualObject {
public:
  PlaneTraceObject(std::string name, double scale, long maxPoints);
  void attach(vtkRenderer* renderer) override { line_.attach(renderer); }
  void apply(const ObjectOptions& options) override;
  void advance(const FrameState& s) override;
  void clear() override { line_.clear(); }
  long points() const { return line_.size(); }

private:
  double lift_;
  GrowingPolyline line_;
};

} // namespace rv
