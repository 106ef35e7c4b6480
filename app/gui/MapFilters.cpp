// MapFilters.cpp -- the filter windows fed by the map window: kept while open, given what the map computes.
#include "app/gui/MapFilters.h"

#include "app/gui/MultipliersWindow.h"
#include "app/gui/PlotWindow.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/Model.h"

namespace rv {

namespace {
template <class W> std::vector<W*> open(std::vector<QPointer<W>>& windows) {
  std::erase_if(windows, [](const QPointer<W>& w) { return w.isNull(); });
  std::vector<W*> out;
  out.reserve(windows.size());
  for (auto& w : windows)
    out.push_back(w.data());
  return out;
}
} // namespace

void MapFilters::addPlot(PlotWindow* window) {
  plots_.emplace_back(window);
}

void MapFilters::addMultipliers(MultipliersWindow* window) {
  multipliers_.emplace_back(window);
}

void MapFilters::addDiagram(ChartWindow* window) {
  diagrams_.emplace_back(window);
}

std::vector<PlotWindow*> MapFilters::plots() {
  return open(plots_);
}

std::vector<MultipliersWindow*> MapFilters::multipliers() {
  return open(multipliers_);
}

void MapFilters::offer(int job, double parameter, const std::vector<std::complex<double>>& m,
                       bool everyStep) {
  for (MultipliersWindow* w : multipliers())
    w->offer(job, parameter, m, everyStep);
}

void MapFilters::showFixedPoint(int job, const QString& caption, const std::vector<std::complex<double>>& m) {
  for (MultipliersWindow* w : multipliers())
    w->showFixedPoint(job, caption, m);
}

void MapFilters::forget(int job) {
  for (MultipliersWindow* w : multipliers())
    w->forget(job), w->flush();
}

void MapFilters::flush() {
  for (MultipliersWindow* w : multipliers())
    w->flush();
}

void MapFilters::markDiagrams(const Model& model,
                              const std::function<std::vector<ChartWindow::Mark>(const Diagram&)>& place,
                              bool force) {
  const std::vector<ChartWindow*> windows = open(diagrams_);
  if (windows.empty()) return;
  if (!modelDiagrams_) modelDiagrams_ = model.diagrams(); // built once per scene, not on every drain
  std::vector<std::vector<ChartWindow::Mark>> marks;      // per window: its diagram's plane
  for (ChartWindow* w : windows) {
    auto& m = marks.emplace_back();
    try {
      m = place(findDiagram(*modelDiagrams_, w->diagram(), "diagram", model.info().id));
    } catch (const InputError&) { // none such: the window says why its chart failed
    }
  }
  if (!force && marks == marked_) return;
  marked_ = marks;
  for (std::size_t i = 0; i < windows.size(); ++i)
    windows[i]->setMarks(marks[i]);
}

void MapFilters::newScene() {
  for (MultipliersWindow* w : multipliers()) // the families of another problem
    w->clear();
  for (ChartWindow* w : open(diagrams_)) // drawn for the old scene: they keep their chart, no longer marked
    w->setMarks({});
  diagrams_.clear(), marked_.clear(), modelDiagrams_.reset();
}

} // namespace rv
