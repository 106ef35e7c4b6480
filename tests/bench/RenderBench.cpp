// Headless frame time and video export throughput at 1280x720 on the EGL backend (software GL here).
// Figures, not tests; see README.md. The frame cases render a default scene played to t = 2, with
// multisampling off and on, and with a trace of 10^6 points (against the bare scene).
#include "render/Snapshot.h"
#include "render/charts/PoincareChart.h"
#include "render/context/HeadlessContext.h"
#include "render/objects/ContactTraceObject.h"
#include "render/video/VideoExport.h"
#include "render/view/VisualScene.h"
#include "scenes/SceneLoader.h"

#include <benchmark/benchmark.h>
#include <cmath>
#include <filesystem>
#include <tuple>
#include <vtkRenderWindow.h>

namespace rv {
namespace {

const char* const kScenes[] = {"paraboloid_on_plane", "ellipsoid_on_plane", "ball_on_ellipsoid",
                               "ball_on_paraboloid", "chaplygin_ball"};

struct Setup {
  Scene scene;
  std::unique_ptr<VisualScene> visual;
  std::unique_ptr<Integrator> integrator;
  std::unique_ptr<HeadlessContext> context;
};

// a default scene played to t = 2 (or through `tracePoints` integrator steps), attached to a 1280x720 window
std::unique_ptr<Setup> setUp(const std::string& id, int samples, long tracePoints = 0) {
  auto s = std::make_unique<Setup>(Setup{loadScene(defaultScenePath(id), {})});
  s->scene.view.multisamples = samples;
  s->visual = std::make_unique<VisualScene>(*s->scene.model, s->scene.view, s->scene.initialState);
  s->integrator = s->scene.startIntegrator();
  Eigen::VectorXd x;
  if (tracePoints > 0) {
    for (long k = 0; k < tracePoints; ++k) {
      s->integrator->step();
      s->visual->advance(s->integrator->time(), s->integrator->state());
    }
    x = s->integrator->state();
    s->visual->show(s->integrator->time(), x);
  } else {
    playTo(*s->visual, *s->integrator, 2.0, x);
  }
  s->context = createHeadlessContext(1280, 720);
  s->visual->addTo(s->context->window());
  capture(s->context->window()); // first frame: shader compilation, buffer uploads
  return s;
}

void frame(benchmark::State& state, const std::string& id, int samples, long tracePoints, int height) {
  const auto s = setUp(id, samples, tracePoints);
  if (height != 720) {
    s->context->window()->SetSize(height * 16 / 9, height);
    capture(s->context->window());
  }
  for (auto _ : state)
    benchmark::DoNotOptimize(capture(s->context->window()));
  for (const char* name : {"trace", "body_trace"})
    if (const auto* t = dynamic_cast<const ContactTraceObject*>(s->visual->find(name))) {
      state.counters[name] = static_cast<double>(t->points());
      state.counters[std::string(name) + "_drawn"] = static_cast<double>(t->segmentsDrawn());
    }
}

void videoExport(benchmark::State& state, int width, int height, const char* preset) {
  const auto path = std::filesystem::temp_directory_path() / "rollviz_bench.mp4";
  long frames = 0;
  for (auto _ : state) {
    state.PauseTiming(); // the scene's setup is not the export
    const auto s = setUp("ellipsoid_on_plane", 0);
    VideoSpec spec{.path = path.string(), .width = width, .height = height, .fps = 25, .duration = 4};
    spec.encoder.preset = preset;
    state.ResumeTiming();
    frames += exportVideo(*s->visual, s->context->window(), *s->integrator, spec);
  }
  std::filesystem::remove(path);
  state.counters["frames"] = static_cast<double>(frames);
  state.counters["video_fps"] = benchmark::Counter(static_cast<double>(frames), benchmark::Counter::kIsRate);
}

// a map of 10^6 points (the standard map's chaotic sea): the time to redraw it, which a pan or zoom costs
void chartMillion(benchmark::State& state, bool multisampled) {
  std::vector<double> x, y;
  double th = 0.1, p = 0.2;
  for (int k = 0; k < 1000000; ++k) {
    p += 1.3 * std::sin(th);
    th += p;
    x.push_back(std::remainder(th, 2 * M_PI)), y.push_back(std::remainder(p, 2 * M_PI));
  }
  PoincareChart chart("theta", "p");
  chart.addSeries(x, y, seriesColour(0));
  auto ctx = createHeadlessContext(800, 800);
  if (!multisampled) ctx->window()->SetMultiSamples(0); // as the GUI's charts on a CPU rasteriser
  chart.attach(ctx->window());
  capture(ctx->window());
  double shift = 0;
  for (auto _ : state) {
    shift += 1e-3; // a pan: new ranges every frame
    chart.setRanges(-3 + shift, 3 + shift, -3, 3);
    benchmark::DoNotOptimize(capture(ctx->window()));
  }
}

const bool registered = [] {
  for (const char* id : kScenes)
    for (int samples : {0, 8})
      benchmark::RegisterBenchmark(
          ("Frame720p/" + std::string(id) + "/msaa" + std::to_string(samples)).c_str(), frame, id, samples, 0,
          720)
          ->Unit(benchmark::kMillisecond);
  // the frame of a 1080p video (the floor fills the view: its gradient background is left out)
  benchmark::RegisterBenchmark("Frame1080p/ellipsoid_on_plane/msaa0", frame, "ellipsoid_on_plane", 0, 0, 1080)
      ->Unit(benchmark::kMillisecond);
  // a long trace: the rattleback's dense scribble around one spot (worst case), the ball's path across the
  // plane
  for (const char* id : {"ellipsoid_on_plane", "chaplygin_ball"})
    benchmark::RegisterBenchmark(("Frame720p/" + std::string(id) + "/msaa0/trace1e6").c_str(), frame, id, 0,
                                 1000000, 720)
        ->Unit(benchmark::kMillisecond);
  // VTK's default 8x multisampling (headless chart pictures), and none (the GUI's charts on software GL)
  benchmark::RegisterBenchmark("Chart800/poincare/1e6points/pan", chartMillion, true)
      ->Unit(benchmark::kMillisecond);
  benchmark::RegisterBenchmark("Chart800/poincare/1e6points/pan/msaa0", chartMillion, false)
      ->Unit(benchmark::kMillisecond);
  // the encoder's presets at 720p and 1080p (video.preset; veryfast is the default)
  for (const auto& [name, w, h] : {std::tuple{"720p", 1280, 720}, std::tuple{"1080p", 1920, 1080}})
    for (const char* preset : {"veryfast", "superfast", "ultrafast"})
      benchmark::RegisterBenchmark(
          ("VideoExport" + std::string(name) + "/ellipsoid_on_plane/4s/" + preset).c_str(), videoExport, w, h,
          preset)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime()
          ->Iterations(2);
  return true;
}();

} // namespace
} // namespace rv
