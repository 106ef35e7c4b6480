// ContactTraceObject.h -- the path of the contact point on the fixed surface (the plane, an ellipsoid, a
// bowl), drawn just off the surface along its normal.
#pragma once
#include "render/GrowingPolyline.h"
#include "render/objects/VisualObject.h"

namespace rv {

class ContactTraceObject final : public VisualObject {
public:
  ContactTraceObject(std::string name, double scale, long maxPoints);
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
