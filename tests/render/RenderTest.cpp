// Headless render tests, built twice: against the EGL backend and against OSMesa. Both compare with the same
// baselines, so passing both also shows that the backends agree.
#include "dynamics/integrators/TimeSampler.h"
#include "render/Snapshot.h"
#include "render/context/HeadlessContext.h"
#include "render/objects/BodyAxesObject.h"
#include "render/objects/ContactTraceObject.h"
#include "render/video/VideoExport.h"
#include "render/view/VisualScene.h"
#include "scenes/Gallery.h"
#include "scenes/SceneCharts.h"
#include "scenes/SceneLoader.h"
#include "tests/render/ImageCompare.h"
#include "tests/render/Play.h"

#include <filesystem>
#include <gtest/gtest.h>
#include <vtkCamera.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

namespace rv {
namespace {

using test::play;
using test::renderScene;

TEST(Render, FlatPicturesAreRejected) {
  const Image flat{.width = 64, .height = 64, .rgb = std::vector<unsigned char>(64 * 64 * 3, 128)};
  EXPECT_FALSE(test::isVaried(flat));
  EXPECT_TRUE(test::isVaried(renderScene("chaplygin_ball", 0.0, 160, 90)));
}

TEST(Render, DefaultChaplyginBallSceneMatchesItsBaseline) {
  const Image img = renderScene("chaplygin_ball", 10.0);
  ASSERT_TRUE(test::isVaried(img));
  EXPECT_EQ(test::matchesBaseline(img, "chaplygin_ball_t10"), "");
}

class DefaultScene : public ::testing::TestWithParam<std::string> {};

TEST_P(DefaultScene, MatchesItsBaseline) {
  const Image img = renderScene(GetParam(), 10.0);
  ASSERT_TRUE(test::isVaried(img));
  EXPECT_EQ(test::matchesBaseline(img, GetParam() + "_t10"), "");
}
INSTANTIATE_TEST_SUITE_P(Rolling, DefaultScene,
                         ::testing::Values("paraboloid_on_plane", "ellipsoid_on_plane", "ball_on_ellipsoid",
                                           "ball_on_paraboloid"));

TEST(Render, LorenzSceneMatchesItsBaseline) {
  const Image img = renderScene("lorenz", 20.0);
  ASSERT_TRUE(test::isVaried(img));
  EXPECT_EQ(test::matchesBaseline(img, "lorenz_t20"), "");
}

TEST(Render, TheBallIsDrawnWhereTheModelPutsIt) {
  // render with and without the ball: the pixels that change are where the camera projects the ball's centre
  const auto played = play("chaplygin_ball", 3.0);
  const Scene& scene = played->scene;
  VisualScene& visual = *played->visual;
  const Eigen::VectorXd& x = played->x;
  auto ctx = createHeadlessContext(640, 360);
  visual.addTo(ctx->window());
  const Image with = capture(ctx->window());
  ObjectOptions hidden;
  hidden.enabled = false;
  visual.setOptions("ball", hidden);
  const Image without = capture(ctx->window());
  const Eigen::Vector3d c = scene.model->pose(x.data())->centre;
  vtkRenderer* ren = visual.renderer();
  ren->SetWorldPoint(c[0], c[1], c[2], 1);
  ren->WorldToDisplay();
  double d[3];
  ren->GetDisplayPoint(d);
  ctx->window()->RemoveRenderer(ren);
  long n = 0;
  double sx = 0, sy = 0;
  for (int y = 0; y < with.height; ++y)
    for (int xx = 0; xx < with.width; ++xx) {
      const std::size_t p = (std::size_t(y) * with.width + xx) * 3;
      if (std::abs(int(with.rgb[p]) - int(without.rgb[p])) +
              std::abs(int(with.rgb[p + 2]) - int(without.rgb[p + 2])) >
          30)
        ++n, sx += xx, sy += y;
    }
  ASSERT_GT(n, 500) << "the ball covers a visible area";
  const double px = sx / n, py = sy / n, projectedY = with.height - 1 - d[1]; // display y is bottom-up
  EXPECT_NEAR(px, d[0], 6.0);
  EXPECT_NEAR(py, projectedY, 12.0); // the shadow disc under the ball pulls the centroid down a little
}

TEST(Render, TraceGrowsAlongTheMotion) {
  const auto played = play("chaplygin_ball", 2.0);
  VisualScene& visual = *played->visual;
  const auto* trace = dynamic_cast<const ContactTraceObject*>(visual.find("trace"));
  ASSERT_NE(trace, nullptr);
  EXPECT_GT(trace->points(), 3); // simplified: a vertex where the path bends by the tolerance
  visual.clear();
  EXPECT_EQ(trace->points(), 0);
}

// the trace on the body: for a ball the contact point in the body's frame is -R gamma (manual (29)), with
// gamma the state's vertical -- an independent reading of where the object puts it
TEST(Render, BodyTraceFollowsTheContactOnTheBall) {
  const auto played = play("chaplygin_ball", 2.0);
  const Eigen::VectorXd& x = played->x;
  const auto* trace = dynamic_cast<const ContactTraceObject*>(played->visual->find("body_trace"));
  ASSERT_NE(trace, nullptr);
  EXPECT_GT(trace->points(), 10);
  const Eigen::Vector3d gamma = x.segment<3>(3);
  const Eigen::Vector3d p = trace->lastPoint();
  EXPECT_NEAR(p.normalized().dot(-gamma.normalized()), 1.0, 1e-12);
  EXPECT_NEAR(p.norm(), 1.0 + 4e-3 * 1.0, 1e-3); // R = 1, just outside the surface
}

// the body's axes (hidden unless asked for): the tip of e_i is as high above the centre as gamma_i of the
// state says (gamma is the vertical in the body's frame, the pose's rotation comes from the integrated
// orientation)
TEST(Render, BodyAxesFollowTheOrientation) {
  const auto played = play("chaplygin_ball", 3.0, {"view.objects.axes.enabled=true"});
  const Scene& scene = played->scene;
  VisualScene& visual = *played->visual;
  const Eigen::VectorXd& x = played->x;
  const auto* shown = dynamic_cast<const BodyAxesObject*>(visual.find("axes"));
  ASSERT_NE(shown, nullptr);
  const Eigen::Vector3d centre = scene.model->pose(x.data())->centre;
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR((shown->tip(i) - centre).normalized()[2], x[3 + i] / x.segment<3>(3).norm(), 1e-9)
        << "axis " << i;
  // drawn: the picture changes where the axes are when they are hidden again
  auto ctx = createHeadlessContext(320, 180);
  visual.addTo(ctx->window());
  const Image with = capture(ctx->window());
  ObjectOptions off;
  off.enabled = false;
  visual.setOptions("axes", off);
  const Image without = capture(ctx->window());
  ctx->window()->RemoveRenderer(visual.renderer());
  EXPECT_GT(test::pixelsChanged(with, without), 60);
}

// every chart view, on a scene where it is quick and meaningful, against its baseline
struct ChartCase {
  std::string view, scene;
  std::vector<std::string> sets;
};

class ChartView : public ::testing::TestWithParam<ChartCase> {};

TEST_P(ChartView, MatchesItsBaseline) {
  const ChartCase& c = GetParam();
  std::vector<SceneOverride> overrides;
  for (const auto& s : c.sets)
    overrides.push_back(parseOverride(s));
  const Scene scene = loadScene(defaultScenePath(c.scene), overrides);
  const auto chart = sceneChart(scene, c.view, {});
  auto ctx = createHeadlessContext(480, 480);
  chart->attach(ctx->window());
  ctx->window()->Render();
  const Image img = capture(ctx->window());
  ASSERT_TRUE(test::isVaried(img)) << c.view;
  EXPECT_EQ(test::matchesBaseline(img, "chart_" + c.view), "");
}

INSTANTIATE_TEST_SUITE_P(
    Views, ChartView,
    ::testing::Values(
        ChartCase{"poincare", "standard_map", {"poincare.points=3000"}},
        ChartCase{"map3d", "chaplygin_ball", {"poincare.points=600"}},
        ChartCase{"plot", "lorenz", {"plot.x=x", "plot.y=z", "plot.period=0.02", "plot.time_limit=30"}},
        ChartCase{"multipliers", "chaplygin_ball", {}}, ChartCase{"bifurcation", "chaplygin_ball", {}},
        ChartCase{"continuation",
                  "henon_map",
                  {"b=-1", "a=2", "fixedpoint.guess=[0.4,-0.4]", "continuation.parameter=a",
                   "continuation.to=4", "continuation.step=0.05"}},
        ChartCase{"spectrum",
                  "henon_heiles",
                  {"spectrum.function=x", "integrator.method=rk4", "integrator.step=0.01"}},
        ChartCase{"lyapunov", "lorenz", {"lyapunov.time=100", "lyapunov.output_period=2"}},
        // a chaotic orbit: long enough for MEGNO's linear growth, short enough that rounding (which differs
        // with the integrator's summation order) has not yet grown to the picture's scale
        ChartCase{"megno",
                  "henon_heiles",
                  {"energy=0.16666666666666666", "megno.time=200", "megno.output_period=1"}},
        ChartCase{"surface",
                  "henon_map",
                  {"grid.x_min=-1.5", "grid.x_max=1.5", "grid.y_min=-0.5", "grid.y_max=0.5",
                   "fixedpoint.guess=[0.2,-0.3]", "fixedpoint.max_distance=0.15"}},
        ChartCase{"ram",
                  "henon_heiles",
                  {"grid.x_min=-0.5", "grid.x_max=0.7", "grid.y_min=-0.5", "grid.y_max=0.5",
                   "grid.step_x=0.01", "grid.step_y=0.01"}},
        // the Henon map's period-doubling curve a = 3 (1 - b)^2 / 4 (scenes/tools/bifurcation_curve.json)
        ChartCase{"bifurcation_curve",
                  "henon_map",
                  {"a=1.4", "b=0.3", "fixedpoint.guess=[0.63,0.19]", "continuation.parameter=a",
                   "continuation.to=0", "continuation.step=-0.05", "bifurcation_curve.second_parameter=b",
                   "bifurcation_curve.kind=period_doubling", "bifurcation_curve.second_min=-1.05",
                   "bifurcation_curve.second_max=0.5"}}),
    [](const auto& info) { return info.param.view; });

// every gallery scene (scenes/gallery, scenes/Gallery.h) at the end of its video: drawn, not blank, as its
// baseline -- which is also the thumbnail File > Gallery shows
TEST(Render, EveryGallerySceneMatchesItsThumbnail) {
  const auto gallery = galleryScenes();
  EXPECT_GE(gallery.size(), 8u);
  for (const auto& g : gallery) {
    SCOPED_TRACE(g.id);
    EXPECT_GT(g.description.size(), 80u) << "says what to watch";
    EXPECT_GT(g.time, 0);
    const Scene scene = loadScene(g.path);
    VisualScene visual(*scene.model, scene.view, scene.initialState);
    auto integrator = scene.startIntegrator();
    Eigen::VectorXd x;
    playTo(visual, *integrator, g.time, x);
    auto ctx = createHeadlessContext(320, 200);
    visual.addTo(ctx->window());
    const Image img = capture(ctx->window());
    ctx->window()->RemoveRenderer(visual.renderer());
    ASSERT_TRUE(test::isVaried(img));
    EXPECT_EQ(test::matchesBaseline(img, "gallery_" + g.id), "");
    EXPECT_TRUE(std::filesystem::is_regular_file(galleryThumbnail(g))) << galleryThumbnail(g); // the GUI's
  }
}

TEST(Render, ChartViewsListIsComplete) {
  EXPECT_EQ(chartViews().size(), 12u); // each has a baseline case above
}

} // namespace
} // namespace rv
