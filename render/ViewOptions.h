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
std::optional<Rgb> parseColor(const std::string& text);

/// How a surface is drawn (manual §2.4.6 toolbar: grid, fill, both).
enum class SurfaceStyle { Fill, Grid, Both };

/// Appearance of one visual object.
struct ObjectOptions {
  bool enabled = true;
  std::optional<Rgb> color; ///< nothing: the object's default
  double opacity = 1.0;     ///< 1 - transparency
  SurfaceStyle style = SurfaceStyle::Fill;
  std::optional<Rgb> traceColor; ///< for objects that leave a trace
  double lineWidth = 3.0;        ///< traces, in pixels
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
  const ObjectOptions& object(const std::string& name) const;
};

} // namespace rv
