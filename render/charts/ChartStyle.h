// ChartStyle.h -- how a chart is dressed for its figure: the screen's style, or a paper's -- white, black
// axes and text, the sizes of a 3.5-inch journal column at 300 dpi -- at a scale (N x the pixels with text,
// pens and markers N x as large: the same picture, finer). Applied to the 2-D charts a window draws after
// they are attached, so every chart view gets it without knowing of it.
#pragma once
#include <string>
#include <utility>
#include <vector>

class vtkAxis;
class vtkRenderWindow;
class vtkTextProperty;
class vtkTextActor;

namespace rv {

struct ChartStyle {
  bool paper = false; ///< the print style (else the screen's)
  int scale = 1;      ///< pixels, text and pens x scale (1..8)
};

/// The style named on a command line or in Python: "screen" or "paper"; InputError naming `what` otherwise.
ChartStyle chartStyle(const std::string& name, int scale, const std::string& what);
/// The figure's size in pixels: `size` (the screen style's default, or given) x scale; the paper style's
/// default is a 3.5 x 2.6-inch column figure at 300 dpi (1050 x 788) when `sizeGiven` is false.
std::pair<int, int> figureSize(const ChartStyle& style, std::pair<int, int> size, bool sizeGiven);
/// Restyles every 2-D chart drawn in `window` (the charts of its context scenes): fonts, pens and markers
/// x scale; paper: black axes, ticks and text, a faint grid, a column's type sizes.
void styleCharts(vtkRenderWindow* window, const ChartStyle& style);

/// A larger picture of a window as it stands (a GUI's 2x / 4x save): while it lives, every chart's type,
/// pens, markers and distances are `scale` x as large and its ticks those of the last render (the screen's),
/// a 3D view's text in display pixels (the time line) is `scale` x as large and as far from its corner, and
/// so are the scene axes' numbers and titles;
/// when it goes, everything is as it was. Nothing for scale 1.
class ScaledPicture {
public:
  ScaledPicture(vtkRenderWindow* window, int scale);
  ~ScaledPicture();
  ScaledPicture(const ScaledPicture&) = delete;
  ScaledPicture& operator=(const ScaledPicture&) = delete;

private:
  vtkRenderWindow* window_;
  int scale_;
  std::vector<vtkAxis*> frozen_; ///< the axes whose ticks it froze
  struct Text {
    vtkTextActor* actor;
    int fontSize;
    double x, y;
  };
  std::vector<Text> texts_;                                 ///< the text actors it scaled, as they were
  std::vector<std::pair<vtkTextProperty*, int>> axisTexts_; ///< the 3D axes' text, with its font size
};

} // namespace rv
