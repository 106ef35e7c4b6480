// WebPage.h -- a motion as one self-contained HTML page: the visual scene is played as for a video (every
// integrator step feeds the traces, frame k shows the state at exactly t0 + k * speed / fps), and what each
// of its actors shows is recorded -- meshes, materials and textures once, matrices and the camera per frame,
// growing traces as their final vertices with the count shown at each frame -- then written beside the
// viewer (three.js, embedded: render/export/WebAssets.h) so that the page plays, turns and scrubs in any
// browser with no network. The format of the embedded data is in render/export/web/page.js.
#pragma once
#include "dynamics/integrators/Integrator.h"
#include "render/ViewOptions.h"

#include <functional>
#include <optional>
#include <string>
#include <utility>
#include <vector>

namespace rv {

class VisualScene;

/// A set of points of a 2D map drawn beside the 3D view (a session's Poincare map).
struct PageMapSeries {
  enum class Kind { Points, Curve, Markers };
  Kind kind = Kind::Points;
  std::vector<double> x, y;
  Rgb colour{0, 0, 1};
};

/// A session's map: its axes' names and what is drawn on it.
struct PageMap {
  std::string xName, yName;
  std::vector<PageMapSeries> series;
};

struct PageSpec {
  std::string path;                                            ///< the .html file to write
  std::string title, description;                              ///< shown above the view
  std::vector<std::pair<std::string, std::string>> parameters; ///< the parameters' names and values
  std::vector<std::string> variables;                          ///< the state's names (each frame's state)
  int fps = 25;                                                ///< frames per second of playback at 1x
  double duration = 10;                                        ///< seconds of playback at 1x
  double speed = 1;                                            ///< simulation seconds per second of playback
  std::optional<PageMap> map;
};

/// Records round(duration * fps) + 1 frames (the last at t0 + duration * speed) of `scene` driven by
/// `integrator` and writes the page whole or not at all (a temporary name, renamed). `progress(done,
/// total)` returning false cancels: nothing is written. Returns the frames written (0 when cancelled).
/// InputError for a path that cannot be written; ComputationError when the run fails.
long writeWebPage(VisualScene& scene, Integrator& integrator, const PageSpec& spec,
                  const std::function<bool(long, long)>& progress = {});

} // namespace rv
