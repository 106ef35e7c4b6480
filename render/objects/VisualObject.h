// VisualObject.h -- one named thing in a visual scene, bound to the model's state (design.md "Visual
// object").
#pragma once
#include "dynamics/core/Model.h"
#include "render/ViewOptions.h"

#include <string>

class vtkRenderer;

namespace rv {

/// What objects see of the motion at one instant.
struct FrameState {
  double t;
  const double* x;
  const Model& model;
  const std::optional<BodyPose>& pose;
};

class VisualObject {
public:
  explicit VisualObject(std::string name) : name_(std::move(name)) {}
  virtual ~VisualObject() = default;
  const std::string& name() const { return name_; }
  /// Whether the object shows when the scene says nothing of it.
  virtual bool shownByDefault() const { return true; }
  /// Adds the object's props to the renderer (once).
  virtual void attach(vtkRenderer* renderer) = 0;
  /// Applies appearance options; called at creation and whenever the user edits them.
  virtual void apply(const ObjectOptions& options) = 0;
  /// A state on the way to the next frame: objects that leave traces record it.
  virtual void advance(const FrameState&) {}
  /// The state shown in the next frame.
  virtual void show(const FrameState& s) { advance(s); }
  /// Forgets the history (traces) when the run restarts.
  virtual void clear() {}

private:
  std::string name_;
};

} // namespace rv
