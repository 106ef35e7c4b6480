#include "scenes/SceneTools.h"

#include "dynamics/core/Errors.h"
#include "dynamics/jobs/PoincareTask.h"
#include "scenes/SceneLoader.h"

#include <cmath>

namespace rv {

SceneMap::SceneMap(Scene scene, const MapToolOverrides& o, bool needGuess)
    : scene_(std::move(scene)), run_(scene_.runSpec()), overrides_(o) {
  ParameterValues fp = scene_.tool("fixedpoint");
  if (o.order < 0) throw InputError("--order: must be at least 1");
  if (o.order > 0) fp.set("order", o.order, "--order");
  if (!o.method.empty()) fp.setChoice("method", o.method, "--method");
  search_ = fixedPointSettingsTable().read(fp);
  section_ = scene_.poincare;
  section_.order = static_cast<int>(fp["order"]);
  const ReturnMap probe = map(); // validates the map (coordinates, section)
  std::vector<double> g = o.guess;
  if (g.empty()) g = scene_.guess;
  const auto& doc = scene_.document;
  if (g.empty() && doc.contains("initial") && doc["initial"].contains("map"))
    g = doc["initial"]["map"].get<std::vector<double>>();
  if (needGuess && g.empty()) throw InputError("--guess: give the starting point x,y[,z]");
  if (needGuess && static_cast<int>(g.size()) != probe.dimension()) {
    std::string names;
    for (const auto& n : probe.coordinateNames())
      names += (names.empty() ? "" : ", ") + n;
    throw InputError("--guess: the map of " + scene_.model->info().id + " has " +
                     std::to_string(probe.dimension()) + " coordinates (" + names + "), the guess has " +
                     std::to_string(g.size()));
  }
  guess_ = Eigen::Map<const Eigen::VectorXd>(g.data(), static_cast<Eigen::Index>(g.size()));
}

IntegratorFactory SceneMap::integrators() const {
  const Model* m = scene_.model.get();
  const RunSpec* spec = &run_;
  return [spec, m] { return spec->makeIntegrator(*m); };
}

ReturnMap SceneMap::map() const {
  return ReturnMap(*scene_.model, integrators(), section_);
}

ContinuationSettings SceneMap::continuation() const {
  ParameterValues cv = scene_.tool("continuation");
  if (overrides_.step) cv.set("step", *overrides_.step, "--step");
  ContinuationSettings c;
  c.search = search_;
  c = continuationSettingsTable().read(cv, c);
  c.parameter = overrides_.parameter.empty() ? scene_.continuationParameter : overrides_.parameter;
  if (c.parameter.empty()) throw InputError("--param: give the parameter to continue in");
  if (scene_.model->info().parameters.find(c.parameter) < 0)
    throw InputError("--param " + c.parameter + ": not a parameter of " + scene_.model->info().id);
  if (overrides_.to)
    c.to = *overrides_.to;
  else if (scene_.continuationTo)
    c.to = *scene_.continuationTo;
  else
    throw InputError("--to: give the finite value of " + c.parameter);
  return c;
}

std::unique_ptr<Continuation> SceneMap::continuationRun() const {
  const ContinuationSettings c = continuation();
  return std::make_unique<Continuation>(run_.modelAt(c.parameter), integrators(), section_,
                                        run_.modelParameters[c.parameter], guess_, c);
}

std::unique_ptr<PoincareMap> scenePoincareMap(const Scene& scene, long points) {
  SectionSettings s = scene.poincare;
  if (points > 0) s.maxPoints = points;
  auto integ = scene.runSpec().makeIntegrator(*scene.model);
  integ->start(*scene.model, 0, scene.initialState, s.backward ? -1 : +1);
  return std::make_unique<PoincareMap>(*scene.model, std::move(integ), s);
}

std::vector<std::vector<std::complex<double>>> multiplierPath(const SceneMap& s, const ToolControl& control) {
  std::vector<std::vector<std::complex<double>>> steps;
  if (s.scene().continuationParameter.empty() || !s.scene().continuationTo) {
    steps.push_back(findFixedPoint(s.map(), s.guess(), s.search(), control).multipliers);
    return steps;
  }
  const auto cont = s.continuationRun();
  try {
    cont->run(control);
  } catch (const ComputationError&) {
    if (cont->points().empty()) throw; // else draw the family as far as it goes
  }
  for (const auto& p : cont->points())
    steps.push_back(p.fixedPoint.multipliers);
  return steps;
}

namespace {
// an edited scene as the tools read it
class SceneEdit final : public TaskEdit {
public:
  explicit SceneEdit(const Scene& scene) : scene_(scene) {}
  RunSpec run() const override { return scene_.runSpec(); }
  SectionSettings section() const override { return scene_.poincare; }
  std::string document() const override { return scene_.document.dump(); }

private:
  const Scene& scene_;
};
} // namespace

bool editTask(Task& task, const Scene& edited) {
  return task.edit(SceneEdit(edited));
}

} // namespace rv
