// VectorPictures.h -- the pictures inside charts (a 2-D sweep's cells, a coloured map's cells, a colour bar)
// carried into vector figures. VTK draws them as textures; its GL2PS exporter (render/export/Figure.h) drops
// a texture from an SVG and misplaces one given in data coordinates in a PDF. While a vector figure is
// captured these items draw their pictures as filled rectangles instead -- one per run of equal colour along
// a row -- which both formats carry as shapes, crisp at any zoom.
#pragma once
#include <vtkChartHistogram2D.h>
#include <vtkColorLegend.h>
#include <vtkPlotHistogram2D.h>
#include <vtkRect.h>

class vtkContext2D;
class vtkImageData;

namespace rv {

/// Whether a vector figure (GL2PS) is being captured now.
bool capturingVectorFigure();

/// Draws an RGBA (or RGB) unsigned-char picture into `rect` (the painter's coordinates) as filled rectangles,
/// merging runs of one colour along its rows; fully transparent pixels are left out. Returns how many
/// rectangles it drew.
long drawPictureAsRectangles(vtkContext2D* painter, const vtkRectf& rect, vtkImageData* picture);

/// vtkPlotHistogram2D whose cells go into vector figures as rectangles.
class CellsPlot : public vtkPlotHistogram2D {
public:
  static CellsPlot* New();
  vtkTypeMacro(CellsPlot, vtkPlotHistogram2D);
  bool Paint(vtkContext2D* painter) override;

protected:
  CellsPlot() = default;
  ~CellsPlot() override = default;

private:
  CellsPlot(const CellsPlot&) = delete;
  void operator=(const CellsPlot&) = delete;
};

/// vtkColorLegend whose colour bar goes into vector figures as rectangles.
class VectorColourLegend : public vtkColorLegend {
public:
  static VectorColourLegend* New();
  vtkTypeMacro(VectorColourLegend, vtkColorLegend);
  bool Paint(vtkContext2D* painter) override;

protected:
  VectorColourLegend() = default;
  ~VectorColourLegend() override = default;

private:
  VectorColourLegend(const VectorColourLegend&) = delete;
  void operator=(const VectorColourLegend&) = delete;
};

/// vtkChartHistogram2D with the two above as its plot and its legend.
class CellsChart : public vtkChartHistogram2D {
public:
  static CellsChart* New();
  vtkTypeMacro(CellsChart, vtkChartHistogram2D);

protected:
  CellsChart();
  ~CellsChart() override = default;

private:
  CellsChart(const CellsChart&) = delete;
  void operator=(const CellsChart&) = delete;
};

} // namespace rv
