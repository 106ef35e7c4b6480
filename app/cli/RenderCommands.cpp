// RenderCommands.cpp -- `rollviz render` (PNG), `rollviz chart` (figures), `rollviz video` (MP4), headless on
// the linked backend, and `rollviz page` (a self-contained web page; no GL needed).
#include "app/cli/Commands.h"
#include "app/cli/Progress.h"
#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/io/FileNames.h"
#include "dynamics/tools/PoincareMap.h"
#include "render/Snapshot.h"
#include "render/charts/PoincareChart.h"
#include "render/context/HeadlessContext.h"
#include "render/export/Figure.h"
#include "render/export/VtkXmlFiles.h"
#include "render/video/VideoExport.h"
#include "render/view/VisualScene.h"
#include "scenes/SceneCharts.h"
#include "scenes/ScenePage.h"
#include "scenes/Session.h"

#include <cmath>
#include <fmt/core.h>
#include <memory>
#include <vtkRenderWindow.h>

namespace rv {

namespace {
struct RenderOptions {
  SceneArgs scene;
  std::string output, size = "1280x720";
  double time = 10;
  SnapshotOptions snapshot;
};
struct ChartOptions {
  SceneArgs scene;
  std::string view = "poincare", output, size = "800x800", diagram, csv, style = "screen";
  long points = 0;
  int scale = 1;
  CLI::Option* sizeOption = nullptr;
};
struct VideoOptions {
  SceneArgs scene;
  std::string output, size, encoder = "libx264";
  double duration = 0, speed = 0;
  int fps = 0;
};
struct PageOptions {
  SceneArgs scene;
  std::string output;
  double duration = 0, speed = 0;
  int fps = 0;
};
} // namespace

Command addRenderCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("render", "render the 3D view of a scene at a time into a PNG");
  auto o = std::make_shared<RenderOptions>();
  addSceneArgs(cmd, o->scene);
  cmd->add_option("-o,--output", o->output,
                  "PNG file; a .vtm file is the view's pieces (bodies, plane, traces) for ParaView")
      ->check(writesOneOf({".png", ".vtm"}))
      ->required();
  cmd->add_option("--size", o->size, "picture size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option("--time", o->time, "simulation time to show (the trace covers [0, time])")
      ->capture_default_str();
  cmd->add_option("--scale", o->snapshot.scale, "picture = scale x size, rendered in tiles (1..16)")
      ->capture_default_str();
  cmd->add_flag("--transparent", o->snapshot.transparent, "transparent background (RGBA PNG)");
  return {cmd, [o] {
            const auto [w, h] = parseSize(o->size);
            if (!(std::isfinite(o->time) && o->time >= 0))
              throw InputError("--time: must be a finite number >= 0");
            const Scene scene = o->scene.load();
            checkWritable(o->output, "-o");
            auto integrator = scene.startIntegrator();
            VisualScene visual(*scene.model, scene.view, scene.initialState);
            Eigen::VectorXd x;
            playTo(visual, *integrator, o->time, x);
            if (hasExtension(o->output, ".vtm")) {
              writeSceneVtm(visual, o->output);
              return 0;
            }
            auto ctx = createHeadlessContext(w, h);
            visual.addTo(ctx->window());
            writePng(ctx->window(), o->output, "-o", o->snapshot);
            ctx->window()->RemoveRenderer(visual.renderer());
            return 0;
          }};
}

Command addChartCommand(CLI::App& app) {
  auto* cmd =
      app.add_subcommand("chart", "draw a view of a scene's tool output as a chart into a PNG, SVG or PDF");
  auto o = std::make_shared<ChartOptions>();
  addSceneArgs(cmd, o->scene);
  static const std::vector<std::string> views = [] {
    auto v = chartViews();
    v.emplace_back("sweep"); // a finished sweep: SCENE is the sweep file, --csv its output
    return v;
  }();
  cmd->add_option("--view", o->view, "what to draw: " + CLI::detail::join(views, " | "))
      ->capture_default_str()
      ->check(CLI::IsMember(views));
  cmd->add_option("--csv", o->csv,
                  "--view sweep: the CSV `rollviz sweep` wrote (the positional is the sweep file)");
  cmd->add_option("-o,--output", o->output, "figure: PNG, or SVG or PDF (vectors, text as text)")
      ->check(writesOneOf(figureExtensions()))
      ->required();
  o->sizeOption = cmd->add_option("--size", o->size, "picture size WIDTHxHEIGHT")->capture_default_str();
  cmd->add_option(
         "--style", o->style,
         "screen, or paper: white, black axes and text, the type and pens of a 3.5-inch journal column "
         "at 300 dpi (1050x788 unless --size)")
      ->capture_default_str()
      ->check(CLI::IsMember({"screen", "paper"}));
  cmd->add_option("--scale", o->scale,
                  "N x the pixels with text and pens N x as large: the same figure, finer")
      ->capture_default_str()
      ->check(CLI::Range(1, 8));
  cmd->add_option("--points", o->points, "Poincare points to compute (default: the scene's poincare.points)");
  cmd->add_option(
      "--diagram", o->diagram,
      "--view bifurcation: which diagram (default: the problem's first; `rollviz diagram --json` lists "
      "them)");
  return {cmd, [o] {
            const ChartStyle style = chartStyle(o->style, o->scale, "--style");
            const auto [w, h] = figureSize(style, parseSize(o->size), o->sizeOption->count() > 0);
            if (o->view == "sweep") {
              if (o->csv.empty())
                throw InputError("--csv: --view sweep draws a finished sweep's CSV: give it");
              const SweepSpec spec = loadSweep(o->scene.scene);
              checkWritable(o->output, "-o");
              SweepChartData data = sweepChartData(spec);
              data.values = readSweepCsv(spec, o->csv, "--csv");
              writeChartFigure(data, o->output, {w, h}, "-o", style);
              return 0;
            }
            if (!o->csv.empty()) throw InputError("--csv: only with --view sweep");
            if (o->view == "poincare")
              if (const auto session = readSessionIfAny(o->scene.scene)) { // the map the GUI saved
                if (!o->scene.sets.empty() || o->points > 0)
                  throw InputError(std::string(o->scene.sets.empty() ? "--points" : "--set") +
                                   ": a session's map is drawn as it was saved (other views compute)");
                checkWritable(o->output, "-o");
                const auto chart = sessionMapChart(*session);
                auto ctx = createHeadlessContext(w, h);
                chart->attach(ctx->window());
                styleCharts(ctx->window(), style);
                writeFigure(ctx->window(), o->output, "-o");
                return 0;
              }
            const Scene scene = o->scene.load();
            checkWritable(o->output, "-o");
            Progress progress(o->view);
            const auto chart =
                sceneChart(scene, o->view, interruptibleControl(progress), o->points, o->diagram);
            auto ctx = createHeadlessContext(w, h);
            chart->attach(ctx->window());
            styleCharts(ctx->window(), style);
            writeFigure(ctx->window(), o->output, "-o");
            return interrupted() ? 130 : 0;
          }};
}

Command addVideoCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand("video", "record the 3D view of a scene into an MP4 (H.264)");
  auto o = std::make_shared<VideoOptions>();
  addSceneArgs(cmd, o->scene);
  cmd->add_option("-o,--output", o->output, "MP4 file")->check(writesOneOf({".mp4"}))->required();
  auto* duration =
      cmd->add_option("--duration", o->duration, "seconds of video (default: the scene's video.duration)");
  auto* fps = cmd->add_option("--fps", o->fps, "frames per second (default: the scene's video.fps)");
  cmd->add_option("--size", o->size,
                  "frame size WIDTHxHEIGHT, even numbers (default: video.width x video.height)");
  cmd->add_option("--speed", o->speed,
                  "simulation seconds per video second (default: the scene's view.speed)");
  cmd->add_option("--encoder", o->encoder, "libav encoder (libx264, or mpeg4)")->capture_default_str();
  return {cmd, [o, duration, fps] {
            const Scene scene = o->scene.load();
            // the scene's video section, then what the command line says
            VideoOverrides given{.sizeName = "--size", .durationName = "--duration", .fpsName = "--fps"};
            if (!o->size.empty()) given.size = parseSize(o->size);
            if (duration->count()) given.duration = o->duration;
            if (fps->count()) given.fps = o->fps;
            VideoSpec spec =
                videoSpec(scene.tool("video"), o->speed > 0 ? o->speed : scene.view.speed, given);
            spec.path = o->output;
            spec.encoder.codec = o->encoder;
            checkWritable(o->output, "-o");
            auto integrator = scene.startIntegrator();
            VisualScene visual(*scene.model, scene.view, scene.initialState);
            auto ctx = createHeadlessContext(spec.width, spec.height);
            visual.addTo(ctx->window());
            Progress progress("video");
            const long frames = exportVideo(visual, ctx->window(), *integrator, spec, [&](long k, long n) {
              progress.update(static_cast<double>(k) / n);
              return !interrupted();
            });
            ctx->window()->RemoveRenderer(visual.renderer());
            return interrupted() && frames < std::lround(spec.duration * spec.fps) ? 130 : 0;
          }};
}

Command addPageCommand(CLI::App& app) {
  auto* cmd = app.add_subcommand(
      "page",
      "write a scene's motion (a session's: with its Poincare map) as one self-contained web page that "
      "plays, turns and scrubs in any browser, offline");
  auto o = std::make_shared<PageOptions>();
  addSceneArgs(cmd, o->scene);
  cmd->add_option("-o,--output", o->output, "HTML file")->check(writesOneOf({".html", ".htm"}))->required();
  auto* duration = cmd->add_option("--duration", o->duration,
                                   "seconds of playback at 1x (default: the scene's video.duration)");
  auto* fps =
      cmd->add_option("--fps", o->fps, "poses per second of playback (default: the scene's video.fps)");
  auto* speed =
      cmd->add_option("--speed", o->speed, "simulation seconds per second of playback (default: view.speed)");
  return {cmd, [o, duration, fps, speed] {
            PageOverrides given;
            if (duration->count()) given.duration = o->duration;
            if (fps->count()) given.fps = o->fps;
            if (speed->count()) given.speed = o->speed;
            const auto session = readSessionIfAny(o->scene.scene);
            if (session && !o->scene.sets.empty())
              throw InputError(
                  "--set: a session's page shows its map as it was saved (give the scene instead)");
            const Scene scene = o->scene.load();
            checkWritable(o->output, "-o");
            Progress progress("page");
            const long frames =
                writeScenePage(scene, session ? &*session : nullptr, o->output, given, [&](long k, long n) {
                  progress.update(static_cast<double>(k) / n);
                  return !interrupted();
                });
            return frames == 0 ? 130 : 0;
          }};
}

} // namespace rv
