// Map3DWindow.h -- the Map3D window of a 3D map (manual §2.1: the full map beside its projection): a 3D
// chart with one series per trajectory of the map window, in the trajectories' order and colours, fed with
// their points as they come. The map window owns it; the window itself is made when first opened.
#pragma once
#include <array>
#include <memory>
#include <string>
#include <vector>

class QWidget;

namespace rv {

class Chart3D;
class QtVtkWidget;

class Map3DWindow {
public:
  /// A trajectory's points on the map: its three coordinates (z may lag behind x and y: then not drawn yet).
  struct Track {
    const std::vector<double>* x;
    const std::vector<double>* y;
    const std::vector<double>* z;
  };
  explicit Map3DWindow(QWidget* parent);
  ~Map3DWindow();
  Map3DWindow(const Map3DWindow&) = delete;
  Map3DWindow& operator=(const Map3DWindow&) = delete;

  /// Opens (or shows) the window with axes `names`, drawing `tracks`; returns it.
  QWidget* open(const std::array<std::string, 3>& names, const std::vector<Track>& tracks);
  /// Whether the chart exists (the window was opened for the current map).
  bool open() const { return chart_ != nullptr; }
  /// Whether the window shows now.
  bool visible() const;
  /// Drops the chart (the trajectories changed order or the map was replaced); the window hides unless
  /// `keepShown` (the caller opens it again at once).
  void reset(bool keepShown);
  /// Draws the tracks' points (new tracks get a series in the next colour).
  void feed(const std::vector<Track>& tracks);
  /// Emphasises track `index` (-1: none).
  void select(int index);
  /// Points drawn (tests).
  long points() const;

private:
  QWidget* parent_;
  QWidget* window_ = nullptr;
  QtVtkWidget* view_ = nullptr;
  std::unique_ptr<Chart3D> chart_;
  std::size_t series_ = 0; ///< tracks the chart has a series for
  long points_ = 0;
};

} // namespace rv
