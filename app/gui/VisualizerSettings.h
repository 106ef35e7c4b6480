// VisualizerSettings.h -- the visualizer's settings panel (manual §2.4.6): tab "objects" (enabled, colour,
// transparency, grid density, trace enabled, trace colour of the chosen object) and tab "axis" (style, ticks
// and subticks, range min / max, numbers of tickmarks and subticks). It edits plain ViewOptions; the main
// window applies them to the scene and keeps them for re-runs.
#pragma once
#include "render/ViewOptions.h"

#include <QWidget>
#include <string>
#include <vector>

class QCheckBox;
class QComboBox;
class QDoubleSpinBox;
class QPushButton;
class QSlider;
class QSpinBox;

namespace rv {

class VisualizerSettings : public QWidget {
  Q_OBJECT
public:
  explicit VisualizerSettings(QWidget* parent = nullptr);
  /// The objects to offer and the options they show now.
  void setObjects(const std::vector<std::string>& names, const ViewOptions& options);
  /// Selects an object in the list (tests, and the toolbar).
  void selectObject(const std::string& name);
  /// Sets the chosen object's colour as if picked in the colour dialog.
  void pickColour(const Rgb& colour);
  QComboBox* objectBox() const { return object_; }
  QCheckBox* enabledBox() const { return enabled_; }
  QSlider* transparencySlider() const { return transparency_; }
  QComboBox* axesStyleBox() const { return axesStyle_; }

signals:
  void objectEdited(const std::string& name, const ObjectOptions& options);
  void axesEdited(const AxesOptions& axes);

private:
  void showObject();
  void emitObject();
  void emitAxes();
  ViewOptions options_;
  bool blocked_ = false;
  QComboBox* object_;
  QCheckBox *enabled_, *trace_;
  QPushButton *colour_, *traceColour_;
  QSlider* transparency_;
  QDoubleSpinBox* density_;
  QComboBox* axesStyle_;
  QCheckBox* ticks_;
  std::vector<QDoubleSpinBox*> min_, max_;
  QCheckBox* autoRange_;
  QSpinBox *tickmarks_, *subticks_;
};

/// "#rrggbb" of a colour, for buttons and scene files.
std::string colourText(const Rgb& c);

} // namespace rv
