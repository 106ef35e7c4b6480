// ViewOptions.h -- appearance of a visual scene as plain data (no VTK): what a scene file's "view"
// section holds and what the GUI edits. Options are kept per object name so they survive a re-run.
#pragma once
#include <array>
#include <map>
#include <optional>
#include <string>

namespace rv {

using Rgb = std::array<double, 3>;

/// Parses "#rrggbb"; returns nothing when the text is not such a colour.
std::optional<Rgb> parseColour(const std::string& text);

/// How a surface is drawn (manual §2.4.6 toolbar: grid, fill, both).
enum class SurfaceStyle { Fill, Grid, Both };

/// Appearance of one visual object.
struct ObjectOptions {
  bool enabled = true;
  std::optional<Rgb> colour; ///< nothing: the object's default
  std::optional<double>
      opacity; ///< 1 - transparency; nothing: the object's default (opaque but for the unit sphere)
  SurfaceStyle style = SurfaceStyle::Fill;
  std::optional<Rgb> traceColour; ///< for objects that leave a trace
  double lineWidth = 3.0;         ///< traces, in pixels
  bool trace = true;              ///< apexes: leave a trace ("with trace") or not ("without trace")
  double gridDensity = 1;         ///< grid lines (plane cells, surface grid) per the object's default spacing
  std::string texture;            ///< "" the object's own, "none" plain colour, or a PNG file's path
  std::optional<std::array<double, 3>> size;   ///< the body's box: edge lengths along the body's axes
  std::optional<std::array<double, 3>> vector; ///< the arbitrary vector at t = 0, in the frame looked in
};

/// What the 3D view shows: the motion of the body in space, or the apexes on the unit sphere (manual §2.4.5).
enum class ViewKind { Motion, Apex };
/// The apex view's frame (manual: Looking in): the fixed frame, or the body's.
enum class LookingIn { Absolute, Body };

/// The scene's coordinate axes (manual §2.4.6 toolbar and "axis" tab).
struct AxesOptions {
  enum class Style { None, Normal, Box } style = Style::None;
  bool ticks = true;                        ///< ticks and subticks with numbers
  std::optional<std::array<double, 3>> min; ///< range; nothing: what is drawn
  std::optional<std::array<double, 3>> max;
  int tickmarks = 5; ///< major ticks per axis
  int subticks = 4;  ///< minor ticks between two major ones
};

/// Camera placement relative to the body (or to the scene's centre when there is none).
struct CameraOptions {
  bool follow = true;    ///< keep the body in view as it rolls
  double distance = 0;   ///< 0: frame the body automatically
  double elevation = 30; ///< degrees above the plane
  double azimuth = -60;  ///< degrees around the vertical
};

/// Everything a visual scene needs besides the model.
struct ViewOptions {
  std::map<std::string, ObjectOptions> objects; ///< by object name: "ball", "plane", "trace", ...
  CameraOptions camera;
  bool overlay = true; ///< time and energy-error text
  double speed = 1.0;  ///< simulation seconds per wall-clock (or video) second
  long maxTracePoints = 1000000;
  int multisamples = 0; ///< MSAA samples of the window (0: off; costly on software GL, see tests/bench)
  ViewKind kind = ViewKind::Motion;
  LookingIn lookingIn = LookingIn::Absolute;
  AxesOptions axes;
  const ObjectOptions& object(const std::string& name) const;
};

/// The window options of a 2D / 3D plot filter (manual §2.4.1-§2.4.2).
struct PlotChartOptions {
  std::array<std::optional<double>, 6>
      range;                    ///< x_min, x_max, y_min, y_max, z_min, z_max; nothing: the data's
  bool holdProportions = false; ///< equal scales on the axes
  float pointSize = 4;          ///< small 2, middle 4, big 7 pixels
};

} // namespace rv
