// PoincareChart.h -- the Poincare map as a VTK chart (manual §2.4.1), and the plane of any point or curve
// plot (multipliers, bifurcation diagrams: ToolCharts.h): one coloured point series per
// trajectory, the selected one drawn larger, axes named after the map coordinates. Rendered in any render
// window (on screen through QtVtkWidget, headless through a HeadlessContext).
#pragma once
#include "render/ViewOptions.h"
#include "render/charts/Chart.h"

#include <array>
#include <string>
#include <vector>
#include <vtkSmartPointer.h>

class vtkChartXY;
class vtkPlot;
class vtkContextView;
class vtkRenderWindow;

namespace rv {

class PoincareChart final : public Chart {
public:
  PoincareChart(const std::string& xTitle, const std::string& yTitle);
  ~PoincareChart() override;
  /// Series with more points than this are thinned to what the screen can show (see LargeSeries): drawing
  /// 10^5 markers costs ~100 ms on software GL, thinning them a few.
  static constexpr std::size_t kThinAbove = 20000;
  /// Adds a trajectory's points (x[i], y[i]); returns its index.
  int addSeries(const std::vector<double>& x, const std::vector<double>& y, const Rgb& colour);
  /// Adds points drawn as large crosses, whatever is selected (a found fixed point: a marker of its own, not
  /// one more trajectory's dot); setSeries fills it as any series. Returns its index.
  int addMarkers(const std::vector<double>& x, const std::vector<double>& y, const Rgb& colour);
  /// Adds a curve through (x[i], y[i]), broken where a value is NaN; returns the index of its first piece.
  int addCurve(const std::vector<double>& x, const std::vector<double>& y, const Rgb& colour,
               float width = 2);
  /// A heat map of values on a regular grid (x fastest: values[j * nx + i] at (x0 + i dx, y0 + j dy)), each
  /// value filling the cell centred on its node, coloured from `low` (at the smallest value) to `high`; NaN
  /// is drawn transparent. A colour bar with the values' scale stands right of the plot.
  void addImage(int nx, int ny, double x0, double dx, double y0, double dy, const std::vector<double>& values,
                const Rgb& low, const Rgb& high);
  /// The label drawn over the point under the cursor (its series and coordinates); off, nothing of the cursor
  /// is drawn into the chart (and so into its exports).
  void setPointLabel(bool on);
  /// Fixes the axes' ranges (otherwise they follow the data).
  void setRanges(double x0, double x1, double y0, double y1);
  /// The axes' ranges now: x0, x1, y0, y1.
  std::array<double, 4> ranges() const;
  /// Keeps the axes where they are now (new data no longer rescales them; zoom and pan still move them).
  void holdRanges();
  /// Whether the axes are held (a zoom, a pan, setRanges, holdRanges) rather than following the data.
  bool rangesHeld() const;
  /// Ranges around every point drawn now, held; the axes follow the data again while there is none.
  void fitToData();
  /// Recolours series `index`.
  void setColour(int index, const Rgb& colour);
  /// Replaces the points of series `index`.
  void setSeries(int index, const std::vector<double>& x, const std::vector<double>& y);
  /// Names the axes.
  void setTitles(const std::string& x, const std::string& y);
  /// The title over the chart (the tool's name).
  void setTitle(const std::string& title);
  /// Names series `index` in the chart's legend (shown once a series has a name; unnamed ones are left out).
  void setLegend(int index, const std::string& name);
  /// How the legend orders its entries, in words ("largest first"; empty: as they were added): what a front
  /// end that reads the legend's numbers out says with them.
  void setLegendOrder(std::string order) { legendOrder_ = std::move(order); }
  const std::string& legendOrder() const { return legendOrder_; }
  /// Puts the legend in the plot area's top left corner (the default is the top right).
  void legendTopLeft();
  /// Removes every series.
  void clear();
  /// Map coordinates of a point of the scene (pixels from the bottom left); false outside the plot area.
  bool toChart(double px, double py, double& x, double& y) const override;
  /// The pixel (from the bottom left) of chart point (x, y); false outside the plot area.
  bool toPixels(double x, double y, double& px, double& py) const;
  /// Draws series `index` emphasised (-1: none).
  void select(int index);
  /// The series drawn emphasised (-1: none).
  int selected() const { return selected_; }
  /// Before each frame: tick labels with as many digits as the ranges need to tell ticks apart (called by
  /// the renderer's StartEvent; public for tests).
  void fitTickDigits();
  /// Draws into `window` (the chart's view takes it over).
  void attach(vtkRenderWindow* window) override;
  void writeCsv(std::ostream& out) const override;
  /// The size of points (pixels; the selected series twice as big).
  void setMarkerSize(float size);
  /// Equal units per pixel on both axes (the manual's "hold proportions"): the shorter range is widened.
  void setEqualAspect(bool equal) { equalAspect_ = equal; }
  vtkChartXY* chart() const;
  /// Whether something changed since the chart was last painted (its scene is dirty).
  bool changedSincePainted() const;

private:
  std::string legendOrder_;
  vtkSmartPointer<vtkContextView> view_;
  vtkSmartPointer<vtkChartXY> chart_;
  /// Series too big to draw point by point on software GL: redrawn as one point per occupied cell of the
  /// screen (cells of about a marker), recomputed whenever the ranges or the plot's size change.
  struct LargeSeries {
    vtkPlot* plot;
    int index;
    std::vector<double> x, y;
    std::array<std::size_t, 4> extremes; ///< the indices of the smallest and largest x and y
    // the thinning: for which ranges, plot size and marker its cells are, the cells taken, the points kept,
    // and how many of x, y it has seen
    std::array<double, 7> grid{};
    std::vector<unsigned char> taken;
    std::vector<double> kx, ky;
    std::size_t thinned = 0;
  };
  void thinLargeSeries();
  /// A series' points: all of them, or for a large one its extremes until thinLargeSeries runs.
  void setPoints(vtkPlot* plot, int index, const std::vector<double>& x, const std::vector<double>& y);
  std::vector<LargeSeries> large_;
  int selected_ = -1;
  std::vector<int> markers_; ///< addMarkers' series: their size is their own
  float markerSize_ = 3;
  bool equalAspect_ = false;
};

/// Distinct colours for successive trajectories.
Rgb seriesColour(int index);

} // namespace rv
