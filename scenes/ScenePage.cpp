#include "scenes/ScenePage.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/FileNames.h"
#include "dynamics/tools/PoincareMap.h"
#include "render/video/VideoExport.h"
#include "render/view/VisualScene.h"
#include "scenes/SceneLoader.h"
#include "scenes/Session.h"

#include <algorithm>
#include <fmt/core.h>

namespace rv {

PageSpec pageSpec(const Scene& scene, const PageOverrides& given) {
  const double speed = given.speed.value_or(scene.view.speed);
  if (!(std::isfinite(speed) && speed > 0))
    throw InputError((given.speed ? given.speedName : "view.speed") + ": must be positive");
  // the video section's checks of duration and rate (its frame size is the video's own: not checked here)
  VideoOverrides video{.size = std::pair{2, 2},
                       .duration = given.duration,
                       .fps = given.fps,
                       .durationName = given.durationName,
                       .fpsName = given.fpsName};
  const VideoSpec v = videoSpec(scene.tool("video"), speed, video);
  PageSpec spec{.title = scene.document.value("title", std::string()),
                .description = scene.document.value("description", std::string()),
                .variables = scene.model->info().stateNames,
                .fps = v.fps,
                .duration = v.duration,
                .speed = speed};
  if (spec.title.empty()) spec.title = scene.model->info().title;
  const auto& values = scene.model->parameters();
  for (const auto& p : values.table().specs())
    spec.parameters.emplace_back(p.id, p.choices.empty() ? fmt::format("{:.10g}", values[p.id])
                                                         : values.choice(p.id));
  return spec;
}

PageMap sessionPageMap(const Session& s) {
  const Scene scene = sceneFromJson(s.scene, s.scenePath.empty() ? "session" : s.scenePath);
  const auto names = PoincareMap(*scene.model, scene.startIntegrator(), scene.poincare).coordinateNames();
  PageMap map{.xName = names.at(0), .yName = names.size() > 1 ? names[1] : "t"};
  using Kind = PageMapSeries::Kind;
  for (const auto& t : s.trajectories) {
    // the range the window showed (Set range): points first..last, 1-based
    const auto n = static_cast<long>(t.x.size());
    const long from = std::min(n, t.first - 1), to = std::max(from, t.last > 0 ? std::min(n, t.last) : n);
    map.series.push_back({Kind::Points,
                          {t.x.begin() + from, t.x.begin() + to},
                          {t.y.begin() + from, t.y.begin() + to},
                          t.colour});
  }
  for (const auto& t : s.tools) {
    if (t.found.empty()) { // a family, a separatrix branch, a tree: their points
      map.series.push_back({Kind::Points, t.x, t.y, t.colour});
      continue;
    }
    // a search found its point: the path it took, its steps, and a marker where it ended
    map.series.push_back({Kind::Curve, t.x, t.y, t.colour});
    map.series.push_back({Kind::Points, t.x, t.y, t.colour});
    map.series.push_back({Kind::Markers, {t.found[0]}, {t.found[1]}, t.colour});
  }
  return map;
}

long writeScenePage(const Scene& scene, const Session* session, const std::string& path,
                    const PageOverrides& given, const std::function<bool(long, long)>& progress) {
  if (!hasExtension(path, ".html") && !hasExtension(path, ".htm"))
    throw InputError(path + ": a web page is written as .html");
  PageSpec spec = pageSpec(scene, given);
  spec.path = path;
  if (session) spec.map = sessionPageMap(*session);
  auto integrator = scene.startIntegrator();
  VisualScene visual(*scene.model, scene.view, scene.initialState);
  return writeWebPage(visual, *integrator, spec, progress);
}

PageTask::PageTask(nlohmann::json document, std::string source, std::optional<Session> session,
                   std::string path)
    : document_(std::move(document)), source_(std::move(source)), session_(std::move(session)),
      path_(std::move(path)) {}

std::string PageTask::describe() const {
  return "the motion" + std::string(session_ ? " and the map" : "") + " as a web page: " + path_;
}

bool PageTask::run(const ToolControl& control) {
  const Scene scene = sceneFromJson(document_, source_);
  const long frames = writeScenePage(scene, session_ ? &*session_ : nullptr, path_, {}, [&](long k, long n) {
    control.progress(static_cast<double>(k) / static_cast<double>(n));
    return !control.stopRequested();
  });
  if (frames > 0) control.progress(1);
  return frames > 0;
}

} // namespace rv
