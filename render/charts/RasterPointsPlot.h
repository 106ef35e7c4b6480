// RasterPointsPlot.h -- a scatter plot whose markers are splatted into one picture on the CPU and drawn as a
// single textured quad. Software GL (llvmpipe) pays ~0.8 us of setup per point sprite: the ~6·10^4 markers a
// Poincaré map of 10^6 points keeps after thinning cost ~50 ms a frame in a 320 x 400 map window as sprites,
// a few ms as a raster. Markers are crisp: a square, or a disk of the marker's diameter. Points coloured by
// scalars, or with other marker styles, or into a vector figure (render/export/Figure.h), are drawn by
// vtkPlotPoints.
#pragma once
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlotPoints.h>

namespace rv {

class RasterPointsPlot : public vtkPlotPoints {
public:
  static RasterPointsPlot* New();
  vtkTypeMacro(RasterPointsPlot, vtkPlotPoints);
  bool Paint(vtkContext2D* painter) override;

protected:
  RasterPointsPlot() = default;
  ~RasterPointsPlot() override = default;

private:
  vtkNew<vtkImageData>
      image_; ///< the splatted picture, kept between frames (reallocated when the size changes)
  RasterPointsPlot(const RasterPointsPlot&) = delete;
  void operator=(const RasterPointsPlot&) = delete;
};

} // namespace rv
