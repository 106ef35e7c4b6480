// ContactTraceObject.h -- the path of the contact point, either on the fixed surface (the plane, an
// ellipsoid, a bowl: drawn just off it along its normal) or on the body itself (kept in the body's frame,
// drawn just outside it, turning with it: manual §2.4.6, the trace on the body).
#pragma once
#include "render/GrowingPolyline.h"
#include "render/objects/VisualObject.h"

namespace rv {

class ContactTraceObject final : public VisualObject {
public:
  enum class On { Support, Body };
  ContactTraceObject(std::string name, On on, double scale, long maxPoints);
  void attach(vtkRenderer* renderer) override { line_.attach(renderer); }
  void apply(const ObjectOptions& options) override;
  void advance(const FrameState& s) override;
  void show(const FrameState& s) override;
  void clear() override { line_.clear(); }
  long points() const { return line_.size(); }
  /// Segments drawn in the last frame (GrowingPolyline's level of detail).
  long segmentsDrawn() const { return line_.segmentsDrawn(); }
  void setLevelOfDetail(bool on) { line_.setLevelOfDetail(on); }
  /// The newest point, in the frame it is kept in (the world's, or the body's).
  const Eigen::Vector3d& lastPoint() const { return last_; }

private:
  On on_;
  double lift_;
  GrowingPolyline line_;
  Eigen::Vector3d last_ = Eigen::Vector3d::Zero();
};

} // namespace rv
