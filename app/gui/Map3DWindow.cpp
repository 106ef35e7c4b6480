// Map3DWindow.cpp -- the Map3D window: its chart, made when opened and fed with the map's trajectories.
#include "app/gui/Map3DWindow.h"

#include "app/gui/QtVtkWidget.h"
#include "render/charts/Chart3D.h"
#include "render/charts/PoincareChart.h"

#include <QWidget>
#include <vtkRenderer.h>

namespace rv {

Map3DWindow::Map3DWindow(QWidget* parent) : parent_(parent) {}

Map3DWindow::~Map3DWindow() {
  if (chart_ && view_) view_->renderWindow()->RemoveRenderer(chart_->renderer());
}

QWidget* Map3DWindow::open(const std::array<std::string, 3>& names, const std::vector<Track>& tracks) {
  if (!window_) {
    view_ = QtVtkWidget::inOwnWindow(parent_, "rollviz — Map3D");
    window_ = view_->window();
  }
  if (!chart_) {
    chart_ = std::make_unique<Chart3D>(names);
    series_ = 0;
    feed(tracks);
    chart_->attach(view_->renderWindow());
  }
  window_->show();
  window_->raise();
  return window_;
}

bool Map3DWindow::visible() const {
  return window_ && window_->isVisible();
}

void Map3DWindow::reset(bool keepShown) {
  if (!chart_) return;
  view_->renderWindow()->RemoveRenderer(chart_->renderer()); // the window's context is alive here
  chart_.reset();
  points_ = 0;
  if (!keepShown) window_->hide();
}

void Map3DWindow::feed(const std::vector<Track>& tracks) {
  if (!chart_) return;
  for (; series_ < tracks.size(); ++series_)
    chart_->addSeries({}, {}, {}, seriesColour(static_cast<int>(series_)), 3);
  points_ = 0;
  for (std::size_t k = 0; k < tracks.size(); ++k) {
    const Track& t = tracks[k];
    points_ += static_cast<long>(t.z->size());
    if (t.z->size() == t.x->size()) chart_->setSeries(static_cast<int>(k), *t.x, *t.y, *t.z);
  }
  if (visible()) view_->update();
}

void Map3DWindow::select(int index) {
  if (!chart_) return;
  chart_->select(index); // its series follow the tracks' order
  if (visible()) view_->update();
}

long Map3DWindow::points() const {
  return chart_ ? points_ : 0;
}

} // namespace rv
