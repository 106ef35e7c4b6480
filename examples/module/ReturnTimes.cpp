#include "ReturnTimes.h"

#include "dynamics/core/Errors.h"
#include "scenes/SceneTools.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace rossler {

rv::ToolEntry returnTimesEntry() {
  return {.id = "return_times",
          .title = "Return times",
          .parent = "poincare",
          .description = "statistics of the times between successive crossings of the Poincare section, "
                         "and their histogram (a chart window)",
          .section = "return_times",
          .command = "return-times",
          .commandHelp = "statistics of the return times to the scene's Poincare section (JSON fields; CSV: "
                         "a histogram)",
          .chartView = "return_times",
          .outputs = {{"mean", "the mean return time", true},
                      {"std", "their standard deviation", true},
                      {"min", "the shortest return time"},
                      {"max", "the longest return time"},
                      {"count", "how many return times (return_times.points)"},
                      {"time", "CSV: the centre of a histogram bin"},
                      {"frequency", "CSV: how many return times fall in the bin"}},
          .reference = "H. Poincare, Les methodes nouvelles de la mecanique celeste I (1892); manual §2.3.1",
          .computation = "examples/module/ReturnTimes.cpp"};
}

const rv::ParameterTable& returnTimesTable() {
  static const rv::ParameterTable table{
      {.id = "points",
       .label = "Return times",
       .defaultValue = 1000,
       .min = 1,
       .max = 1e8,
       .description = "how many return times (one more crossing of the section)",
       .integer = true},
      {.id = "bins",
       .label = "Histogram bins",
       .defaultValue = 20,
       .min = 1,
       .max = 10000,
       .description = "the bins of the histogram between the least and the largest return time",
       .integer = true},
  };
  return table;
}

rv::ToolRunner returnTimesRunner() {
  return {[](const rv::Scene& scene, const rv::ToolControl& control) {
    const auto& settings = scene.tool("return_times");
    const long points = static_cast<long>(settings["points"]);
    const int bins = static_cast<int>(settings["bins"]);
    const auto map = rv::scenePoincareMap(scene, points + 1);
    std::vector<double> times;
    double last = 0;
    bool first = true;
    while (auto p = map->next(control)) {
      if (!first) times.push_back(p->time - last);
      first = false;
      last = p->time;
      control.progress(static_cast<double>(times.size()) / static_cast<double>(points));
    }
    rv::ToolResult r;
    r.stopped = control.stopRequested();
    if (times.empty()) {
      if (r.stopped) return r;
      throw rv::ComputationError(
          "return_times: fewer than two crossings of the section " +
          (scene.poincare.observable.empty() ? std::string("(default)") : scene.poincare.observable) + " (" +
          std::to_string(times.size()) + " return times)");
    }
    if (!r.stopped && static_cast<long>(times.size()) < points)
      throw rv::ComputationError("return_times: the map ended after " + std::to_string(times.size()) +
                                 " return times of " + std::to_string(points) + " (poincare.time?)");
    double sum = 0;
    for (double t : times)
      sum += t;
    const double n = static_cast<double>(times.size()), mean = sum / n;
    double squares = 0;
    for (double t : times)
      squares += (t - mean) * (t - mean);
    const auto [lo, hi] = std::minmax_element(times.begin(), times.end());
    r.fields = {{"mean", mean},
                {"std", std::sqrt(squares / n)},
                {"min", *lo},
                {"max", *hi},
                {"count", static_cast<long>(times.size())}};
    // the histogram: equal bins over [min, max] (one bin when every return time is the same)
    const double width = *hi > *lo ? (*hi - *lo) / bins : 1.0;
    std::vector<double> count(static_cast<std::size_t>(bins), 0.0);
    for (double t : times)
      count[static_cast<std::size_t>(std::min(bins - 1, static_cast<int>((t - *lo) / width)))] += 1;
    r.table.names = {"time", "frequency"};
    for (int k = 0; k < bins; ++k)
      r.table.addRow({*lo + (k + 0.5) * width, count[static_cast<std::size_t>(k)]});
    return r;
  }};
}

} // namespace rossler
