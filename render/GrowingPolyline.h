// GrowingPolyline.h -- a line that grows by appending points in place (no rebuild per frame), simplified as
// it grows so that long traces stay cheap to draw, with a cap on the number of vertices kept. The
// simplification is a streaming form of Douglas & Peucker (Cartographica 10(2), 1973): a point is dropped
// while the chord from the last kept vertex to the newest point passes within `tolerance` of every point
// dropped since; a smooth curve of radius r then keeps one vertex per ~sqrt(8 r tolerance) of its length.
//
// On top of that, a screen-space level of detail: before each frame the size of a pixel at the line's nearest
// point is measured, and of the settled part of the line (all but the newest kLodHead segments, which stay
// exact) only the segments that reach a cell (a cube of at most 1.5 pixels; smaller for lines under 3 pixels
// wide) no earlier segment reached are drawn; translucent lines are drawn whole. A dense scribble (the
// rattleback's traces after 10^6 steps: 1.2·10^5 segments in a blob of a few hundred pixels) then draws fewer
// segments than it covers pixels (1.0·10^4); a segment left out lies within a cell's diagonal of drawn
// ones of the same colour and width, so the picture is the same within the image tolerance
// (tests/render/ViewTest.cpp). Zooming in shrinks the cells and brings segments back; every vertex is kept.
#pragma once
#include "render/ViewOptions.h"

#include <Eigen/Core>
#include <cstdint>
#include <unordered_set>
#include <vector>

#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

class vtkActor;
class vtkObject;
class vtkPolyData;
class vtkRenderer;

namespace rv {

class GrowingPolyline {
public:
  /// tolerance: how far the drawn line may pass from a dropped point (0 keeps every point); the newest point
  /// is always the line's end. asPoints: draw every appended point as a dot, unconnected (the iterates of a
  /// map).
  GrowingPolyline(double tolerance, long maxPoints, bool asPoints = false);
  ~GrowingPolyline();
  GrowingPolyline(const GrowingPolyline&) = delete;
  GrowingPolyline& operator=(const GrowingPolyline&) = delete;
  /// Draws in `renderer`; the level of detail follows its camera (one renderer at a time).
  void attach(vtkRenderer* renderer);
  void setAppearance(const Rgb& colour, double lineWidth, double opacity, bool visible);
  void append(double x, double y, double z);
  void clear();
  /// Vertices of the simplified line (all of them, drawn or not).
  long size() const;
  /// Vertex i (0 <= i < size()).
  Eigen::Vector3d vertex(long i) const;
  /// Segments drawn in the last frame (size() - 1 with the level of detail off).
  long segmentsDrawn() const;
  /// Turns the screen-space level of detail off (every segment drawn) or on (the default).
  void setLevelOfDetail(bool on);
  vtkActor* actor() const;

  /// The newest segments always drawn, unfiltered.
  static constexpr long kLodHead = 1024;

private:
  bool chordPassesNearDropped(const Eigen::Vector3d& end) const;
  /// Called before each frame: measures the pixel and refilters when its cell size changed.
  void beforeFrame();
  /// Filters the settled segments from settled_ on at the current cell size and rebuilds the drawn cells.
  void settle(bool all);
  void rebuildCells();
  double tolerance_;
  long maxPoints_;
  bool asPoints_;
  Eigen::Vector3d anchor_ = Eigen::Vector3d::Zero();      ///< the last vertex that stays
  Eigen::Vector3d provisional_ = Eigen::Vector3d::Zero(); ///< the newest point, the line's end
  std::vector<Eigen::Vector3d> samples_; ///< points dropped since the anchor, every tolerance / 2
  vtkSmartPointer<vtkPolyData> data_;
  vtkSmartPointer<vtkActor> actor_;

  // level of detail
  bool lod_ = true;
  double cell_ = 0;                         ///< about 1.5 pixels at the line (0: every segment drawn)
  std::unordered_set<std::uint64_t> cells_; ///< cells reached by the drawn settled segments
  std::vector<long> kept_;                  ///< settled segments drawn: segment i joins vertices i, i + 1
  long settled_ = 0;                        ///< segments before this one are settled and filtered
  vtkWeakPointer<vtkRenderer> renderer_;    ///< the renderer whose camera the level of detail follows
  unsigned long observer_ = 0;
};

} // namespace rv
