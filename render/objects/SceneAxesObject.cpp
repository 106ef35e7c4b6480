#include "render/objects/SceneAxesObject.h"

#include "dynamics/core/Format.h"

#include <algorithm>
#include <cmath>
#include <vtkActor.h>
#include <vtkAxisActor.h>
#include <vtkCommand.h>
#include <vtkOutlineSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>
#include <vtkTextProperty.h>

namespace rv {

SceneAxesObject::SceneAxesObject(std::string name, const AxesOptions& axes,
                                 const std::array<double, 3>& fallbackMin,
                                 const std::array<double, 3>& fallbackMax)
    : VisualObject(std::move(name)), axes_(axes), fallbackLo_(fallbackMin), fallbackHi_(fallbackMax),
      startLo_(fallbackMin), startHi_(fallbackMax) {
  for (int i = 0; i < 3; ++i) {
    auto a = vtkSmartPointer<vtkAxisActor>::New();
    a->SetAxisType(i); // VTK_AXIS_TYPE_X, _Y, _Z
    a->SetTickLocationToOutside();
    a->SetCalculateTitleOffset(false);
    a->SetCalculateLabelOffset(false);
    for (auto* p : {a->GetTitleTextProperty(), a->GetLabelTextProperty()}) {
      p->SetColor(0.1, 0.1, 0.15);
      p->SetFontFamilyToArial();
    }
    // labels are screen text (Use2DMode: readable at any zoom); VTK's 2D mode places x labels below their
    // axis and y labels beside it, but leaves z's at the tick itself: right-justified, they stay outside the
    // box
    a->SetUse2DMode(1);
    if (i == 2) a->GetLabelTextProperty()->SetJustificationToRight();
    a->GetLabelTextProperty()->SetVerticalJustificationToCentered();
    a->GetAxisLinesProperty()->SetColor(0.15, 0.15, 0.2);
    a->GetAxisMajorTicksProperty()->SetColor(0.15, 0.15, 0.2);
    a->GetAxisMinorTicksProperty()->SetColor(0.15, 0.15, 0.2);
    axis_[i] = a;
  }
  outline_ = vtkSmartPointer<vtkOutlineSource>::New();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(outline_->GetOutputPort());
  box_ = vtkSmartPointer<vtkActor>::New();
  box_->SetMapper(mapper);
  box_->GetProperty()->SetColor(0.3, 0.3, 0.36);
  box_->GetProperty()->SetLighting(false);
}

void SceneAxesObject::setLift(double dz) {
  for (auto& a : axis_)
    a->SetPosition(0, 0, dz);
  box_->SetPosition(0, 0, dz);
}

SceneAxesObject::~SceneAxesObject() {
  if (renderer_) renderer_->RemoveObserver(observer_);
}

void SceneAxesObject::attach(vtkRenderer* renderer) {
  if (renderer_) renderer_->RemoveObserver(observer_);
  renderer_ = renderer;
  observer_ = renderer->AddObserver(vtkCommand::StartEvent, this, &SceneAxesObject::fitLabelsToView);
  for (auto& a : axis_) {
    a->SetCamera(renderer->GetActiveCamera());
    renderer->AddActor(a);
  }
  renderer->AddActor(box_);
  rebuild();
}

void SceneAxesObject::apply(const ObjectOptions& o) {
  enabled_ = o.enabled;
  rebuild();
}

void SceneAxesObject::advance(const FrameState& s) {
  if (labelLo_ || !follows_) return; // a chart's box has the chart's range, the apex view the sphere's
  std::array<double, 3> p{};
  if (s.pose)
    p = {s.pose->contact[0], s.pose->contact[1], s.pose->contact[2]};
  else
    for (int i = 0; i < 3; ++i)
      p[i] = i < s.model.dimension() ? s.x[i] : 0.0;
  bool grew = false;
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(p[i])) return;
    const double margin = 0.25 * (fallbackHi_[i] - fallbackLo_[i]);
    if (p[i] < fallbackLo_[i]) fallbackLo_[i] = p[i] - margin, grew = true;
    if (p[i] > fallbackHi_[i]) fallbackHi_[i] = p[i] + margin, grew = true;
  }
  if (grew && !(axes_.min && axes_.max)) rebuild();
}

void SceneAxesObject::clear() {
  fallbackLo_ = startLo_, fallbackHi_ = startHi_;
  rebuild();
}

void SceneAxesObject::setAxes(const AxesOptions& axes) {
  axes_ = axes;
  rebuild();
}

void SceneAxesObject::setLabelling(const std::array<double, 3>& lo, const std::array<double, 3>& hi,
                                   const std::array<std::string, 3>& titles) {
  labelLo_ = lo, labelHi_ = hi, titles_ = titles;
  rebuild();
}

std::vector<double> SceneAxesObject::majorTicks(int i) const {
  const double a = labelLo_ ? (*labelLo_)[i] : lo_[i], b = labelHi_ ? (*labelHi_)[i] : hi_[i];
  const double lo = std::min(a, b), hi = std::max(a, b);
  if (!(hi > lo)) return {a};
  // round numbers: a step of 1, 2 or 5 x 10^k giving about `tickmarks` intervals, from the first multiple in
  // range
  const double raw = (hi - lo) / std::max(1, axes_.tickmarks);
  const double magnitude = std::pow(10.0, std::floor(std::log10(raw)));
  const double r = raw / magnitude;
  const double step = (r < 1.5 ? 1 : r < 3 ? 2 : r < 7 ? 5 : 10) * magnitude;
  std::vector<double> ticks;
  for (double k = std::ceil(lo / step - 1e-9); k * step <= hi + 1e-9 * step; k += 1)
    ticks.push_back(std::abs(k) < 0.5 ? 0.0 : k * step);
  return ticks;
}

void SceneAxesObject::rebuild() {
  lo_ = axes_.min.value_or(fallbackLo_);
  hi_ = axes_.max.value_or(fallbackHi_);
  const bool shown = enabled_ && axes_.style != AxesOptions::Style::None;
  const double bounds[6] = {lo_[0], hi_[0], lo_[1], hi_[1], lo_[2], hi_[2]};
  const double extent = std::max({hi_[0] - lo_[0], hi_[1] - lo_[1], hi_[2] - lo_[2]});
  for (int i = 0; i < 3; ++i) {
    auto& a = axis_[i];
    // y runs along the far x edge: three axes from one corner put their first labels on each other
    double p1[3] = {i == 1 ? hi_[0] : lo_[0], lo_[1], lo_[2]}, p2[3] = {p1[0], p1[1], p1[2]};
    p2[i] = hi_[i];
    a->SetPoint1(p1);
    a->SetPoint2(p2);
    a->SetBounds(bounds);
    a->SetRange(lo_[i], hi_[i]);
    // vtkAxisActor places ticks in world coordinates (…Start/Delta…) and numbers them in range units; the
    // ticks are round numbers of the labelled range, placed where they fall in the world's
    const auto ticks = majorTicks(i);
    const double from = labelLo_ ? (*labelLo_)[i] : lo_[i], to = labelHi_ ? (*labelHi_)[i] : hi_[i];
    const double toWorld = to != from ? (hi_[i] - lo_[i]) / (to - from) : 1.0;
    const double step = ticks.size() > 1 ? ticks[1] - ticks[0] : (hi_[i] - lo_[i]);
    const double major = step * toWorld, minor = major / (axes_.subticks + 1);
    const double first = lo_[i] + (ticks.front() - from) * toWorld;
    a->SetMajorStart(i, first);
    a->SetDeltaMajor(i, major);
    a->SetMinorStart(first - std::floor((first - lo_[i]) / minor + 1e-9) * minor);
    a->SetDeltaMinor(minor);
    a->SetMajorRangeStart(ticks.front());
    a->SetDeltaRangeMajor(step);
    a->SetMinorRangeStart(ticks.front());
    a->SetDeltaRangeMinor(step / (axes_.subticks + 1));
    a->SetTitle(titles_[i].c_str());
    const double span = std::abs(ticks.back() - ticks.front());
    labelTexts_[i].clear();
    for (double v : ticks)
      labelTexts_[i].push_back(format("%.4g", std::abs(v) < 1e-12 * span ? 0.0 : v));
    labelStride_[i] = 0; // written by fitLabelsToView
    a->SetMajorTickSize(0.02 * extent);
    a->SetMinorTickSize(0.01 * extent);
    a->SetLabelOffset(0.05 * extent);
    a->SetTitleOffset(0.12 * extent);
    a->SetLabelScale(0.032 * extent);
    a->SetTitleScale(0.04 * extent);
    a->SetTickVisibility(axes_.ticks);
    a->SetMinorTicksVisible(axes_.ticks && axes_.subticks > 0);
    a->SetLabelVisibility(axes_.ticks);
    a->SetTitleVisibility(true);
    a->SetVisibility(shown);
  }
  outline_->SetBounds(bounds);
  box_->SetVisibility(shown && axes_.style == AxesOptions::Style::Box);
  fitLabelsToView();
}

bool SceneAxesObject::labelsShown(int i) const {
  return axis_[i]->GetVisibility() && axis_[i]->GetLabelVisibility();
}

int SceneAxesObject::labelFontSize(int i) const {
  return axis_[i]->GetLabelTextProperty()->GetFontSize();
}

void SceneAxesObject::fitLabelsToView() {
  if (!renderer_ || renderer_->GetSize()[0] <= 0) return;
  const auto toDisplay = [this](const double* p) {
    renderer_->SetWorldPoint(p[0], p[1], p[2], 1.0);
    renderer_->WorldToDisplay();
    const double* d = renderer_->GetDisplayPoint();
    return std::array<double, 2>{d[0], d[1]};
  };
  for (int i = 0; i < 3; ++i) {
    auto& a = axis_[i];
    const auto& texts = labelTexts_[i];
    if (texts.empty()) continue;
    const auto p = toDisplay(a->GetPoint1()), q = toDisplay(a->GetPoint2());
    // a label needs its width along the axis (about 0.6 of the font size a character, and a gap): where the
    // foreshortened axis has less room a tick, every k-th is labelled; an axis seen end-on has none
    const double length = std::hypot(q[0] - p[0], q[1] - p[1]);
    std::size_t chars = 1;
    for (const auto& t : texts)
      chars = std::max(chars, t.size());
    const double width = 0.6 * a->GetLabelTextProperty()->GetFontSize() * static_cast<double>(chars) + 6;
    const double perTick = length / static_cast<double>(std::max<std::size_t>(1, texts.size() - 1));
    const double k = std::isfinite(perTick) && perTick > 0 ? std::ceil(width / perTick) : 1e9;
    // two labels at least, on an axis a few labels long (a short one ends among the others at a corner)
    const bool room =
        k <= std::max<double>(1, static_cast<double>(texts.size() - 1) / 2) && length >= 2.5 * width;
    const int stride = room ? static_cast<int>(k) : 0;
    if (stride != labelStride_[i] && stride > 0) {
      vtkNew<vtkStringArray> labels;
      for (std::size_t n = 0; n < texts.size(); ++n)
        labels->InsertNextValue(n % static_cast<std::size_t>(stride) == 0 ? texts[n] : std::string());
      a->SetLabels(labels);
    }
    labelStride_[i] = stride;
    a->SetLabelVisibility(axes_.ticks && room);
    a->SetTitleVisibility(room);
  }
}

} // namespace rv
