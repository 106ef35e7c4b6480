// Chart3D.h -- a 3D point chart (manual: Map3D, the 3D plot filter): coloured point series in a box with
// titled, ticked axes (SceneAxesObject), turned with the mouse like the 3D view.
#pragma once
#include "render/charts/Chart.h"
#include "render/objects/SceneAxesObject.h"

#include <array>
#include <memory>
#include <string>
#include <vector>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

namespace rv {

class Chart3D final : public Chart {
public:
  explicit Chart3D(std::array<std::string, 3> titles);
  ~Chart3D() override;
  /// Adds points (x[i], y[i], z[i]) in one colour; returns its index.
  int addSeries(const std::vector<double>& x, const std::vector<double>& y, const std::vector<double>& z,
                const Rgb& colour, float pointSize = 3);
  /// Replaces the points of series `index` (a live window: the box follows the data; the actors are rebuilt
  /// before the next frame).
  void setSeries(int index, const std::vector<double>& x, const std::vector<double>& y,
                 const std::vector<double>& z);
  /// Draws series `index` emphasised, its points twice as big (-1: none).
  void select(int index);
  /// Recolours series `index`.
  void setColour(int index, const Rgb& colour);
  /// Fixes the box (otherwise it is the data's bounds); nothing in an entry keeps the data's value there.
  void setRanges(const std::array<std::optional<double>, 6>& range);
  /// Draws x, y and z at one scale (a cube of data is a cube) or each filling the box.
  void setEqualScales(bool equal) { equal_ = equal; }
  void attach(vtkRenderWindow* window) override;
  void writeCsv(std::ostream& out) const override;
  vtkRenderer* renderer() const { return renderer_; }
  /// The box drawn, after attach and as of the last frame: x_min, x_max, y_min, ... in data units.
  const std::array<double, 6>& bounds() const { return bounds_; }

private:
  std::array<std::string, 3> titles_;
  struct Series {
    std::vector<double> x, y, z;
    Rgb colour;
    float size;
  };
  std::vector<Series> series_;
  std::array<std::optional<double>, 6> range_;
  std::array<double, 6> bounds_{};
  bool equal_ = false;
  bool dirty_ = false;
  int selected_ = -1; ///< series changed since the actors were built
  std::array<double, 3> boxSize_{1, 1, 1};
  void rebuild();
  vtkSmartPointer<vtkRenderer> renderer_;
  std::unique_ptr<SceneAxesObject> axes_;
};

} // namespace rv
