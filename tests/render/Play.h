// Play.h -- render tests' common start: a default scene (with --set overrides) played to a time.
#pragma once
#include "render/Snapshot.h"
#include "render/context/HeadlessContext.h"
#include "render/video/VideoExport.h"
#include "render/view/VisualScene.h"
#include "scenes/SceneLoader.h"

#include <memory>
#include <vtkRenderWindow.h>

namespace rv::test {

// a default scene (with --set overrides) played to time t: the visual scene and the state it shows
struct Played {
  Scene scene;
  std::unique_ptr<VisualScene> visual;
  Eigen::VectorXd x;
};

inline std::unique_ptr<Played> play(const std::string& id, double t,
                                    const std::vector<std::string>& sets = {}) {
  std::vector<SceneOverride> overrides;
  for (const auto& s : sets)
    overrides.push_back(parseOverride(s));
  auto p = std::make_unique<Played>(Played{loadScene(defaultScenePath(id), overrides)});
  p->visual = std::make_unique<VisualScene>(*p->scene.model, p->scene.view, p->scene.initialState);
  auto integrator = p->scene.startIntegrator();
  playTo(*p->visual, *integrator, t, p->x);
  return p;
}

inline Image renderScene(const std::string& id, double t, int w = 640, int h = 360) {
  const auto p = play(id, t);
  auto ctx = createHeadlessContext(w, h);
  p->visual->addTo(ctx->window());
  Image img = capture(ctx->window());
  ctx->window()->RemoveRenderer(p->visual->renderer());
  return img;
}

/// Pixels whose colour differs by more than `threshold` (sum over channels) between two same-size pictures.
inline long pixelsChanged(const Image& a, const Image& b, int threshold = 40) {
  long n = 0;
  for (std::size_t p = 0; p + 2 < a.rgb.size(); p += 3)
    n += std::abs(int(a.rgb[p]) - int(b.rgb[p])) + std::abs(int(a.rgb[p + 1]) - int(b.rgb[p + 1])) +
             std::abs(int(a.rgb[p + 2]) - int(b.rgb[p + 2])) >
         threshold;
  return n;
}

} // namespace rv::test
