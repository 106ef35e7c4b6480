// MapTrajectories.cpp -- the map window's trajectories: their jobs, points, colours, ranges and MEGNO, saved
// and restored.
#include "app/gui/MapTrajectories.h"

#include "app/gui/MapFilters.h"
#include "app/gui/PlotWindow.h"
#include "dynamics/core/Errors.h"
#include "dynamics/jobs/MegnoTask.h"
#include "dynamics/jobs/PoincareTask.h"
#include "render/charts/PoincareChart.h"

#include <QColor>
#include <algorithm>
#include <cmath>
#include <limits>

namespace rv {

namespace {
std::map<std::string, double> valuesMap(const ParameterValues& v) {
  std::map<std::string, double> m;
  for (const auto& spec : v.table().specs())
    m[spec.id] = v[spec.id];
  return m;
}
void setValues(ParameterValues& v, const std::map<std::string, double>& m, const std::string& what) {
  for (const auto& [id, value] : m)
    v.set(id, value, what + "." + id);
}
} // namespace

MapTrajectories::MapTrajectories(JobTree& jobs, MapFilters& filters, std::function<void(const QString&)> say,
                                 std::function<void()> redraw)
    : jobs_(jobs), filters_(filters), say_(std::move(say)), redraw_(std::move(redraw)) {}

MapTrajectories::~MapTrajectories() = default;

void MapTrajectories::clear() {
  series_.clear();
}

const MapTrajectories::Series* MapTrajectories::find(int id) const {
  for (const auto& s : series_)
    if (s.job->id() == id) return &s;
  return nullptr;
}

MapTrajectories::Series* MapTrajectories::find(int id) {
  return const_cast<Series*>(std::as_const(*this).find(id));
}

MapTrajectories::Series& MapTrajectories::add(Job& job, PoincareTask* task, const Rgb& colour) {
  const int plot = chart_->addSeries({}, {}, colour);
  series_.push_back({&job, task, {}, {}, {}, plot, colour});
  Series& s = series_.back();
  s.since.start();
  for (PlotWindow* p : filters_.plots())
    s.task->taps().add(p->follow(s.job->id(), s.colour));
  if (colourByMegno_) startMegno(s);
  return s;
}

Job& MapTrajectories::start(const Eigen::VectorXd& state, const QString& origin) {
  RunSpec spec = scene_->runSpec();
  spec.initialState = state;
  auto task = std::make_unique<PoincareTask>(spec, scene_->poincare);
  PoincareTask* raw = task.get();
  Job& job = jobs_.add(std::move(task));
  Series& s = add(job, raw, seriesColour(static_cast<int>(series_.size())));
  s.origin = origin;
  chart_->select(s.plot);
  job.start();
  return job;
}

std::size_t MapTrajectories::takePoints(Series& s, std::size_t most) {
  if (s.pendingAt >= s.pending.size()) {
    s.task->points().take(s.pending);
    s.pendingAt = 0;
  }
  const std::size_t end = s.pendingAt + std::min(most, s.pending.size() - s.pendingAt);
  for (std::size_t k = s.pendingAt; k < end; ++k) {
    MapPoint& p = s.pending[k];
    s.x.push_back(p.coordinates.at(0));
    s.y.push_back(p.coordinates.size() > 1 ? p.coordinates[1] : p.time);
    if (p.coordinates.size() > 2) s.z.push_back(p.coordinates[2]);
    // freed now, a few thousand a turn, not all at once when the next batch replaces this one (10^5 frees
    // in one turn of the event loop)
    std::vector<double>().swap(p.coordinates);
  }
  const std::size_t taken = end - s.pendingAt;
  s.pendingAt = end;
  return taken;
}

std::vector<SavedTrajectory> MapTrajectories::save(const std::vector<int>& ids, bool onlyRunning, bool goOn) {
  std::vector<SavedTrajectory> out;
  for (auto& s : series_) {
    const bool wanted = ids.empty() || std::find(ids.begin(), ids.end(), s.job->id()) != ids.end();
    const bool running = s.job->running();
    if (!wanted || (onlyRunning && !running)) continue;
    s.job->stop(); // (its state is read only while it does not run)
    // what was produced before the stop, drawn or not yet, is part of what is saved
    while (takePoints(s, std::numeric_limits<std::size_t>::max()) > 0) {
    }
    Snapshot state;
    s.task->save(state);
    const RunSpec& spec = s.task->spec();
    SavedTrajectory t;
    t.start.assign(spec.initialState.data(), spec.initialState.data() + spec.initialState.size());
    t.parameters = valuesMap(spec.modelParameters);
    t.integrator = valuesMap(spec.integratorParameters);
    t.colour = s.colour;
    t.x = s.x, t.y = s.y, t.z = s.z;
    t.state = std::move(state.values);
    t.running = running;
    t.first = s.first, t.last = s.last;
    t.origin = s.origin.toStdString();
    t.id = s.job->id();
    out.push_back(std::move(t));
    if (goOn && running) s.job->start();
  }
  return out;
}

int MapTrajectories::restore(const std::vector<SavedTrajectory>& saved) {
  if (!scene_) return 0;
  // checked whole first: a list that does not fit the scene adds nothing
  std::vector<std::unique_ptr<PoincareTask>> tasks;
  for (std::size_t n = 0; n < saved.size(); ++n) {
    const SavedTrajectory& t = saved[n];
    const std::string what = "saved trajectory " + std::to_string(n + 1);
    RunSpec spec = scene_->runSpec();
    if (static_cast<Eigen::Index>(t.start.size()) != spec.initialState.size())
      throw InputError(what + ": made for another problem");
    spec.initialState =
        Eigen::Map<const Eigen::VectorXd>(t.start.data(), static_cast<Eigen::Index>(t.start.size()));
    setValues(spec.modelParameters, t.parameters, what + ".parameters");
    setValues(spec.integratorParameters, t.integrator, what + ".integrator");
    auto task = std::make_unique<PoincareTask>(spec, scene_->poincare);
    Snapshot state{t.state, 0};
    task->restore(state);
    tasks.push_back(std::move(task));
  }
  for (std::size_t n = 0; n < saved.size(); ++n) {
    const SavedTrajectory& t = saved[n];
    PoincareTask* raw = tasks[n].get();
    Job& job = jobs_.add(std::move(tasks[n]), nullptr, t.id); // its number, where it is free
    Series& s = add(job, raw, t.colour);
    s.x = t.x, s.y = t.y, s.z = t.z;
    s.first = t.first, s.last = t.last;
    s.origin = QString::fromStdString(t.origin);
    drawSeries(s);
    // a finished one finishes again at once (its limit is reached); one the user had stopped stays so
    if (t.running || (raw->limit() > 0 && raw->produced() >= raw->limit())) job.start();
  }
  return static_cast<int>(saved.size());
}

bool MapTrajectories::morePoints(int id, long more) {
  Series* s = find(id);
  if (!s || s->job->running() || s->task->limit() <= 0) return false;
  s->job->edit([more](Task& t) { static_cast<PoincareTask&>(t).extend(more); });
  s->job->start();
  return true;
}

bool MapTrajectories::takeMegnoValues() {
  bool changed = false;
  for (auto& s : series_) {
    if (!s.megnoJob || s.megnoValue || s.megnoJob->running()) continue;
    if (s.megnoJob->status() == Job::Status::Finished) {
      const auto& last = s.megno->result().last;
      s.megnoValue = last.megno;
      applyColour(s);
      changed = true;
      // <Y> near 2 is a torus; on a chaotic orbit it grows like lambda t / 2 (the rate tends to lambda)
      say_(QString("MEGNO (tool #%1) of trajectory #%2: <Y> = %3 at t = %4, rate %5")
               .arg(s.megnoJob->id())
               .arg(s.job->id())
               .arg(last.megno, 0, 'g', 6)
               .arg(last.time, 0, 'g', 6)
               .arg(last.megnoRate, 0, 'g', 4));
    } else if (s.megnoJob->status() == Job::Status::Failed) {
      // drawn in its own colour; why it failed is said once, by the tool manager (as every job's failure)
      s.megnoValue = std::numeric_limits<double>::quiet_NaN();
    }
  }
  return changed;
}

bool MapTrajectories::drain() {
  bool changed = takeMegnoValues();
  // the points a few milliseconds allow in this turn of the event loop (the map's frame comes after them in
  // the same turn), at most kDrainPerTick a series
  QElapsedTimer spent;
  spent.start();
  for (auto& s : series_) {
    std::size_t taken = 0;
    while (taken < kDrainPerTick && (taken == 0 || spent.elapsed() < kDrainMilliseconds)) {
      const std::size_t got = takePoints(s, std::min<std::size_t>(kDrainPerTick - taken, 4096));
      if (got == 0) break;
      taken += got;
    }
    if (taken == 0) {
      if (s.x.empty() && !s.noCrossingSaid && s.job->running() && !scene_->model->isMap() &&
          s.since.elapsed() > kNoCrossingMilliseconds) {
        s.noCrossingSaid = true; // once: e.g. the Chaplygin sleigh's spin dies out and never changes sign
        const SectionSettings& section = s.task->settings();
        say_(QString("trajectory #%1 has not crossed the section %2 = %3 yet: its orbit may never reach "
                     "it (the Poincaré map tab chooses another section)")
                 .arg(s.job->id())
                 .arg(QString::fromStdString(section.observable.empty() ? scene_->model->info().section
                                                                        : section.observable))
                 .arg(section.value));
      }
      continue;
    }
    drawSeries(s);
    changed = true;
  }
  return changed;
}

void MapTrajectories::remove(const std::function<bool(const Job*)>& isGone) {
  for (auto& s : series_)
    if (s.megnoJob && isGone(s.megnoJob) && !isGone(s.job)) { // its MEGNO alone: back to its own colour
      s.megnoJob = nullptr, s.megno = nullptr, s.megnoValue.reset();
      chart_->setColour(s.plot, s.colour);
    }
  for (auto it = series_.begin(); it != series_.end();)
    if (isGone(it->job)) {
      chart_->setSeries(it->plot, {}, {});
      for (PlotWindow* p : filters_.plots())
        p->unfollow(it->job->id());
      it = series_.erase(it);
    } else {
      ++it;
    }
}

void MapTrajectories::clearOutput(int id) {
  if (Series* s = find(id)) {
    s->x.clear(), s->y.clear(), s->z.clear();
    drawSeries(*s);
    for (PlotWindow* p : filters_.plots())
      p->clear(id);
  }
}

long MapTrajectories::points() const {
  long n = 0;
  for (const auto& s : series_)
    n += static_cast<long>(s.x.size());
  return n;
}

std::pair<std::vector<double>, std::vector<double>> MapTrajectories::points(int id) const {
  const Series* s = find(id);
  return s ? std::pair{s->x, s->y} : std::pair<std::vector<double>, std::vector<double>>{};
}

std::pair<long, long> MapTrajectories::shownSpan(const Series& s) {
  const long n = static_cast<long>(s.x.size());
  const long a = std::clamp(s.first - 1, 0L, n), b = s.last > 0 ? std::clamp(s.last, a, n) : n;
  return {a, b};
}

void MapTrajectories::drawSeries(const Series& s) {
  if (s.first <= 1 && s.last <= 0) return chart_->setSeries(s.plot, s.x, s.y);
  const auto [a, b] = shownSpan(s);
  chart_->setSeries(s.plot, {s.x.begin() + a, s.x.begin() + b}, {s.y.begin() + a, s.y.begin() + b});
}

QString MapTrajectories::origin(int id) const {
  const Series* s = find(id);
  if (!s) return {};
  if (!s->origin.isEmpty() || s->x.empty()) return s->origin;
  return QString("(%1, %2)").arg(s->x[0], 0, 'g', 6).arg(s->y[0], 0, 'g', 6);
}

bool MapTrajectories::setColour(int id, const Rgb& colour) {
  Series* s = find(id);
  if (!s) return false;
  s->colour = colour;
  applyColour(*s); // its own colour shows unless it is coloured by its MEGNO
  for (PlotWindow* p : filters_.plots())
    p->setColour(id, colour);
  return true;
}

bool MapTrajectories::setRange(int id, long first, long last) {
  Series* s = find(id);
  if (!s) return false;
  s->first = std::max(1L, first), s->last = last;
  drawSeries(*s);
  redraw_();
  return true;
}

long MapTrajectories::shownPoints(int id) const {
  const Series* s = find(id);
  if (!s) return 0;
  const auto [a, b] = shownSpan(*s);
  return b - a;
}

Rgb MapTrajectories::megnoColour(double megno) {
  // 2 and below blue (hue 240), 8 and above red (hue 0); NaN (a failed job) falls to blue
  const double t = std::clamp((megno - 2) / 6, 0.0, 1.0);
  const QColor c = QColor::fromHsvF(static_cast<float>(2.0 / 3.0 * (1 - t)), 0.85f, 0.9f);
  return {c.redF(), c.greenF(), c.blueF()};
}

void MapTrajectories::startMegno(Series& s) {
  if (s.megnoJob) return;
  auto task = std::make_unique<MegnoTask>(s.task->spec(), scene_->settings(megnoSettingsTable(), "megno"));
  s.megno = task.get();
  s.megnoJob = &jobs_.add(std::move(task), s.job);
  s.megnoJob->start();
}

void MapTrajectories::applyColour(const Series& s) {
  chart_->setColour(s.plot, shownColour(s.job->id()));
  redraw_();
}

void MapTrajectories::setColourByMegno(bool on) {
  colourByMegno_ = on;
  for (auto& s : series_) {
    if (on) startMegno(s);
    applyColour(s);
  }
}

std::optional<double> MapTrajectories::megno(int id) const {
  const Series* s = find(id);
  return s ? s->megnoValue : std::nullopt;
}

Rgb MapTrajectories::shownColour(int id) const {
  const Series* s = find(id);
  if (!s) return {0, 0, 0};
  return colourByMegno_ && s->megnoValue && !std::isnan(*s->megnoValue) ? megnoColour(*s->megnoValue)
                                                                        : s->colour;
}

std::pair<int, int> MapTrajectories::plotOf(int id) const {
  for (std::size_t k = 0; k < series_.size(); ++k)
    if (series_[k].job->id() == id) return {series_[k].plot, static_cast<int>(k)};
  return {-1, -1};
}

std::shared_ptr<PlotTap> MapTrajectories::tap(int id, const PlotSettings& settings) {
  const Series* s = find(id);
  if (!s) return nullptr;
  try {
    PlotSampler check(*scene_->model, settings); // fail here, not on the job's thread
  } catch (const InputError&) {
    return nullptr;
  }
  auto tap = std::make_shared<PlotTap>(settings);
  s->task->taps().add(tap);
  return tap;
}

void MapTrajectories::follow(PlotWindow* window) {
  for (const auto& s : series_)
    s.task->taps().add(window->follow(s.job->id(), s.colour));
}

std::vector<ChartWindow::Mark> MapTrajectories::marks(const Diagram& d) const {
  std::vector<ChartWindow::Mark> marks;
  for (const auto& s : series_) {
    const DiagramPoint p = d.place(s.task->levelState().data());
    marks.push_back({p[0], p[1], s.colour});
  }
  return marks;
}

std::vector<Map3DWindow::Track> MapTrajectories::tracks() const {
  std::vector<Map3DWindow::Track> tracks;
  tracks.reserve(series_.size());
  for (const auto& s : series_)
    tracks.push_back({&s.x, &s.y, &s.z});
  return tracks;
}

} // namespace rv
