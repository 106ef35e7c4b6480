// BifurcationCurveTool.cpp -- the bifurcation_curve tool: the curve of the first fold, period doubling or
// Neimark-Sacker point of the scene's continuation, followed in two parameters (dynamics/tools/
// BifurcationCurve.h). Its chart is BuiltinCharts.cpp's.
#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"
#include "dynamics/tools/ReturnMap.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/FixedPointJson.h"
#include "scenes/SceneTools.h"
#include "scenes/builtin/BuiltinTool.h"

namespace rv {

namespace {

bool startsCurve(const TypeChange& change, CurveKind kind) {
  switch (kind) {
  case CurveKind::Fold:
    return change.kind == TypeChange::Kind::Fold || change.kind == TypeChange::Kind::MultiplierPlusOne;
  case CurveKind::PeriodDoubling:
    return change.kind == TypeChange::Kind::MultiplierMinusOne;
  case CurveKind::NeimarkSacker:
    return change.kind == TypeChange::Kind::NeimarkSacker;
  }
  return false;
}

// The curve of the first fold / period doubling / Neimark-Sacker point of the scene's continuation, in the
// plane of continuation.parameter and bifurcation_curve.second_parameter.
ToolResult runBifurcationCurve(const Scene& scene, const ToolControl& control) {
  const SceneMap s(scene);
  const ContinuationSettings c = s.continuation();
  BifurcationCurveSettings cs = bifurcationCurveSettingsTable().read(scene.tool("bifurcation_curve"));
  cs.search = s.search();
  cs.first = c.parameter;
  cs.eventAccuracy = c.bifurcationAccuracy;
  const auto& doc = scene.document;
  if (doc.contains("bifurcation_curve") && doc["bifurcation_curve"].contains("second_parameter"))
    cs.second = doc["bifurcation_curve"]["second_parameter"].get<std::string>();
  if (cs.second.empty())
    throw InputError("bifurcation_curve.second_parameter: give the curve's second parameter (the first is "
                     "continuation.parameter, " +
                     c.parameter + ")");
  if (cs.second == cs.first)
    throw InputError("bifurcation_curve.second_parameter: " + cs.second +
                     " is the continued parameter already; give another");

  // the start: the first such bifurcation along the continuation
  ToolResult result;
  const auto continuation = s.continuationRun();
  std::string failure;
  try {
    if (!continuation->run(control)) {
      result.stopped = true;
      return result;
    }
  } catch (const ComputationError& e) {
    failure = e.what(); // a family that ends may still have passed the bifurcation
  }
  const TypeChange* found = nullptr;
  for (const auto& t : continuation->changes())
    if (!found && startsCurve(t, cs.kind)) found = &t;
  if (!found) {
    std::string seen;
    for (const auto& t : continuation->changes())
      seen += (seen.empty() ? "" : "; ") + describe(t, c.parameter);
    throw ComputationError(format("bifurcation_curve: the continuation in %s finds no %s point%s%s%s",
                                  c.parameter.c_str(), toString(cs.kind),
                                  seen.empty() ? "" : (" (it finds: " + seen + ")").c_str(),
                                  failure.empty() ? "" : "; it ends: ", failure.c_str()));
  }

  const RunSpec& spec = s.spec();
  const ModelAt2 modelAt = [entry = spec.model, values = spec.modelParameters, first = cs.first,
                            second = cs.second](double p, double q) {
    ParameterValues v = values;
    v.set(first, p, "bifurcation curve in " + first);
    v.set(second, q, "bifurcation curve in " + second);
    return entry->create(v);
  };
  const double q0 = spec.modelParameters[cs.second];
  BifurcationCurveResult r;
  try {
    bifurcationCurve(modelAt, s.integrators(), s.section(), found->parameter, q0, found->at.fixedPoint.point,
                     cs, control, {}, &r);
  } catch (const Stopped&) {
    result.stopped = true;
  }

  const ReturnMap map = s.map();
  result.table.names = {cs.first, cs.second};
  for (const auto& n : map.coordinateNames())
    result.table.names.push_back(n);
  for (const auto& p : r.points) {
    std::vector<double> row{p.first, p.second};
    for (double x : toVector(p.fixedPoint.point))
      row.push_back(x);
    result.table.addRow(row);
  }
  nlohmann::json events = nlohmann::json::array();
  for (const auto& e : r.events)
    events.push_back({{"what", e.what},
                      {cs.first, e.at.first},
                      {cs.second, e.at.second},
                      {"point", toVector(e.at.fixedPoint.point)},
                      {"multipliers", multipliersJson(e.at.fixedPoint.multipliers)}});
  result.fields = {{"kind", toString(cs.kind)},
                   {"parameters", {cs.first, cs.second}},
                   {"start",
                    {{cs.first, found->parameter},
                     {cs.second, q0},
                     {"point", toVector(found->at.fixedPoint.point)},
                     {"found", describe(*found, c.parameter)}}},
                   {"points", r.points.size()},
                   {"events", events},
                   {"end", r.end}};
  return result;
}

} // namespace

BuiltinTool bifurcationCurveTool() {
  return {
      .entry = {.id = "bifurcation_curve",
                .title = "Bifurcation curve",
                .parent = "continuation",
                .description =
                    "the curve of a fold, period doubling or Neimark-Sacker point of the continued family in "
                    "the plane of continuation.parameter and bifurcation_curve.second_parameter (a chart "
                    "window)",
                .section = "bifurcation_curve",
                .command = "bifurcation-curve",
                .commandHelp =
                    "continue the fixed point to its first fold, period doubling or Neimark-Sacker point and "
                    "follow that bifurcation in two parameters: the curve as CSV, where it meets others",
                .chartView = "bifurcation_curve",
                .outputs = {{"<first>, <second>", "CSV: a point of the curve in the parameter plane"},
                            {"<map coordinates>", "CSV: the fixed point there"},
                            {"kind", "the bifurcation followed"},
                            {"parameters", "the two parameters' ids"},
                            {"start", "the bifurcation the curve starts from: parameter values and point"},
                            {"points", "how many points the curve has"},
                            {"events",
                             "where the curve meets another: what, parameter values, point, multipliers"},
                            {"end", "how each way of the curve ended (the box, a closed curve, ...)"}},
                .reference =
                    "Kuznetsov, Elements of Applied Bifurcation Theory (2004) §10.3; Govaerts (2000) ch. 4",
                .computation = "dynamics/tools/BifurcationCurve.h (bifurcationCurve); runner "
                               "scenes/builtin/BifurcationCurveTool.cpp",
                .alsoSections = {"continuation"}},
      .settings =
          ToolSection{.title = "Bifurcation curve", .table = &bifurcationCurveSettingsTable().table()},
      .runner = ToolRunner{.run = runBifurcationCurve}};
}

} // namespace rv
