// The apex view, the scene axes, textures, snapshots (large, transparent), long traces and a cancelled video:
// built with RenderTest.cpp, so it runs on EGL and on OSMesa.
#include "render/GrowingPolyline.h"
#include "render/charts/ChartStyle.h"
#include "render/charts/PoincareChart.h"
#include "render/objects/PlaneObject.h"

#include "render/BodyMeshes.h"
#include "render/objects/ApexObject.h"
#include "render/objects/ContactTraceObject.h"
#include "render/objects/FrameObjects.h"
#include "render/objects/SceneAxesObject.h"
#include "render/video/Mp4Writer.h"
#include "render/video/ScreenRecorder.h"
#include "scenes/ModelFile.h"
#include "tests/render/ImageCompare.h"
#include "tests/render/Play.h"
#include <Eigen/LU>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <gtest/gtest.h>
#include <numbers>
#include <tuple>
#include <unistd.h>
#include <vtkAxis.h>
#include <vtkCamera.h>
#include <vtkChartXY.h>
#include <vtkImageData.h>
#include <vtkPNGReader.h>
#include <vtkPolyData.h>
#include <vtkRenderer.h>
#include <vtkStringArray.h>

namespace rv {
namespace {

using test::play;

// a temporary file's name of this process: the EGL and OSMesa test binaries run side by side (ctest -j)
std::string ownName(const std::string& name) {
  return std::to_string(::getpid()) + "_" + name;
}

Image renderPlayed(VisualScene& visual, int w = 480, int h = 360) {
  auto ctx = createHeadlessContext(w, h);
  visual.addTo(ctx->window());
  Image img = capture(ctx->window());
  ctx->window()->RemoveRenderer(visual.renderer());
  return img;
}

// looking in the body's frame, the apex of the fixed z axis is R^T e_z = gamma, which the state carries
// itself (chaplygin_ball: M then gamma): the rotation the apexes use is the integrated orientation, an
// independent reading
TEST(ApexView, TheFixedVerticalSeenFromTheBodyIsGamma) {
  const auto p = play("chaplygin_ball", 4.0, {"view.kind=apex", "view.looking_in=body"});
  const auto* z = dynamic_cast<const ApexObject*>(p->visual->find("apex_z"));
  ASSERT_NE(z, nullptr);
  const Eigen::Vector3d gamma = p->x.segment<3>(3);
  EXPECT_NEAR((z->tip() - gamma.normalized()).norm(), 0, 1e-9);
  EXPECT_GT(z->tracePoints(), 10);
}

// looking in the absolute frame the apexes are the body's axes: orthonormal and right-handed, and the height
// of each is gamma_i (the vertical in the body's frame)
TEST(ApexView, TheBodysAxesSeenFromSpaceAreOrthonormalWithHeightsGamma) {
  const auto p = play("chaplygin_ball", 4.0, {"view.kind=apex"});
  Eigen::Matrix3d r;
  for (int i = 0; i < 3; ++i) {
    const auto* a = dynamic_cast<const ApexObject*>(p->visual->find(std::string("apex_") + "xyz"[i]));
    ASSERT_NE(a, nullptr);
    r.col(i) = a->tip();
  }
  EXPECT_NEAR((r.transpose() * r - Eigen::Matrix3d::Identity()).norm(), 0, 1e-12);
  EXPECT_NEAR(r.determinant(), 1, 1e-12);
  const Eigen::Vector3d gamma = p->x.segment<3>(3).normalized();
  for (int i = 0; i < 3; ++i)
    EXPECT_NEAR(r(2, i), gamma[i], 1e-9) << "axis " << i;
}

// an arbitrary vector fixed in the body: given as the body's first axis at t = 0, it stays the first axis
TEST(ApexView, AnArbitraryVectorTurnsWithTheBody) {
  const auto p0 = play("chaplygin_ball", 0.0, {"view.kind=apex"});
  const Eigen::Vector3d e1 = dynamic_cast<const ApexObject*>(p0->visual->find("apex_x"))->tip();
  const std::string v = "view.objects.vector.vector=[" + std::to_string(2 * e1[0]) + "," +
                        std::to_string(2 * e1[1]) + "," + std::to_string(2 * e1[2]) + "]";
  const auto p = play("chaplygin_ball", 3.0, {"view.kind=apex", "view.objects.vector.enabled=true", v});
  const auto* vector = dynamic_cast<const VectorObject*>(p->visual->find("vector"));
  const auto* x = dynamic_cast<const ApexObject*>(p->visual->find("apex_x"));
  ASSERT_NE(vector, nullptr);
  EXPECT_NEAR((vector->value() - 2 * x->tip()).norm(), 0, 1e-5); // to_string keeps 6 decimals
  EXPECT_GT((x->tip() - e1).norm(), 0.1) << "the body has turned";
}

TEST(ApexView, MatchesItsBaseline) {
  const auto p = play("ellipsoid_on_plane", 30.0,
                      {"view.kind=apex", "view.axes.style=box", "view.objects.vector.enabled=true"});
  const Image img = renderPlayed(*p->visual);
  ASSERT_TRUE(test::isVaried(img));
  EXPECT_EQ(test::matchesBaseline(img, "apex_ellipsoid_on_plane_t30"), "");
}

// the apex view says what its colours are: a line per axis in that axis' colour (none in other views)
TEST(ApexView, HasAKeyToItsColours) {
  const auto p = play("ellipsoid_on_plane", 1.0, {"view.kind=apex"});
  ASSERT_EQ(p->visual->colourKey().size(), 3u);
  EXPECT_NE(p->visual->colourKey()[0].find("e1"), std::string::npos);
  const auto body = play("chaplygin_ball", 0.0, {"view.kind=apex", "view.looking_in=body"});
  EXPECT_NE(body->visual->colourKey()[2].find("gamma"), std::string::npos);
  EXPECT_TRUE(play("ellipsoid_on_plane", 0.0)->visual->colourKey().empty());
  const Image img = renderPlayed(*p->visual);
  // bottom left, above the time: text in each axis colour (a channel well above the other two)
  for (int axis = 0; axis < 3; ++axis) {
    long n = 0;
    for (int y = img.height - 100; y < img.height; ++y)
      for (int x = 0; x < img.width / 2; ++x) {
        const unsigned char* px = &img.rgb[(static_cast<std::size_t>(y) * img.width + x) * 3];
        n += px[axis] > 120 && px[axis] > px[(axis + 1) % 3] + 60 && px[axis] > px[(axis + 2) % 3] + 60;
      }
    EXPECT_GT(n, 30) << "axis " << axis;
  }
}

// issue 61 (6): seen from straight above (the standard map's view) the z axis points at the viewer and its
// labels fell on one another at a corner ("3210-1-2-3"); they are left out, x's and y's stay, and from the
// side all three show
TEST(SceneAxes, AnAxisSeenEndOnShowsNoLabels) {
  for (const double elevation : {90.0, 25.0}) {
    const auto p = play("standard_map", 10.0,
                        {"view.axes.style=box", "view.camera.elevation=" + std::to_string(elevation)});
    auto ctx = createHeadlessContext(640, 360);
    p->visual->addTo(ctx->window());
    ASSERT_TRUE(test::isVaried(capture(ctx->window())));
    const auto* axes = dynamic_cast<const SceneAxesObject*>(p->visual->find("scene_axes"));
    ASSERT_NE(axes, nullptr);
    EXPECT_TRUE(axes->labelsShown(0) && axes->labelsShown(1)) << elevation;
    EXPECT_EQ(axes->labelsShown(2), elevation != 90.0);
    ctx->window()->RemoveRenderer(p->visual->renderer());
  }
}

// issue 61 (6): the axes' numbers were tiny in a large picture (a 1920x1080 snapshot of a small view): while
// a ScaledPicture lives they are `scale` times as large, and as they were after
TEST(SceneAxes, TheirNumbersGrowWithALargePicture) {
  const auto p = play("chaplygin_ball", 1.0, {"view.axes.style=box"});
  auto ctx = createHeadlessContext(320, 200);
  p->visual->addTo(ctx->window());
  (void)capture(ctx->window());
  const auto* axes = dynamic_cast<const SceneAxesObject*>(p->visual->find("scene_axes"));
  ASSERT_NE(axes, nullptr);
  const int before = axes->labelFontSize(0);
  {
    const ScaledPicture scaled(ctx->window(), 3);
    EXPECT_EQ(axes->labelFontSize(0), 3 * before);
  }
  EXPECT_EQ(axes->labelFontSize(0), before);
  ctx->window()->RemoveRenderer(p->visual->renderer());
}

TEST(SceneAxes, TicksAreWhereTheRangeAndCountsPutThem) {
  const auto p = play(
      "chaplygin_ball", 1.0,
      {"view.axes.style=box", "view.axes.min=[0,-2,0]", "view.axes.max=[10,2,1]", "view.axes.tickmarks=5"});
  const auto* axes = dynamic_cast<const SceneAxesObject*>(p->visual->find("scene_axes"));
  ASSERT_NE(axes, nullptr);
  // round numbers, about five intervals: [0, 10] by 2; [-2, 2] by 1 (not by 0.8); [0, 1] by 0.2
  const std::vector<double> x = axes->majorTicks(0), y = axes->majorTicks(1), z = axes->majorTicks(2);
  ASSERT_EQ(x.size(), 6u);
  ASSERT_EQ(y.size(), 5u);
  ASSERT_EQ(z.size(), 6u);
  for (int k = 0; k <= 5; ++k) {
    EXPECT_NEAR(x[k], 2.0 * k, 1e-12);
    EXPECT_NEAR(z[k], 0.2 * k, 1e-12);
  }
  for (int k = 0; k <= 4; ++k)
    EXPECT_NEAR(y[k], -2.0 + k, 1e-12);
  // drawn: switching them off changes the picture
  const Image with = renderPlayed(*p->visual);
  AxesOptions none;
  p->visual->setAxes(none);
  EXPECT_GT(test::pixelsChanged(with, renderPlayed(*p->visual)), 300);
}

// In a body view the box the axes draw without a range of their own holds the body and shows in the frame
// (it used to be four body sizes wide: its edges fell outside the camera's view, the axes seemed missing),
// and lines at z = 0 are drawn above the floor, not hidden in it. (Switching the axes off changed 1731 pixels
// of this picture with the old box, 2837 with this one.)
TEST(SceneAxes, InABodyViewTheBoxAroundTheBodyIsSeen) {
  const auto p = play("chaplygin_ball", 2.0, {"view.axes.style=box"});
  const auto* axes = dynamic_cast<const SceneAxesObject*>(p->visual->find("scene_axes"));
  ASSERT_NE(axes, nullptr);
  const Image with = renderPlayed(*p->visual);
  AxesOptions none;
  p->visual->setAxes(none);
  const long changed = test::pixelsChanged(with, renderPlayed(*p->visual));
  EXPECT_GT(changed, 2400) << "the box and its numbers are in the picture: " << changed;
}

// Without a range of their own the axes hold the motion: the Lorenz attractor leaves the box its start point
// gives (|x0| = sqrt 3) at once, and by t = 20 has reached z > 40 and |x| > 15 (its known extent); the box
// covers every point of the curve, and Reset (clear) gives the starting box back.
TEST(SceneAxes, TheBoxGrowsToHoldTheCurve) {
  const auto p = play("lorenz", 20.0, {"view.axes.style=box"});
  auto* axes = dynamic_cast<SceneAxesObject*>(p->visual->find("scene_axes"));
  ASSERT_NE(axes, nullptr);
  // the box's ends are where the curve went (z up to ~48); its ticks are round numbers inside it
  for (int i = 0; i < 3; ++i)
    for (double t : axes->majorTicks(i)) {
      const double step = axes->majorTicks(i)[1] - axes->majorTicks(i)[0];
      EXPECT_NEAR(t / step, std::round(t / step), 1e-9) << "axis " << i << " tick " << t;
      EXPECT_TRUE(step == 1 || step == 2 || step == 5 || step == 10 || step == 20) << step;
    }
  const auto [lo, hi] = axes->range();
  EXPECT_GT(hi[2], 40.0);
  EXPECT_LT(lo[0], -15.0);
  EXPECT_GT(hi[0], 15.0);
  // every point of the integration is inside: replay it and check
  auto integrator = p->scene.startIntegrator();
  int outside = 0;
  while (integrator->time() < 20) {
    integrator->step();
    for (int i = 0; i < 3; ++i)
      outside += integrator->state()[i] < lo[i] || integrator->state()[i] > hi[i];
  }
  EXPECT_EQ(outside, 0);
  p->visual->clear();
  const auto [lo0, hi0] = axes->range();
  EXPECT_NEAR(hi0[2], std::sqrt(3.0), 1e-12);
  // a range of its own stays
  const auto fixed =
      play("lorenz", 5.0, {"view.axes.style=box", "view.axes.min=[-1,-1,-1]", "view.axes.max=[1,1,1]"});
  const auto [flo, fhi] = dynamic_cast<SceneAxesObject*>(fixed->visual->find("scene_axes"))->range();
  EXPECT_EQ(fhi[2], 1.0);
  // the apex view's box is the unit sphere's wherever the body rolls
  const auto apex = play("chaplygin_ball", 30.0, {"view.kind=apex", "view.axes.style=box"});
  const auto [alo, ahi] = dynamic_cast<SceneAxesObject*>(apex->visual->find("scene_axes"))->range();
  EXPECT_EQ(alo[0], -1.0);
  EXPECT_EQ(ahi[1], 1.0);
}

// "grid" draws the plane's grid over the floor: the floor stays (a wireframe of its one quad would leave the
// background showing through where the floor was)
TEST(Objects, GridStyleKeepsTheFloor) {
  const auto p = play("chaplygin_ball", 0.5);
  const Image fill = renderPlayed(*p->visual);
  ObjectOptions grid = p->visual->options().object("plane");
  grid.style = SurfaceStyle::Grid;
  p->visual->setOptions("plane", grid);
  const Image lines = renderPlayed(*p->visual);
  EXPECT_TRUE(test::isVaried(lines));
  if (const char* out = std::getenv("ROLLVIZ_TEST_OUTPUT")) {
    writePng(fill, std::string(out) + "/plane_fill.png");
    writePng(lines, std::string(out) + "/plane_grid.png");
  }
  // pixels of the window's background colour: as few as with the filled floor (the camera sees floor
  // everywhere here; a wireframe of the plane's one quad would show the background through it)
  double bg[3];
  p->visual->renderer()->GetBackground(bg);
  const auto background = [&](const Image& img) {
    long n = 0;
    for (std::size_t k = 0; k + 2 < img.rgb.size(); k += 3)
      n += std::abs(img.rgb[k] - 255 * bg[0]) + std::abs(img.rgb[k + 1] - 255 * bg[1]) +
               std::abs(img.rgb[k + 2] - 255 * bg[2]) <
           12;
    return n;
  };
  EXPECT_LT(background(lines), background(fill) + 200) << background(fill);
  EXPECT_GT(test::pixelsChanged(fill, lines, 20), 500); // the checker gave way to lines on a plain sheet
}

// a body's "grid" is meridians and parallels on its surface (not the mesh's triangles): every vertex on the
// ellipsoid, 24 + 11 lines
TEST(Objects, ABodysGridIsMeridiansAndParallels) {
  BodyGeometry g;
  g.shape = BodyShape::Ellipsoid;
  g.semiAxes = {1.0, 0.6, 0.4};
  g.centre = {0.0, 0.0, 0.1};
  const auto lines = makeBodyGridLines(g);
  EXPECT_EQ(lines->GetNumberOfLines(), 35);
  EXPECT_EQ(lines->GetNumberOfPolys(), 0);
  double worst = 0;
  for (vtkIdType i = 0; i < lines->GetNumberOfPoints(); ++i) {
    double q[3];
    lines->GetPoint(i, q);
    worst = std::max(worst, std::abs(std::pow(q[0] / 1.0, 2) + std::pow(q[1] / 0.6, 2) +
                                     std::pow((q[2] - 0.1) / 0.4, 2) - 1));
  }
  EXPECT_LT(worst, 1e-6); // (VTK keeps points in single precision)
  // drawn: the grid alone covers far fewer pixels than the surface, yet is there
  const auto p = play("chaplygin_ball", 0.5, {"view.objects.plane.enabled=false"});
  const Image fill = renderPlayed(*p->visual);
  ObjectOptions grid = p->visual->options().object("ball");
  grid.style = SurfaceStyle::Grid;
  p->visual->setOptions("ball", grid);
  const Image wire = renderPlayed(*p->visual);
  grid.enabled = false;
  p->visual->setOptions("ball", grid);
  const Image none = renderPlayed(*p->visual);
  if (const char* out = std::getenv("ROLLVIZ_TEST_OUTPUT"))
    writePng(wire, std::string(out) + "/ball_grid.png");
  const long surface = test::pixelsChanged(none, fill, 20), meshLines = test::pixelsChanged(none, wire, 20);
  EXPECT_GT(meshLines, surface / 20) << surface;
  EXPECT_LT(meshLines, surface * 3 / 4) << surface; // lines, front and back, not a surface
}

TEST(Objects, TextureNoneAndAPngChangeTheBall) {
  const auto own = play("chaplygin_ball", 1.0);
  const auto plain = play("chaplygin_ball", 1.0, {"view.objects.ball.texture=none"});
  const auto png = play("chaplygin_ball", 1.0, {"view.objects.ball.texture=stripes"});
  const Image a = renderPlayed(*own->visual), b = renderPlayed(*plain->visual),
              c = renderPlayed(*png->visual);
  EXPECT_GT(test::pixelsChanged(a, b), 500);
  EXPECT_GT(test::pixelsChanged(a, c), 500);
  EXPECT_GT(test::pixelsChanged(b, c), 500);
}

TEST(Snapshot, TransparentBackgroundAndLargePictures) {
  // (no text: glyphs rasterised at 3x differ from 1x ones averaged, and the key fills much of so small a
  // view)
  const auto p = play("chaplygin_ball", 1.0, {"view.kind=apex", "view.overlay=false"});
  auto ctx = createHeadlessContext(200, 150);
  p->visual->addTo(ctx->window());
  const auto dir = std::filesystem::temp_directory_path();
  const std::string clear = (dir / ownName("rv_clear.png")).string(),
                    large = (dir / ownName("rv_large.png")).string();
  writePng(ctx->window(), clear, "-o", {.transparent = true});
  writePng(ctx->window(), large, "-o", {.scale = 3});
  const Image normal = capture(ctx->window());
  ctx->window()->RemoveRenderer(p->visual->renderer());

  vtkNew<vtkPNGReader> png;
  png->SetFileName(clear.c_str());
  png->Update();
  ASSERT_EQ(png->GetOutput()->GetNumberOfScalarComponents(), 4);
  const auto* rgba = static_cast<const unsigned char*>(png->GetOutput()->GetScalarPointer(0, 0, 0));
  EXPECT_EQ(rgba[3], 0) << "a corner is background";
  const auto* centre = static_cast<const unsigned char*>(png->GetOutput()->GetScalarPointer(100, 75, 0));
  EXPECT_GT(centre[3], 100) << "the sphere is not background";

  // three times the size, and the same picture: every 3x3 block averages to the window's pixel
  const Image big = readPng(large);
  ASSERT_EQ(big.width, 600);
  ASSERT_EQ(big.height, 450);
  Image shrunk{.width = 200, .height = 150, .rgb = std::vector<unsigned char>(200 * 150 * 3)};
  for (int y = 0; y < 150; ++y)
    for (int x = 0; x < 200; ++x)
      for (int c = 0; c < 3; ++c) {
        int sum = 0;
        for (int dy = 0; dy < 3; ++dy)
          for (int dx = 0; dx < 3; ++dx)
            sum += big.rgb[(std::size_t(3 * y + dy) * 600 + 3 * x + dx) * 3 + c];
        shrunk.rgb[(std::size_t(y) * 200 + x) * 3 + c] = static_cast<unsigned char>(sum / 9);
      }
  EXPECT_LT(test::compareImages(normal, shrunk).meanAbs, 6.0);
  std::filesystem::remove(clear);
  std::filesystem::remove(large);
}

// the streaming simplification keeps the drawn line within its tolerance of every point appended, with far
// fewer vertices: a circle of radius 1 sampled 100 000 times, tolerance 1e-3 (checked at half of it), needs
// about 2 pi / sqrt(8 * 5e-4) = 100 vertices
TEST(Trace, LongTracesAreSimplifiedWithinTheirTolerance) {
  GrowingPolyline line(1e-3, 1000000);
  std::vector<Eigen::Vector3d> points;
  const int n = 100000;
  for (int k = 0; k <= n; ++k) {
    const double a = 2 * std::numbers::pi * k / n;
    points.emplace_back(std::cos(a), std::sin(a), 0.01 * std::sin(7 * a));
    line.append(points.back()[0], points.back()[1], points.back()[2]);
  }
  EXPECT_GT(line.size(), 50);
  EXPECT_LT(line.size(), 200);
  std::vector<Eigen::Vector3d> vertices;
  for (long i = 0; i < line.size(); ++i)
    vertices.push_back(line.vertex(i));
  // (VTK keeps points in single precision)
  EXPECT_NEAR((vertices.front() - points.front()).norm(), 0, 1e-6);
  EXPECT_NEAR((vertices.back() - points.back()).norm(), 0, 1e-6);
  double worst = 0;
  for (const auto& q : points) {
    double best = 1e9;
    for (std::size_t i = 0; i + 1 < vertices.size(); ++i) {
      const Eigen::Vector3d d = vertices[i + 1] - vertices[i];
      const double s = std::clamp((q - vertices[i]).dot(d) / d.squaredNorm(), 0.0, 1.0);
      best = std::min(best, (vertices[i] + s * d - q).norm());
    }
    worst = std::max(worst, best);
  }
  EXPECT_LE(worst, 1e-3 + 1e-6);
}

// the screen-space level of detail draws a fraction of a dense trace's segments and the same picture: the
// rattleback's scribble after 3·10^5 steps (both traces), drawn with and without it
TEST(Trace, TheLevelOfDetailDrawsFewerSegmentsAndTheSamePicture) {
  auto played = test::play("ellipsoid_on_plane", 0);
  auto integrator = played->scene.startIntegrator();
  for (long k = 0; k < 1000000; ++k) {
    integrator->step();
    played->visual->advance(integrator->time(), integrator->state());
  }
  Eigen::VectorXd x = integrator->state();
  played->visual->show(integrator->time(), x);
  auto traces = [&] {
    std::vector<ContactTraceObject*> t;
    for (const char* name : {"trace", "body_trace"})
      t.push_back(dynamic_cast<ContactTraceObject*>(played->visual->find(name)));
    return t;
  };
  auto ctx = createHeadlessContext(1280, 720);
  played->visual->addTo(ctx->window());
  const Image lod = capture(ctx->window());
  long drawn = 0, total = 0;
  for (auto* t : traces()) {
    ASSERT_TRUE(t);
    drawn += t->segmentsDrawn();
    total += t->points() - 1;
    t->setLevelOfDetail(false);
  }
  const Image exact = capture(ctx->window());
  for (auto* t : traces())
    EXPECT_EQ(t->segmentsDrawn(), t->points() - 1);
  // a thinner line gets smaller cells (more segments drawn); a translucent one is drawn whole (overlaps
  // darken)
  auto* plane = traces()[0];
  plane->setLevelOfDetail(true);
  ObjectOptions o = played->visual->options().object("trace");
  o.lineWidth = 1;
  played->visual->setOptions("trace", o);
  capture(ctx->window());
  const long thinDrawn = plane->segmentsDrawn();
  o.lineWidth = 3;
  played->visual->setOptions("trace", o);
  capture(ctx->window());
  EXPECT_GT(thinDrawn, plane->segmentsDrawn() * 3 / 2);
  o.opacity = 0.5;
  played->visual->setOptions("trace", o);
  capture(ctx->window());
  EXPECT_EQ(plane->segmentsDrawn(), plane->points() - 1);
  ctx->window()->RemoveRenderer(played->visual->renderer());
  if (const char* out = std::getenv("ROLLVIZ_TEST_OUTPUT")) {
    writePng(lod, std::string(out) + "/trace_lod.png");
    writePng(exact, std::string(out) + "/trace_exact.png");
  }
  EXPECT_GT(total, 40000) << "a dense trace";
  long red = 0; // the plane's trace is drawn (red): the pictures compared are of a trace
  for (std::size_t p = 0; p + 2 < exact.rgb.size(); p += 3)
    red += exact.rgb[p] > 180 && exact.rgb[p + 1] < 80 && exact.rgb[p + 2] < 80;
  EXPECT_GT(red, 5000);
  EXPECT_LT(drawn, total / 2) << "the level of detail leaves most of a dense scribble's segments out";
  const auto d = test::compareImages(lod, exact);
  EXPECT_LT(d.meanAbs, 2.0); // the baselines' tolerance
  EXPECT_LT(d.fractionOver, 0.01);
  std::printf("segments drawn %ld of %ld; mean |difference| %.3f, pixels over 48: %.4f%%\n", drawn, total,
              d.meanAbs, 100 * d.fractionOver);
}

int countFrames(const std::string& path) {
  const std::string cmd =
      "ffprobe -v error -count_frames -select_streams v:0 -show_entries stream=nb_read_frames "
      "-of csv=p=0 '" +
      path + "'";
  FILE* f = popen(cmd.c_str(), "r");
  if (!f) return -1;
  int frames = -1;
  if (std::fscanf(f, "%d", &frames) != 1) frames = -1;
  pclose(f);
  return frames;
}

// a cancelled export leaves a valid, shorter video: the frames rendered so far, finished properly
TEST(Video, ACancelledExportIsAValidShorterVideo) {
  const auto p = play("chaplygin_ball", 0.0);
  auto integrator = p->scene.startIntegrator();
  auto ctx = createHeadlessContext(320, 240);
  p->visual->addTo(ctx->window());
  const std::string path = (std::filesystem::temp_directory_path() / ownName("rv_cancelled.mp4")).string();
  VideoSpec spec{.path = path, .width = 320, .height = 240, .fps = 10, .duration = 5};
  const long written =
      exportVideo(*p->visual, ctx->window(), *integrator, spec, [](long done, long) { return done < 7; });
  ctx->window()->RemoveRenderer(p->visual->renderer());
  EXPECT_EQ(written, 7);
  EXPECT_EQ(countFrames(path), 7);
  std::filesystem::remove(path);
}

// the mean colour of video frame `n` (ffmpeg decodes it to RGB); {-1,-1,-1} when it cannot be read
std::array<double, 3> frameColour(const std::string& path, int n, int width, int height) {
  const std::string cmd = "ffmpeg -v error -i '" + path + "' -vf 'select=eq(n\\," + std::to_string(n) +
                          ")' -vframes 1 -f rawvideo -pix_fmt rgb24 - 2>/dev/null";
  FILE* f = popen(cmd.c_str(), "r");
  std::array<double, 3> mean{-1, -1, -1};
  if (!f) return mean;
  std::vector<unsigned char> rgb(static_cast<std::size_t>(width) * height * 3);
  if (std::fread(rgb.data(), 1, rgb.size(), f) == rgb.size()) {
    mean = {0, 0, 0};
    for (std::size_t p = 0; p < rgb.size(); ++p)
      mean[p % 3] += rgb[p] / (rgb.size() / 3.0);
  }
  pclose(f);
  return mean;
}

Image plain(int width, int height, unsigned char r, unsigned char g, unsigned char b) {
  Image img{width, height, {}};
  for (long p = 0; p < static_cast<long>(width) * height; ++p)
    img.rgb.insert(img.rgb.end(), {r, g, b});
  return img;
}

// a screen recording lasts as long as it was recorded: each picture holds until the next (a resized view's
// picture is scaled), frame k showing what was on screen at k / fps
TEST(Video, AScreenRecordingFollowsTheWallClock) {
  const std::string path = (std::filesystem::temp_directory_path() / ownName("rv_screen.mp4")).string();
  ScreenRecorder rec(path, 161, 120, 10); // an odd width is made even
  EXPECT_EQ(rec.width(), 160);
  rec.add(plain(161, 120, 220, 30, 30), 0.0); // red from the start
  rec.add(plain(80, 60, 30, 30, 220), 0.55);  // blue (a smaller view) from 0.55 s
  EXPECT_EQ(rec.frames(), 6);                 // frames 0..5 begin before 0.55 s
  EXPECT_EQ(rec.finish(1.0), 10);             // blue holds until the end: one second of video
  EXPECT_EQ(countFrames(path), 10);
  const auto red = frameColour(path, 5, 160, 120), blue = frameColour(path, 6, 160, 120),
             last = frameColour(path, 9, 160, 120);
  EXPECT_GT(red[0], 180);
  EXPECT_LT(red[2], 80);
  EXPECT_GT(blue[2], 180);
  EXPECT_LT(blue[0], 80);
  EXPECT_GT(last[2], 180);
  std::filesystem::remove(path);
  // nothing recorded: no file
  {
    ScreenRecorder none(path, 160, 120, 10);
    EXPECT_EQ(none.finish(2.0), 0);
  }
  EXPECT_FALSE(std::filesystem::exists(path));
}

} // namespace
} // namespace rv

namespace rv {
namespace {

// n iterates of the standard map at K = 1.3 from (th, p): its chaotic sea, coordinates in (-pi, pi]
void standardMapSea(int n, double th, double p, std::vector<double>& x, std::vector<double>& y) {
  for (int k = 0; k < n; ++k) {
    p += 1.3 * std::sin(th), th += p;
    x.push_back(std::remainder(th, 2 * std::numbers::pi)),
        y.push_back(std::remainder(p, 2 * std::numbers::pi));
  }
}

// a series of 150 000 points is thinned to one point per screen cell; the picture stays that of all points
// (the same points drawn as ten series of 15 000, which are not thinned)
// issue 61 (6): zoomed deep (the standard map near theta = pi) the ticks read "3.14159 3.14159 ..."; their
// labels now differ, and at ordinary ranges they are VTK's own
TEST(Chart, TickLabelsTellTicksApartAtAnyZoom) {
  PoincareChart chart("theta", "p");
  chart.addSeries({3.14159, 3.1416}, {0.5, 0.6}, seriesColour(0));
  auto ctx = createHeadlessContext(500, 400);
  chart.attach(ctx->window());
  const auto labels = [&](double x0, double x1) {
    chart.setRanges(x0, x1, 0, 1);
    (void)capture(ctx->window());
    vtkStringArray* l = chart.chart()->GetAxis(vtkAxis::BOTTOM)->GetTickLabels();
    std::vector<std::string> out;
    for (vtkIdType i = 0; l && i < l->GetNumberOfValues(); ++i)
      out.push_back(l->GetValue(i));
    return out;
  };
  const auto deep = labels(3.1415920, 3.1415930);
  ASSERT_GE(deep.size(), 3u);
  for (std::size_t i = 1; i < deep.size(); ++i)
    EXPECT_NE(deep[i], deep[i - 1]) << deep[i];
  const auto ordinary = labels(0, 8);
  EXPECT_EQ(std::count(ordinary.begin(), ordinary.end(), "4"), 1);
  EXPECT_EQ(chart.chart()->GetAxis(vtkAxis::BOTTOM)->GetNotation(), vtkAxis::STANDARD_NOTATION);
}

TEST(Chart, ALargeSeriesIsThinnedWithoutChangingThePicture) {
  std::vector<double> x, y;
  standardMapSea(150000, 0.1, 0.2, x, y);
  static_assert(PoincareChart::kThinAbove < 150000 && PoincareChart::kThinAbove >= 15000);
  const auto draw = [&](bool split) {
    PoincareChart chart("theta", "p");
    if (split) {
      for (int part = 0; part < 10; ++part)
        chart.addSeries({x.begin() + 15000 * part, x.begin() + 15000 * (part + 1)},
                        {y.begin() + 15000 * part, y.begin() + 15000 * (part + 1)}, seriesColour(0));
    } else {
      chart.addSeries(x, y, seriesColour(0));
    }
    chart.setRanges(-1, 1, -1.5, 0.5); // zoomed in: the thinning follows the ranges
    auto ctx = createHeadlessContext(400, 400);
    chart.attach(ctx->window());
    return capture(ctx->window());
  };
  const Image whole = draw(false), parts = draw(true);
  ASSERT_TRUE(test::isVaried(whole));
  EXPECT_LT(test::compareImages(whole, parts).meanAbs, 3.0);
  // the share of the plot the points cover (dark pixels) stays within 2.5 % of the whole picture's
  const auto covered = [](const Image& img) {
    long n = 0;
    for (std::size_t p = 0; p + 2 < img.rgb.size(); p += 3)
      n += img.rgb[p] + img.rgb[p + 1] + img.rgb[p + 2] < 600;
    return static_cast<double>(n) / (img.width * img.height);
  };
  EXPECT_NEAR(covered(whole), covered(parts), 0.025);
  EXPECT_GT(covered(whole), 0.3);
}

} // namespace
} // namespace rv

namespace rv {
namespace {

// a map filling: a series handed over as it grows (its new points thinned against the cells already taken,
// only they copied) ends as the same picture as the whole series given at once
TEST(Chart, ASeriesThatGrowsEndsAsTheWholeSeries) {
  std::vector<double> x, y;
  standardMapSea(120000, 0.3, 0.1, x, y);
  Image first, stepwise, once;
  {
    PoincareChart grown("theta", "p");
    auto ctx = createHeadlessContext(360, 360);
    grown.attach(ctx->window());
    grown.setRanges(-3, 3, -3, 3);
    const int index =
        grown.addSeries({x.begin(), x.begin() + 30000}, {y.begin(), y.begin() + 30000}, seriesColour(0));
    first = capture(ctx->window());
    for (std::ptrdiff_t n : {60000, 90000, 120000}) {
      grown.setSeries(index, {x.begin(), x.begin() + n}, {y.begin(), y.begin() + n});
      stepwise = capture(ctx->window());
    }
  }
  {
    PoincareChart whole("theta", "p");
    auto ctx = createHeadlessContext(360, 360);
    whole.attach(ctx->window());
    whole.setRanges(-3, 3, -3, 3);
    whole.addSeries(x, y, seriesColour(0));
    capture(ctx->window()); // the first frame lays the plot out (thinned for the window's size until then)
    once = capture(ctx->window());
  }
  EXPECT_GT(test::pixelsChanged(first, stepwise, 40), 500) << "the points added are drawn";
  const auto d = test::compareImages(stepwise, once);
  EXPECT_LT(d.meanAbs, 0.5);
  EXPECT_LT(d.fractionOver, 0.001);
}

// a change is pending until the next frame paints it, and that frame's own thinning (it re-sets the large
// series' data before painting) leaves nothing pending: the GUI skips the frame VTK's chart asks for after
// every change when it has painted it already
TEST(Chart, AChangeIsPendingUntilTheNextFrame) {
  std::vector<double> x, y;
  standardMapSea(60000, 0.3, 0.1, x, y);
  static_assert(PoincareChart::kThinAbove < 30000);
  PoincareChart chart("theta", "p");
  auto ctx = createHeadlessContext(300, 300);
  chart.attach(ctx->window());
  const int index =
      chart.addSeries({x.begin(), x.begin() + 30000}, {y.begin(), y.begin() + 30000}, seriesColour(0));
  EXPECT_TRUE(chart.changedSincePainted());
  capture(ctx->window());
  EXPECT_FALSE(chart.changedSincePainted());
  chart.setSeries(index, x, y); // grown: thinned again before the next frame
  EXPECT_TRUE(chart.changedSincePainted());
  capture(ctx->window());
  EXPECT_FALSE(chart.changedSincePainted());
  chart.setSeries(index, {x.begin(), x.begin() + 100}, {y.begin(), y.begin() + 100}); // a small one again
  EXPECT_TRUE(chart.changedSincePainted());
  capture(ctx->window());
  EXPECT_FALSE(chart.changedSincePainted());
}

// the gradient background is left out of a frame only when the floor covers every pixel: checked against a
// solid magenta background (not touched by the skip), which shows through wherever the floor does not reach:
// seen from above, nearly level (the horizon shows), further off, from below, and far off (its edges show)
TEST(Plane, TheBackgroundIsLeftOutOnlyWhereTheFloorFillsTheView) {
  for (const auto& [elevation, distance, fills] : {std::tuple{"30", "", true},
                                                   {"4", "", false},
                                                   {"30", "40", true},
                                                   {"-20", "", true},
                                                   {"60", "400", false}}) {
    std::vector<std::string> sets = {std::string("view.camera.elevation=") + elevation};
    if (*distance) sets.push_back(std::string("view.camera.distance=") + distance);
    const auto p = play("ellipsoid_on_plane", 2.0, sets);
    auto* plane = dynamic_cast<PlaneObject*>(p->visual->find("plane"));
    ASSERT_TRUE(plane);
    auto ctx = createHeadlessContext(480, 270);
    p->visual->addTo(ctx->window());
    vtkRenderer* r = p->visual->renderer();
    capture(ctx->window()); // lays the view out (clipping range)
    EXPECT_EQ(plane->fillsTheView(), fills) << "elevation " << elevation << ", distance " << distance;
    EXPECT_TRUE(r->GetGradientBackground()) << "restored after the frame";
    r->GradientBackgroundOff();
    r->SetBackground(1, 0, 1);
    const Image img = capture(ctx->window());
    long magenta = 0;
    for (std::size_t k = 0; k + 2 < img.rgb.size(); k += 3)
      magenta += img.rgb[k] > 240 && img.rgb[k + 1] < 15 && img.rgb[k + 2] > 240;
    EXPECT_EQ(magenta == 0, fills) << magenta << " background pixels at elevation " << elevation;
    ctx->window()->RemoveRenderer(r);
  }
}

// looking in the body's frame the camera turns with the body: the ball's middle looks the same at any time,
// while in the absolute frame it turns (the control)
TEST(BodyFrameView, TheBodyStandsStillOnScreen) {
  const auto patch = [](const Image& img) {
    Image p{.width = 40, .height = 40, .rgb = {}};
    for (int y = img.height / 2 - 20; y < img.height / 2 + 20; ++y)
      for (int x = img.width / 2 - 20; x < img.width / 2 + 20; ++x)
        for (int c = 0; c < 3; ++c)
          p.rgb.push_back(img.rgb[(std::size_t(y) * img.width + x) * 3 + c]);
    return p;
  };
  const auto at = [&](double t, const std::string& frame) {
    const auto p = play("chaplygin_ball", t, {"view.looking_in=" + frame});
    return patch(renderPlayed(*p->visual));
  };
  EXPECT_LT(test::compareImages(at(2, "body"), at(4, "body")).meanAbs, 3.0);
  EXPECT_GT(test::compareImages(at(2, "absolute"), at(4, "absolute")).meanAbs, 15.0);
}

// in a phase-space view the camera frames the growing curve until the user takes it: turned by hand, it stays
// where the user put it while the run goes on (playing), and a reset gives the framing back
TEST(Camera, TheUserKeepsTheCameraInAPhaseSpaceView) {
  const auto p = play("lorenz", 2.0);
  vtkCamera* cam = p->visual->renderer()->GetActiveCamera();
  double framed[3];
  cam->GetPosition(framed);
  p->visual->show(2.5, p->x + Eigen::Vector3d(30, 30, 30)); // the curve grows: framed again
  double grown[3];
  cam->GetPosition(grown);
  EXPECT_GT(std::abs(grown[0] - framed[0]) + std::abs(grown[1] - framed[1]) + std::abs(grown[2] - framed[2]),
            1e-6);
  cam->Azimuth(40); // the user turns it
  cam->Zoom(1.5);
  double mine[3], focal[3];
  cam->GetPosition(mine);
  cam->GetFocalPoint(focal);
  p->visual->show(3.0, p->x + Eigen::Vector3d(-40, 60, 80));
  double after[3], focalAfter[3];
  cam->GetPosition(after);
  cam->GetFocalPoint(focalAfter);
  for (int i = 0; i < 3; ++i) {
    EXPECT_EQ(after[i], mine[i]);
    EXPECT_EQ(focalAfter[i], focal[i]);
  }
  p->visual->resetCamera(); // framed again, and followed again
  double reset[3];
  cam->GetPosition(reset);
  EXPECT_GT(std::abs(reset[0] - mine[0]) + std::abs(reset[1] - mine[1]) + std::abs(reset[2] - mine[2]), 1e-6);
  p->visual->show(3.5, p->x + Eigen::Vector3d(100, 100, 100));
  double followed[3];
  cam->GetPosition(followed);
  EXPECT_GT(std::abs(followed[0] - reset[0]) + std::abs(followed[1] - reset[1]) +
                std::abs(followed[2] - reset[2]),
            1e-6);
}

// Issue 43: the camera cannot be turned under the floor -- below the plane, the next render lifts it just
// above (the same distance from what it looks at, the same side seen from above); a camera above the floor is
// left exactly where it is.
TEST(Camera, TheCameraStaysAboveTheFloor) {
  const auto p = play("ellipsoid_on_plane", 1.0);
  vtkCamera* cam = p->visual->renderer()->GetActiveCamera();
  double f[3];
  cam->GetFocalPoint(f);
  cam->SetPosition(f[0] + 3, f[1] + 1, f[2] - 2); // turned down through the floor
  const double dist = std::sqrt(3.0 * 3 + 1 + 2 * 2);
  const Image below = renderPlayed(*p->visual);
  double lifted[3];
  cam->GetPosition(lifted);
  EXPECT_GT(lifted[2], 0.0);
  EXPECT_NEAR(std::hypot(lifted[0] - f[0], lifted[1] - f[1], lifted[2] - f[2]), dist, 1e-9);
  EXPECT_NEAR(std::atan2(lifted[1] - f[1], lifted[0] - f[0]), std::atan2(1.0, 3.0), 1e-9); // the same side
  EXPECT_TRUE(test::isVaried(below)); // the body over its floor, not the underside of the plane
  cam->SetPosition(f[0] + 3, f[1] + 1, f[2] + 2);
  renderPlayed(*p->visual);
  double above[3];
  cam->GetPosition(above);
  EXPECT_EQ(above[0], f[0] + 3);
  EXPECT_EQ(above[1], f[1] + 1);
  EXPECT_EQ(above[2], f[2] + 2);
}

// a model written as equations draws its body from a mesh file (an OBJ cube) on the fixed surface its view
// names (a sphere): the surface and the body are on the picture, and a file that holds no mesh is refused
// with its name
TEST(ModelFileView, AMeshBodyOnASphere) {
  const auto dir = std::filesystem::temp_directory_path() / ownName("mesh_view");
  std::filesystem::create_directories(dir);
  {
    std::ofstream obj(dir / "cube.obj");
    obj << "v -1 -1 -1\nv 1 -1 -1\nv 1 1 -1\nv -1 1 -1\nv -1 -1 1\nv 1 -1 1\nv 1 1 1\nv -1 1 1\n"
           "f 1 4 3 2\nf 5 6 7 8\nf 1 2 6 5\nf 2 3 7 6\nf 3 4 8 7\nf 4 1 5 8\n";
    std::ofstream(dir / "broken.stl") << "solid nothing\nendsolid nothing\n";
  }
  nlohmann::json model = nlohmann::json::parse(R"json({
    "id": "cube_on_a_sphere", "parameters": {"R": 2, "s": 0.4}, "state": ["phi"], "equations": {"phi": "1"},
    "view": {"body": "mesh", "mesh": "cube.obj", "scale": "s",
             "support": {"surface": "sphere", "radius": "R"},
             "rotation": "[[cos(phi), 0, -sin(phi)], [0, 1, 0], [sin(phi), 0, cos(phi)]]",
             "position": "(R + s) * [cos(phi), 0, sin(phi)]", "contact": "R * [cos(phi), 0, sin(phi)]"}})json");
  const std::string source = (dir / "model.json").string();
  const ModelEntry& entry = modelEntryFromJson(model, source);
  const auto m = entry.create(ParameterValues(entry.info->parameters));
  const Eigen::VectorXd x0 = Eigen::VectorXd::Constant(1, 1.2);
  VisualScene visual(*m, ViewOptions{}, x0);
  ASSERT_NE(visual.find("surface"), nullptr);
  ASSERT_EQ(visual.find("plane"), nullptr);
  const Image drawn = renderPlayed(visual);
  if (const char* out = std::getenv("ROLLVIZ_TEST_OUTPUT"))
    writePng(drawn, std::string(out) + "/mesh_on_sphere.png");
  ObjectOptions hidden = visual.options().object("body");
  hidden.enabled = false;
  visual.setOptions("body", hidden);
  const Image withoutBody = renderPlayed(visual);
  EXPECT_GT(test::pixelsChanged(withoutBody, drawn, 20), 500); // the cube is there
  ObjectOptions noSurface = visual.options().object("surface");
  noSurface.enabled = false;
  visual.setOptions("surface", noSurface);
  EXPECT_GT(test::pixelsChanged(renderPlayed(visual), withoutBody, 20), 5000); // and the sphere
  model["view"]["mesh"] = "broken.stl";
  const ModelEntry& broken = modelEntryFromJson(model, source);
  const auto b = broken.create(ParameterValues(broken.info->parameters));
  try {
    VisualScene refused(*b, ViewOptions{}, x0);
    ADD_FAILURE() << "a file with no mesh was drawn";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("broken.stl: the mesh holds no triangles"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

} // namespace
} // namespace rv
