// MapPanelTools.cpp -- the map window's fixed-point tools (manual §2.3): a search from a click or the scene's
// guess; and every registered tool drawn on the map as its rows come (ToolWindow::MapRows: the separatrices,
// the continuation of a family and the switch to a doubled one, the bifurcation tree, a module's tool), run
// as the registry's runner (scenes/ToolTask.h), its points offered to the multipliers filters, its notes and
// outcome to the Results dock.
#include "app/gui/MapPanel.h"

#include "app/gui/MultipliersWindow.h"
#include "app/gui/QtVtkWidget.h"
#include "dynamics/core/Errors.h"
#include "dynamics/tools/ToolRegistry.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/SceneLoader.h"
#include "scenes/SceneTools.h"
#include "scenes/ToolTask.h"

#include <algorithm>
#include <cmath>

namespace rv {

void MapPanel::searchFixedPointAt(double x, double y) {
  if (!scene_ || scene_->model->info().mapCoordinates.empty()) return;
  chart_->holdRanges();
  try {
    // the fixedpoint tool's runner from the click, which stays the search's guess when it is edited
    const std::vector<SceneOverride> guess{{"fixedpoint.guess", nlohmann::json(mapPoint(x, y)).dump()}};
    const nlohmann::json document = toolDocument();
    const SceneMap sm(sceneFromJson(document, scene_->source, guess)); // bad settings: said now
    auto task = std::make_unique<ToolTask>("fixedpoint", std::vector<nlohmann::json>{document},
                                           scene_->source, false, guess);
    ToolTask* raw = task.get();
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

void MapPanel::startTool(std::unique_ptr<Task> task, const Rgb& colour, std::function<bool(ToolSeries&)> pull,
                         std::function<QString(const ToolSeries&)> ended) {
  Job& job = jobs_.add(std::move(task));
  tools_.push_back({&job, chart_->addSeries({}, {}, colour), colour, {}, {}, std::move(pull)});
  tools_.back().ended = std::move(ended);
  job.start();
}

void MapPanel::offerMultipliers(ToolSeries& t, double parameter, const std::vector<std::complex<double>>& m) {
  t.multipliers.emplace_back(parameter, m);
  filters_.offer(t.job->id(), parameter, m, t.everyStep);
}

void MapPanel::addMultipliersWindow(MultipliersWindow* window) {
  filters_.addMultipliers(window);
  for (const auto& t : tools_)
    for (const auto& [parameter, m] : t.multipliers)
      window->offer(t.job->id(), parameter, m, t.everyStep);
  for (const auto& s : searches_)
    if (!s.multipliers.empty()) window->showFixedPoint(s.job->id(), s.caption, s.multipliers);
  window->flush();
}

void MapPanel::startSeparatrices() {
  // a job per branch, the outgoing pair in one colour and the incoming in another
  const Rgb colours[] = {{0.55, 0.1, 0.6}, {0.55, 0.1, 0.6}, {0.1, 0.5, 0.2}, {0.1, 0.5, 0.2}};
  for (int b = 1; b <= 4; ++b)
    startMapRows("separatrix", {{"separatrix.branches", "[" + std::to_string(b) + "]"}},
                 b == 1 ? "growing the separatrices of the fixed point near the scene's guess" : "",
                 colours[b - 1]);
}

void MapPanel::startContinuation() {
  // the fixed point found last (a Shift+click's, or the guess's search) is the one the user means; the
  // scene's guess only when none was found
  const auto found =
      std::find_if(searches_.rbegin(), searches_.rend(), [](const Search& s) { return !s.foundAt.empty(); });
  if (found != searches_.rend())
    continueFixedPoint(found->job->id());
  else
    startMapRows("continuation", {}, "continuing the fixed point near the scene's guess (none found yet)");
}

bool MapPanel::continueFixedPoint(int id) {
  const auto s =
      std::find_if(searches_.begin(), searches_.end(), [id](const Search& s) { return s.job->id() == id; });
  if (s == searches_.end() || s->foundAt.empty()) {
    emit message(QString("tool #%1 found no fixed point to continue").arg(id));
    return false;
  }
  const std::vector<double> point = mapPoint(s->foundAt[0], s->foundAt[1]);
  startMapRows("continuation", {{"fixedpoint.guess", nlohmann::json(point).dump()}},
               QString("continuing the fixed point tool #%1 found, (%2, %3)")
                   .arg(id)
                   .arg(s->foundAt[0], 0, 'g', 10)
                   .arg(s->foundAt[1], 0, 'g', 10));
  return true;
}

int MapPanel::fixedPointAt(const QPoint& at) const {
  const double dpr = view_->devicePixelRatioF();
  const double ax = at.x() * dpr, ay = (view_->height() - at.y()) * dpr, near = 8 * dpr;
  int best = -1;
  double closest = near;
  for (const auto& s : searches_) {
    double px, py;
    if (s.foundAt.empty() || !chart_->toPixels(s.foundAt[0], s.foundAt[1], px, py)) continue;
    if (const double d = std::hypot(px - ax, py - ay); d <= closest) closest = d, best = s.job->id();
  }
  return best;
}

void MapPanel::startBifurcationTree() {
  startMapRows("bifurcation_tree", {}, "growing the bifurcation tree of the scene's fixed point");
}

void MapPanel::followDoubledFamily(int k) {
  if (k < 1 || k > static_cast<int>(doublings_.size())) {
    emit message(
        doublings_.empty()
            ? "no period doubling located: continue the fixed point first (Tools > Continue the fixed "
              "point)"
            : QString("there are %1 located period doublings, not %2").arg(doublings_.size()).arg(k));
    return;
  }
  startMapRows("continuation", {{"continuation.switch", std::to_string(k)}},
               "following the family of doubled order born at the " + doublings_[k - 1]);
}

std::vector<std::pair<double, double>> MapPanel::toolPoints(int id) const {
  std::vector<std::pair<double, double>> out;
  for (const auto& t : tools_)
    if (t.job->id() == id)
      for (std::size_t i = 0; i < t.x.size(); ++i)
        out.emplace_back(t.x[i], t.y[i]);
  return out;
}

namespace {
// where a streamed row's columns are: the map point's, the continued parameter's, the multipliers' (re1,
// im1, ...) and the type's; -1 where the row has none
struct RowColumns {
  int x = -1, y = -1, parameter = -1, type = -1;
  std::vector<std::pair<int, int>> multipliers;
  RowColumns(const StreamedRow& row, const std::vector<std::string>& coordinates,
             const std::string& parameter) {
    const auto at = [&row](const std::string& name) {
      const auto it = std::find(row.names.begin(), row.names.end(), name);
      return it == row.names.end() ? -1 : static_cast<int>(it - row.names.begin());
    };
    if (coordinates.size() >= 2) x = at(coordinates[0]), y = at(coordinates[1]);
    if (!parameter.empty()) this->parameter = at(parameter);
    for (int i = 1;; ++i) {
      const int re = at("re" + std::to_string(i)), im = at("im" + std::to_string(i));
      if (re < 0 || im < 0) break;
      multipliers.emplace_back(re, im);
    }
    const auto t = std::find(row.textNames.begin(), row.textNames.end(), "type");
    if (t != row.textNames.end()) type = static_cast<int>(t - row.textNames.begin());
  }
};

const Rgb kToolColours[] = {
    {0.95, 0.55, 0.1}, {0.6, 0.2, 0.5}, {0.1, 0.5, 0.2}, {0.55, 0.1, 0.6}, {0.2, 0.4, 0.8}};
} // namespace

bool MapPanel::drainSearches() {
  bool changed = false;
  const std::vector<std::string>& coordinates =
      scene_ ? scene_->model->info().mapCoordinates : std::vector<std::string>{};
  std::vector<ToolTask::RunRow> steps;
  for (auto& s : searches_) {
    if (s.task && s.task->rows().take(steps) > 0) {
      for (const auto& [run, row] : steps) {
        if (run < s.run) continue;                              // a late step of an earlier run
        if (run > s.run) s.run = run, s.x.clear(), s.y.clear(); // searching again from the guess
        const RowColumns c(row, coordinates, "");
        if (c.x >= 0 && c.y >= 0)
          s.x.push_back(row.values[static_cast<std::size_t>(c.x)]),
              s.y.push_back(row.values[static_cast<std::size_t>(c.y)]);
      }
      if (s.path >= 0 && s.x.size() >= 2) chart_->setSeries(s.path, s.x, s.y); // a line needs two points
      chart_->setSeries(s.point, s.x, s.y);
      changed = true;
    }
    // (a record has nothing more to say; a stopped search says it when it ends)
    if (s.reported || !s.task ||
        (s.job->status() != Job::Status::Finished && s.job->status() != Job::Status::Failed))
      continue;
    s.reported = true;
    const auto r = s.task->result();
    if (r && r->fields.contains("point")) {
      const auto at = r->fields["point"].get<std::vector<double>>();
      std::vector<std::complex<double>> multipliers;
      for (const auto& z : r->fields["multipliers"])
        multipliers.emplace_back(z[0].get<double>(), z[1].get<double>());
      QString m = QString("fixed point (");
      for (std::size_t i = 0; i < at.size(); ++i)
        m += QString(i ? ", %1" : "%1").arg(at[i], 0, 'g', 12);
      m += QString("): %1; multipliers").arg(QString::fromStdString(r->fields["type"].get<std::string>()));
      for (auto z : multipliers)
        m += QString(" %1%2%3i")
                 .arg(z.real(), 0, 'g', 6)
                 .arg(z.imag() < 0 ? "" : "+")
                 .arg(z.imag(), 0, 'g', 6);
      emit message(m);
      if (at.size() >= 2) {
        s.foundAt = {at[0], at[1]};
        chart_->setSeries(s.found, {at[0]}, {at[1]});
      }
      s.multipliers = multipliers; // shown in every multipliers filter, also in one opened later
      s.caption = m;
      filters_.showFixedPoint(s.job->id(), m, s.multipliers);
    } else if (s.job->status() == Job::Status::Failed) {
      emit message(QString::fromStdString("fixed point: " + s.job->error()));
    }
  }
  return changed;
}

void MapPanel::startRows(const std::string& id) {
  const ToolEntry* entry = ToolRegistry::global().find(id);
  startMapRows(id, {}, entry ? QString::fromStdString(entry->title) + " on the map" : QString());
}

void MapPanel::startMapRows(const std::string& id, const std::vector<SceneOverride>& overrides,
                            const QString& said, std::optional<Rgb> colour) {
  if (!scene_ || scene_->model->info().mapCoordinates.empty()) {
    emit message("this problem has no map coordinates");
    return;
  }
  const ToolRunner* runner = findToolRunner(id);
  if (!runner) return;
  try {
    const nlohmann::json document = toolDocument();
    const Scene scene = sceneFromJson(document, scene_->source, overrides);
    auto task = std::make_unique<ToolTask>(id, std::vector<nlohmann::json>{document}, scene_->source, false,
                                           overrides);
    ToolTask* raw = task.get();
    const std::vector<std::string> coordinates = scene.model->info().mapCoordinates;
    const std::string parameter = scene.continuationParameter;
    const bool eachElliptic = runner->ellipticMultipliersEachRow;
    const bool doubled = scene.tool("continuation").get("switch") != 0;
    startTool(
        std::move(task), colour.value_or(kToolColours[tools_.size() % std::size(kToolColours)]),
        [this, raw, coordinates, parameter, eachElliptic, doubled, seen = 0,
         located = false](ToolSeries& t) mutable {
          t.everyStep = eachElliptic;
          bool drew = false;
          std::vector<ToolTask::RunRow> rows;
          raw->rows().take(rows);
          for (const auto& item : rows) {
            const int run = item.run;
            const StreamedRow& row = item.row; // (a name a lambda may capture, unlike a structured binding)
            if (run < seen) continue;          // a late row of an earlier run
            if (run > seen) { // a run from the start (after a stop, an edit): what the earlier drew goes
              seen = run;
              located = false;
              t.x.clear(), t.y.clear(), t.along.clear(), t.multipliers.clear();
              filters_.forget(t.job->id());
              drew = true;
            }
            const RowColumns c(row, coordinates, parameter);
            const auto value = [&row](int i) { return row.values[static_cast<std::size_t>(i)]; };
            if (c.x < 0 || c.y < 0) continue;
            t.x.push_back(value(c.x)), t.y.push_back(value(c.y));
            if (c.parameter < 0) continue;
            t.along.push_back(value(c.parameter));
            if (c.multipliers.empty()) continue;
            const bool elliptic = c.type >= 0 && row.text[static_cast<std::size_t>(c.type)] ==
                                                     toString(FixedPointType::Elliptic);
            if (eachElliptic && !elliptic) continue; // manual §2.4.3: only a tree's elliptic branches
            std::vector<std::complex<double>> m;
            for (const auto& [re, im] : c.multipliers)
              m.emplace_back(value(re), value(im));
            offerMultipliers(t, value(c.parameter), m);
          }
          std::vector<std::string> notes;
          raw->notes().take(notes);
          for (const auto& n : notes)
            emit message(QString::fromStdString(n));
          // once it has ended, the period doublings a family followed from the scene's point located: where
          // Follow the doubled family can switch
          const auto result = located || doubled ? std::nullopt : raw->result();
          located = located || result.has_value(); // (read once: a result is copied whole)
          if (result && result->fields.contains("changes") && !result->fields.contains("doubled")) {
            doublings_.clear();
            for (const auto& c : result->fields["changes"])
              if (c.value("kind", "") == toString(TypeChange::Kind::MultiplierMinusOne))
                doublings_.push_back(QString("period doubling at %1 = %2")
                                         .arg(QString::fromStdString(parameter))
                                         .arg(c["parameter"].get<double>(), 0, 'g', 12));
          }
          return drew || !rows.empty();
        },
        [raw, parameter](const ToolSeries& t) {
          const auto result = raw->result();
          QString said = QString("%1 (tool #%2) ended: %3 points")
                             .arg(QString::fromStdString(raw->tool().title))
                             .arg(t.job->id())
                             .arg(t.x.size());
          if (!t.along.empty())
            said += QString(", %1 from %2 to %3")
                        .arg(QString::fromStdString(parameter))
                        .arg(t.along.front(), 0, 'g', 10)
                        .arg(t.along.back(), 0, 'g', 10);
          if (result && !result->failure.empty()) said += "; " + QString::fromStdString(result->failure);
          return said;
        });
    if (!said.isEmpty()) emit message(said);
  } catch (const InputError& e) {
    emit message(QString::fromStdString(e.what()));
  }
}

void MapPanel::searchFromGuess() {
  if (!scene_) return;
  std::vector<double> guess; // the Fixed point tab's, as shown
  try {
    guess = sceneFromJson(toolDocument(), scene_->source).guess;
  } catch (const InputError& e) {
    emit message(QString::fromStdString(e.what()));
    return;
  }
  if (guess.size() < 2) {
    emit message("the scene has no fixedpoint.guess (set it in the Fixed point tab, or Shift+click the map)");
    return;
  }
  searchFixedPointAt(guess[0], guess[1]);
}

int MapPanel::fixedPointsFound() const {
  int n = 0;
  for (const auto& s : searches_)
    n += !s.foundAt.empty();
  return n;
}

namespace {
/// A tool's output as a session or Undo kept it: drawn already, nothing to compute; its job ends as the
/// tool's did (a failure with its outcome in words as the reason).
class RecordedTask final : public Task {
public:
  RecordedTask(std::string name, std::string summary, SavedToolOutput::Outcome outcome)
      : name_(std::move(name)), summary_(std::move(summary)), outcome_(outcome) {}
  std::string name() const override { return name_; }
  std::string describe() const override { return "restored from a saved record: " + summary_; }
  bool run(const ToolControl&) override {
    if (outcome_ == SavedToolOutput::Outcome::Failed) throw ComputationError(summary_);
    return outcome_ == SavedToolOutput::Outcome::Finished;
  }
  void reset() override {}
  bool isRecord() const override { return true; }

private:
  std::string name_, summary_;
  SavedToolOutput::Outcome outcome_;
};

/// How a tool's job ended, as a record keeps it (one running is kept as stopped).
SavedToolOutput::Outcome outcomeOf(const Job& j) {
  switch (j.status()) {
  case Job::Status::Finished:
    return SavedToolOutput::Outcome::Finished;
  case Job::Status::Failed:
    return SavedToolOutput::Outcome::Failed;
  default:
    return SavedToolOutput::Outcome::Stopped;
  }
}
} // namespace

std::vector<SavedToolOutput> MapPanel::saveToolOutputs(const std::vector<int>& ids) const {
  const auto wanted = [&ids](const Job* j) { return ids.empty() || std::ranges::count(ids, j->id()) > 0; };
  const auto sofar = [](const Job* j, std::size_t points) {
    const QString name = QString::fromStdString(j->task().name());
    if (j->status() == Job::Status::Failed) // (a record's reason is its outcome in words already)
      return j->task().isRecord() ? QString::fromStdString(j->error())
                                  : QString("%1 (tool #%2) failed: %3")
                                        .arg(name)
                                        .arg(j->id())
                                        .arg(QString::fromStdString(j->error()));
    return QString("%1 (tool #%2): %3 points so far, %4 when saved")
        .arg(name)
        .arg(j->id())
        .arg(points)
        .arg(j->running() ? "running" : "stopped");
  };
  std::vector<SavedToolOutput> out;
  for (const auto& s : searches_) {
    if (!wanted(s.job)) continue;
    SavedToolOutput o{s.job->task().name(), {},         kSearchColour, s.x, s.y, s.foundAt, {}, false,
                      outcomeOf(*s.job),    s.job->id()};
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
                   t.everyStep,
                   outcomeOf(*t.job),
                   t.job->id()});
  }
  return out;
}

void MapPanel::restoreToolOutputs(const std::vector<SavedToolOutput>& saved) {
  for (const auto& o : saved) {
    Job& job = jobs_.add(std::make_unique<RecordedTask>(o.name, o.summary, o.outcome), nullptr, o.id);
    job.start(); // ends at once as the tool did: a record
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
      if (!s.multipliers.empty()) filters_.showFixedPoint(job.id(), s.caption, s.multipliers);
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
  filters_.flush();
  view_->update();
}

} // namespace rv
