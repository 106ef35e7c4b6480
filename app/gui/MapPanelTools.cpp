// MapPanelTools.cpp -- the map window's fixed-point tools (manual §2.3): a search from a click or the scene's
// guess, the separatrices, the continuation of a family and the switch to a doubled one, the bifurcation
// tree; each a job whose output is drawn on the map, offered to the multipliers filters, and whose outcome
// reaches the Results dock.
#include "app/gui/MapPanel.h"

#include "app/gui/MultipliersWindow.h"
#include "app/gui/QtVtkWidget.h"
#include "dynamics/core/Errors.h"
#include "dynamics/jobs/FixedPointTasks.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/SceneTools.h"

#include <algorithm>

namespace rv {

void MapPanel::searchFixedPointAt(double x, double y) {
  if (!scene_ || scene_->model->info().mapCoordinates.empty()) return;
  chart_->holdRanges();
  try {
    MapToolOverrides o;
    o.guess = mapPoint(x, y);
    const SceneMap sm(Scene(*scene_), o);
    auto task = std::make_unique<FixedPointTask>(sm.taskSpec());
    FixedPointTask* raw = task.get();
    Job& job = jobs_.add(std::move(task));
    const int path = chart_->addCurve({x, x}, {y, y}, kSearchColour, 1.5);
    const int point = chart_->addSeries({}, {}, kSearchColour);
    searches_.push_back({&job, raw, {}, {}, path, point});
    searches_.back().found = chart_->addMarkers({}, {}, kSearchColour);
    job.start();
    emit message(
        QString("searching a fixed point of order %1 from (%2, %3)").arg(sm.section().order).arg(x).arg(y));
  } catch (const InputError& e) {
    emit message(QString::fromStdString(e.what()));
  }
}

std::unique_ptr<SceneMap> MapPanel::sceneMap() {
  if (!scene_ || scene_->model->info().mapCoordinates.empty()) {
    emit message("this problem has no map coordinates");
    return nullptr;
  }
  try {
    return std::make_unique<SceneMap>(Scene(*scene_));
  } catch (const InputError& e) {
    emit message(QString::fromStdString(e.what()));
    return nullptr;
  }
}

void MapPanel::startTool(std::unique_ptr<Task> task, const Rgb& colour, std::function<bool(ToolSeries&)> pull,
                         std::function<QString(const ToolSeries&)> ended) {
  Job& job = jobs_.add(std::move(task));
  tools_.push_back({&job, chart_->addSeries({}, {}, colour), colour, {}, {}, std::move(pull)});
  tools_.back().ended = std::move(ended);
  job.start();
}

void MapPanel::offerMultipliers(ToolSeries& t, double parameter, const std::vector<std::complex<double>>& m) {
  t.multipliers.emplace_back(parameter, m);
  std::erase_if(multiplierWindows_, [](const QPointer<MultipliersWindow>& w) { return w.isNull(); });
  for (auto& w : multiplierWindows_)
    w->offer(t.job->id(), parameter, m, t.everyStep);
}

void MapPanel::addMultipliersWindow(MultipliersWindow* window) {
  multiplierWindows_.emplace_back(window);
  for (const auto& t : tools_)
    for (const auto& [parameter, m] : t.multipliers)
      window->offer(t.job->id(), parameter, m, t.everyStep);
  for (const auto& s : searches_)
    if (!s.multipliers.empty()) window->showFixedPoint(s.job->id(), s.caption, s.multipliers);
  window->flush();
}

void MapPanel::startSeparatrices() {
  const auto sm = sceneMap();
  if (!sm) return;
  const SeparatrixSettings base = separatrixSettings(scene_->tool("separatrix"), sm->search());
  const Rgb colours[] = {{0.55, 0.1, 0.6}, {0.55, 0.1, 0.6}, {0.1, 0.5, 0.2}, {0.1, 0.5, 0.2}};
  for (int b = 1; b <= 4; ++b) {
    SeparatrixSettings s = base;
    s.branch = b;
    auto task = std::make_unique<SeparatrixTask>(sm->taskSpec(), s);
    SeparatrixTask* raw = task.get();
    startTool(
        std::move(task), colours[b - 1],
        [raw](ToolSeries& t) {
          std::vector<std::vector<Eigen::VectorXd>> batches;
          raw->points().take(batches);
          for (const auto& batch : batches)
            for (const auto& p : batch)
              t.x.push_back(p[0]), t.y.push_back(p[1]);
          return !batches.empty();
        },
        [b](const ToolSeries& t) {
          return QString("separatrix branch %1 (tool #%2) ended: %3 points")
              .arg(b)
              .arg(t.job->id())
              .arg(t.x.size());
        });
  }
  emit message("growing the separatrices of the fixed point near the scene's guess");
}

void MapPanel::startContinuation() {
  const auto sm = sceneMap();
  if (!sm) return;
  ContinuationSettings settings = sm->continuation();
  startContinuationWith(settings, "continuing the scene's fixed point");
}

void MapPanel::followDoubledFamily(int k) {
  const auto sm = sceneMap();
  if (!sm) return;
  if (k < 1 || k > static_cast<int>(doublings_.size())) {
    emit message(
        doublings_.empty()
            ? "no period doubling located: continue the fixed point first (Tools > Continue the fixed "
              "point)"
            : QString("there are %1 located period doublings, not %2").arg(doublings_.size()).arg(k));
    return;
  }
  ContinuationSettings settings = sm->continuation();
  settings.switchAt = k;
  startContinuationWith(settings, "following the family of doubled order born at the " + doublings_[k - 1]);
}

std::vector<std::pair<double, double>> MapPanel::toolPoints(int id) const {
  std::vector<std::pair<double, double>> out;
  for (const auto& t : tools_)
    if (t.job->id() == id)
      for (std::size_t i = 0; i < t.x.size(); ++i)
        out.emplace_back(t.x[i], t.y[i]);
  return out;
}

void MapPanel::startContinuationWith(const ContinuationSettings& settings, const QString& said) {
  const auto sm = sceneMap();
  if (!sm) return;
  try {
    auto task = std::make_unique<ContinuationTask>(sm->taskSpec(), settings);
    ContinuationTask* raw = task.get();
    const std::string parameter = settings.parameter;
    // the doublings of a family followed from the scene's point are where a later switch can start
    const int run = settings.switchAt == 0 ? ++continuationRun_ : -1;
    if (run > 0) doublings_.clear();
    startTool(
        std::move(task), {0.95, 0.55, 0.1},
        [this, raw, parameter, run](ToolSeries& t) {
          std::vector<ContinuationPoint> points;
          std::vector<TypeChange> changes;
          raw->points().take(points);
          raw->changes().take(changes);
          for (const auto& p : points) {
            t.x.push_back(p.fixedPoint.point[0]), t.y.push_back(p.fixedPoint.point[1]);
            offerMultipliers(t, p.parameter, p.fixedPoint.multipliers);
          }
          for (const auto& c : changes) {
            const QString text = QString::fromStdString(describe(c, parameter));
            if (run == continuationRun_ && c.kind == TypeChange::Kind::MultiplierMinusOne)
              doublings_.push_back(QString("period doubling at %1 = %2")
                                       .arg(QString::fromStdString(parameter))
                                       .arg(c.parameter, 0, 'g', 12));
            emit message(text);
          }
          return !points.empty();
        },
        [parameter](const ToolSeries& t) {
          if (t.multipliers.empty())
            return QString("continuation (tool #%1) ended with no point").arg(t.job->id());
          return QString("continuation (tool #%1) ended: %2 fixed points, %3 from %4 to %5")
              .arg(t.job->id())
              .arg(t.multipliers.size())
              .arg(QString::fromStdString(parameter))
              .arg(t.multipliers.front().first, 0, 'g', 10)
              .arg(t.multipliers.back().first, 0, 'g', 10);
        });
    emit message(said);
  } catch (const InputError& e) {
    emit message(QString::fromStdString(e.what()));
  }
}

void MapPanel::startBifurcationTree() {
  const auto sm = sceneMap();
  if (!sm) return;
  try {
    const BifurcationTreeSettings settings =
        bifurcationTreeSettings(sm->scene().tool("bifurcation_tree"), sm->continuation());
    auto task = std::make_unique<BifurcationTreeTask>(sm->taskSpec(), settings);
    BifurcationTreeTask* raw = task.get();
    startTool(
        std::move(task), {0.6, 0.2, 0.5},
        [this, raw](ToolSeries& t) {
          t.everyStep = true;
          std::vector<TreePoint> points;
          std::vector<PeriodDoubling> doublings;
          raw->points().take(points);
          raw->doublings().take(doublings);
          for (const auto& p : points) {
            t.x.push_back(p.point.fixedPoint.point[0]), t.y.push_back(p.point.fixedPoint.point[1]);
            if (p.point.fixedPoint.type ==
                FixedPointType::Elliptic) // manual §2.4.3: only the tree's elliptic branches
              offerMultipliers(t, p.point.parameter, p.point.fixedPoint.multipliers);
          }
          for (const auto& d : doublings)
            emit message(QString("period doubling of the order-%1 point at %2")
                             .arg(d.order)
                             .arg(d.parameter, 0, 'g', 12));
          std::vector<std::string> ends;
          raw->ends().take(ends);
          for (const auto& e : ends)
            emit message(QString("the bifurcation tree ends: %1").arg(QString::fromStdString(e)));
          return !points.empty();
        },
        [](const ToolSeries& t) {
          return QString("bifurcation tree (tool #%1) ended: %2 fixed points")
              .arg(t.job->id())
              .arg(t.x.size());
        });
    emit message("growing the bifurcation tree of the scene's fixed point");
  } catch (const InputError& e) {
    emit message(QString::fromStdString(e.what()));
  }
}

void MapPanel::searchFromGuess() {
  if (!scene_ || scene_->guess.size() < 2) {
    emit message("the scene has no fixedpoint.guess (set it in the Fixed point tab, or Shift+click the map)");
    return;
  }
  searchFixedPointAt(scene_->guess[0], scene_->guess[1]);
}

int MapPanel::fixedPointsFound() const {
  int n = 0;
  for (const auto& s : searches_)
    n += !s.foundAt.empty();
  return n;
}

namespace {
/// A tool's output as a session or Undo kept it: drawn already, nothing to compute.
class RecordedTask final : public Task {
public:
  RecordedTask(std::string name, std::string summary)
      : name_(std::move(name)), summary_(std::move(summary)) {}
  std::string name() const override { return name_; }
  std::string describe() const override { return "restored from a saved record: " + summary_; }
  bool run(const ToolControl&) override { return true; }
  void reset() override {}

private:
  std::string name_, summary_;
};
} // namespace

std::vector<SavedToolOutput> MapPanel::saveToolOutputs(const std::vector<int>& ids) const {
  const auto wanted = [&ids](const Job* j) { return ids.empty() || std::ranges::count(ids, j->id()) > 0; };
  const auto sofar = [](const Job* j, std::size_t points) {
    return QString("%1 (tool #%2): %3 points so far, %4 when saved")
        .arg(QString::fromStdString(j->task().name()))
        .arg(j->id())
        .arg(points)
        .arg(j->running() ? "running" : "stopped");
  };
  std::vector<SavedToolOutput> out;
  for (const auto& s : searches_) {
    if (!wanted(s.job)) continue;
    SavedToolOutput o{s.job->task().name(), {}, kSearchColour, s.x, s.y, s.foundAt, {}, false};
    o.summary = (s.reported ? s.caption : sofar(s.job, s.x.size())).toStdString();
    if (s.reported && s.caption.isEmpty()) o.summary = "fixed point: " + s.job->error();
    if (!s.multipliers.empty()) o.multipliers.emplace_back(0.0, s.multipliers);
    out.push_back(std::move(o));
  }
  for (const auto& t : tools_) {
    if (!wanted(t.job)) continue;
    const bool ended = t.job->status() == Job::Status::Finished && t.ended;
    out.push_back({t.job->task().name(),
                   (ended ? t.ended(t) : sofar(t.job, t.x.size())).toStdString(),
                   t.colour,
                   t.x,
                   t.y,
                   {},
                   t.multipliers,
                   t.everyStep});
  }
  return out;
}

void MapPanel::restoreToolOutputs(const std::vector<SavedToolOutput>& saved) {
  for (const auto& o : saved) {
    Job& job = jobs_.add(std::make_unique<RecordedTask>(o.name, o.summary));
    job.start(); // finishes at once: a record
    const QString summary = QString::fromStdString(o.summary);
    if (!o.found.empty()) { // a search that found its point: its path, its steps and the point's cross
      Search s{&job,
               nullptr,
               o.x,
               o.y,
               chart_->addCurve(o.x, o.y, o.colour, 1.5),
               chart_->addSeries(o.x, o.y, o.colour)};
      s.found = chart_->addMarkers({o.found[0]}, {o.found[1]}, o.colour);
      s.reported = true;
      if (!o.multipliers.empty()) s.multipliers = o.multipliers.front().second;
      s.caption = summary, s.foundAt = o.found;
      for (auto& w : multiplierWindows_)
        if (w && !s.multipliers.empty()) w->showFixedPoint(job.id(), s.caption, s.multipliers);
      searches_.push_back(std::move(s));
      continue;
    }
    ToolSeries t{&job, chart_->addSeries(o.x, o.y, o.colour), o.colour, o.x,
                 o.y,  [](ToolSeries&) { return false; }};
    t.everyStep = o.everyStep;
    t.ended = [summary](const ToolSeries&) { return QString(summary); };
    t.endSaid = true; // the Results log said it when it was computed
    for (const auto& [parameter, m] : o.multipliers)
      offerMultipliers(t, parameter, m);
    tools_.push_back(std::move(t));
  }
  for (auto& w : multiplierWindows_)
    if (w) w->flush();
  view_->update();
}

} // namespace rv
