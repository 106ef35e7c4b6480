// ApexWindow.cpp -- the apex motion window: its view, what it follows and the states it is given.
#include "app/gui/ApexWindow.h"

#include "app/gui/MapPanel.h"
#include "app/gui/QtVtkWidget.h"

#include <QWidget>
#include <vtkRenderer.h>

namespace rv {

ApexWindow::ApexWindow(QWidget* parent, std::function<void(QWidget*)> place)
    : parent_(parent), place_(std::move(place)) {}

ApexWindow::~ApexWindow() {
  dropScene();
}

QWidget* ApexWindow::open(const Scene& scene, const ViewOptions& view) {
  if (!window_) {
    view_ = QtVtkWidget::inOwnWindow(parent_, "rollviz — apex motion");
    window_ = view_->window();
    place_(window_);
  }
  if (!visual_ && scene.model->geometry()) {
    ViewOptions v = view;
    v.kind = ViewKind::Apex;
    v.axes.style = AxesOptions::Style::Box;
    v.axes.tickmarks = 4, v.axes.subticks = 1;
    visual_ = std::make_unique<VisualScene>(*scene.model, v, scene.initialState);
    visual_->addTo(view_->renderWindow());
  }
  window_->show();
  window_->raise();
  view_->update();
  return window_;
}

bool ApexWindow::visible() const {
  return window_ && window_->isVisible();
}

void ApexWindow::dropScene() {
  if (visual_ && view_) view_->renderWindow()->RemoveRenderer(visual_->renderer());
  visual_.reset();
  if (tap_) tap_->closed = true;
  tap_.reset(), source_ = -1;
}

void ApexWindow::restart(const Scene& scene) {
  if (!visual_ || followsMap()) return;
  visual_->clear();
  visual_->show(0.0, scene.initialState);
}

void ApexWindow::follow(int id, MapPanel& map, const Scene& scene, double shownTime) {
  if (!visual_) return;
  if (tap_) tap_->closed = true;
  tap_ = map.trajectories().tap(
      id, PlotSettings{.condition = "t", .period = 0.04, .maxPoints = 1L << 40, .wholeState = true});
  source_ = tap_ ? id : -1;
  visual_->clear(); // a new trajectory: its own traces
  if (!tap_) visual_->show(shownTime, scene.initialState);
  window_->setWindowTitle(tap_ ? QString("rollviz — apex motion: trajectory %1").arg(id)
                               : QString("rollviz — apex motion: the 3D view's run"));
}

void ApexWindow::forget(int id, MapPanel& map, const Scene& scene, double shownTime) {
  if (visual_ && id == source_) follow(-1, map, scene, shownTime);
}

void ApexWindow::advance(double t, const Eigen::VectorXd& x) {
  if (visual_ && !followsMap()) visual_->advance(t, x);
}

void ApexWindow::show(double t, const Eigen::VectorXd& x) {
  if (!visual_ || followsMap()) return;
  visual_->show(t, x);
  time_ = t;
}

void ApexWindow::feedFromMap(const Scene& scene) {
  if (!tap_ || !visual_) return;
  std::vector<std::vector<double>> states;
  if (tap_->points.take(states) == 0) return;
  Eigen::VectorXd x(scene.model->dimension());
  for (const auto& v : states) { // (t, x...)
    x = Eigen::Map<const Eigen::VectorXd>(v.data() + 1, x.size());
    visual_->advance(v[0], x);
  }
  visual_->show(states.back()[0], x);
  time_ = states.back()[0];
  update();
}

void ApexWindow::setOptions(const std::string& name, const ObjectOptions& options) {
  if (visual_ && visual_->find(name)) visual_->setOptions(name, options);
  if (view_) view_->update();
}

void ApexWindow::update() {
  if (visible()) view_->update();
}

} // namespace rv
