// SceneAxesObject.h -- the scene's coordinate axes (manual §2.4.6: axes style none / normal / box; the axis
// tab: ticks and subticks, range min/max, numbers of tickmarks and subticks). Three vtkAxisActor with the
// ticks at round numbers (steps of 1, 2 or 5 x 10^k, about `tickmarks` intervals of the range) placed where
// they fall, plus the box's edges.
#pragma once
#include "render/objects/VisualObject.h"

#include <array>
#include <optional>
#include <string>
#include <utility>
#include <vector>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

class vtkActor;
class vtkAxisActor;
class vtkOutlineSource;

namespace rv {

class SceneAxesObject final : public VisualObject {
public:
  /// `fallbackMin/Max`: the range when the options give none (the region the scene is drawn in).
  SceneAxesObject(std::string name, const AxesOptions& axes, const std::array<double, 3>& fallbackMin,
                  const std::array<double, 3>& fallbackMax);
  ~SceneAxesObject() override;
  void attach(vtkRenderer* renderer) override;
  void apply(const ObjectOptions& options) override;
  /// Without a range of its own the box grows to hold the motion: the contact point of a body, the first
  /// three coordinates of a phase curve (by a quarter of its size each time, so it is rebuilt seldom).
  void advance(const FrameState& s) override;
  /// Whether the box grows with the motion (not in the apex view: its box is the unit sphere's).
  /// Draws the axes this much above where their numbers say (a body view: lines on the floor at z = 0 would
  /// be hidden in it, as the contact trace would).
  void setLift(double dz);
  void setFollowsMotion(bool follows) { follows_ = follows; }
  /// Back to the region the scene started in.
  void clear() override;
  /// The range drawn now (min and max of x, y, z).
  std::pair<std::array<double, 3>, std::array<double, 3>> range() const { return {lo_, hi_}; }
  /// Changes the style, range and ticks (the scene's view.axes).
  void setAxes(const AxesOptions& axes);
  /// Writes numbers from [lo, hi] (and these titles) along axes that span another world range (a chart
  /// drawn scaled into a box).
  void setLabelling(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                    const std::array<std::string, 3>& titles);
  /// The numbers written at the major ticks of axis i (0, 1, 2), lowest first: the multiples of a round step
  /// (1, 2 or 5 x 10^k) inside the axis' range, about `tickmarks` intervals apart.
  std::vector<double> majorTicks(int axis) const;
  /// Whether axis `i` (0, 1, 2) shows its labels in the last frame.
  bool labelsShown(int i) const;
  /// The font size (pixels) of axis `i`'s numbers.
  int labelFontSize(int i) const;

private:
  void rebuild();
  /// Before each frame: labels that would fall on one another along a foreshortened axis ("-20-100 10") are
  /// thinned to every k-th tick; an axis seen nearly end-on ("3210-1-2-3" at a corner) shows its ticks but
  /// neither labels nor title.
  void fitLabelsToView();

  AxesOptions axes_;
  std::array<double, 3> lo_, hi_, fallbackLo_, fallbackHi_, startLo_, startHi_;
  bool enabled_ = true;
  bool follows_ = true;
  std::optional<std::array<double, 3>> labelLo_, labelHi_;
  std::array<std::string, 3> titles_ = {"x", "y", "z"};
  std::array<vtkSmartPointer<vtkAxisActor>, 3> axis_;
  std::array<std::vector<std::string>, 3> labelTexts_; ///< every major tick's number
  std::array<int, 3> labelStride_ = {0, 0, 0};         ///< every k-th labelled in the last frame (0: none)
  vtkSmartPointer<vtkOutlineSource> outline_;
  vtkSmartPointer<vtkActor> box_;
  vtkWeakPointer<vtkRenderer> renderer_;
  unsigned long observer_ = 0;
};

} // namespace rv
