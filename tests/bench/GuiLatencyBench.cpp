// The GUI's responsiveness while a job streams map points (issue 7): a probe timer asks the event loop for a
// turn every 5 ms and records how late each turn comes, while the map window receives 10^6 points of the
// standard map. A figure, not a test (tests/bench/README.md). Run under a display (xvfb-run).
#include "app/gui/MainWindow.h"
#include "app/gui/MapPanel.h"
#include "app/gui/QtVtkWidget.h"
#include "scenes/SceneLoader.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QTimer>
#include <algorithm>
#include <benchmark/benchmark.h>
#include <vector>

namespace rv {
namespace {

void mapStreamLatency(benchmark::State& state) {
  const long target = state.range(0);
  for (auto _ : state) {
    MainWindow window;
    window.show();
    nlohmann::json doc = loadScene(defaultScenePath("standard_map")).document;
    doc["poincare"]["points"] = target;
    doc["initial"] = {{"map", {0.1, 0.2}}}; // the chaotic sea: points spread over the torus
    doc["parameters"]["K"] = 1.3;
    QElapsedTimer clock;
    std::vector<double> gaps;
    double worstWhileStreaming = 0, worstAfter = 0; // before and after every point had arrived
    qint64 last = -1;
    bool allArrived = false;
    QTimer probe;
    QObject::connect(&probe, &QTimer::timeout, [&] {
      const qint64 now = clock.nsecsElapsed();
      if (last >= 0) {
        gaps.push_back((now - last) / 1e6 - 5.0); // lateness beyond the 5 ms asked for
        double& worst = allArrived ? worstAfter : worstWhileStreaming;
        worst = std::max(worst, gaps.back());
      }
      last = now;
    });
    window.runDocument(doc);
    clock.start();
    probe.start(5);
    QElapsedTimer wall;
    wall.start();
    qint64 reached = -1; // when every point had arrived; the probe runs 3 s more while the map draws them
    while (wall.elapsed() < 600000 && (reached < 0 || wall.elapsed() < reached + 3000)) {
      QApplication::processEvents(QEventLoop::AllEvents, 5);
      if (reached < 0 && window.mapPanel()->points() >= target) reached = wall.elapsed(), allArrived = true;
    }
    probe.stop();
    state.counters["seconds_to_all_points"] = reached / 1000.0;
    std::sort(gaps.begin(), gaps.end());
    const auto at = [&](double q) { return gaps.empty() ? 0.0 : gaps[std::size_t(q * (gaps.size() - 1))]; };
    state.counters["latency_p50_ms"] = at(0.5);
    state.counters["latency_p99_ms"] = at(0.99);
    state.counters["latency_max_ms"] = gaps.empty() ? 0.0 : gaps.back();
    state.counters["latency_max_streaming_ms"] = worstWhileStreaming; // the job computing beside the GUI
    state.counters["latency_max_after_ms"] = worstAfter;              // the map redrawn, nothing computing
    state.counters["points"] = static_cast<double>(window.mapPanel()->points());
    state.counters["probes"] = static_cast<double>(gaps.size());
  }
}
BENCHMARK(mapStreamLatency)->Arg(100000)->Arg(1000000)->Unit(benchmark::kSecond)->Iterations(1);

} // namespace
} // namespace rv

int main(int argc, char** argv) {
  qputenv("QT_XCB_GL_INTEGRATION", "xcb_glx");
  QSurfaceFormat::setDefaultFormat(rv::QtVtkWidget::defaultFormat());
  QApplication app(argc, argv);
  QApplication::setOrganizationName("rollviz-bench");
  benchmark::Initialize(&argc, argv);
  benchmark::RunSpecifiedBenchmarks();
  return 0;
}
