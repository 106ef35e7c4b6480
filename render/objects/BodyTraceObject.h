// BodyTraceObject.h -- the path of the contact point on the body itself (manual §2.4.6: the trace on the
// body), kept in the body's frame and drawn just outside its surface, so that it turns with the body.
#pragma once
#include "render/GrowingPolyline.h"
#include "render/objects/VisualObject.h"

namespace rv {

class BodyTraceObject final : public VisualObject {
public:
  BodyTraceObject(std::string name, double scale, long maxPoints);
  void attach(vtkRenderer* renderer) override { line_.attach(renderer); }
  void apply(const ObjectOptions& options) override;
  void advance(const FrameState& s) override;
  void show(const FrameState& s) override;
  void clear() override { line_.clear(); }
  long points() const { return line_.size(); }
  /// The newest point, in the body's frame.
  const Eigen::Vector3d& lastPoint() const { return last_; }

private:
  double lift_;
  GrowingPolyline line_;
  Eigen::Vector3d last_ = Eigen::Vector3d::Zero();
};

} // namespace rv
