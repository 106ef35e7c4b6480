// MainWindow.h -- the main window of the skeleton GUI: the 3D view of a scene with play / pause, reset and
// speed. The motion is integrated on a TrajectoryStream thread; the GUI thread only draws.
#pragma once
#include "dynamics/jobs/TrajectoryStream.h"
#include "render/VisualScene.h"
#include "scenes/Scene.h"

#include <nlohmann/json.hpp>

#include <QElapsedTimer>
#include <QMainWindow>
#include <QTimer>
#include <memory>

class QAction;
class QDoubleSpinBox;
class QLabel;

namespace rv {

class QtVtkWidget;
class MapPanel;
class ControlPanel;
class ToolManager;

class MainWindow : public QMainWindow {
  Q_OBJECT
public:
  explicit MainWindow(QWidget* parent = nullptr);
  ~MainWindow() override;
  /// Loads a scene file and starts it; on failure shows why and keeps the current scene.
  bool openScene(const QString& path);
  /// Runs a scene document (the control panel's edits); on failure shows why and keeps the current scene.
  bool runDocument(const nlohmann::json& document);
  /// Simulation time shown in the last frame.
  double shownTime() const { return shownTime_; }
  QtVtkWidget* view() const { return view_; }
  MapPanel* mapPanel() const { return map_; }
  ControlPanel* controlPanel() const { return control_; }
  ToolManager* toolManager() const { return tools_; }
  const Scene* scene() const { return scene_.get(); }

public slots:
  void togglePlay();
  void restart();
  void snapshot();
  void openDialog();

private:
  void tick();
  void showStatus();
  /// Replaces the running scene (from `source`, a file or "edited").
  void useScene(std::unique_ptr<Scene> scene, const QString& source);
  QtVtkWidget* view_;
  MapPanel* map_;
  ControlPanel* control_;
  ToolManager* tools_;
  QAction* playAction_;
  QDoubleSpinBox* speedBox_;
  QLabel* status_;
  QTimer timer_;
  QElapsedTimer clock_;
  QString scenePath_;
  // destroyed in reverse order: the stream's thread stops before the scene it integrates goes away
  std::unique_ptr<Scene> scene_;
  std::unique_ptr<VisualScene> visual_;
  std::unique_ptr<TrajectoryStream> stream_;
  TrajectoryStream::Batch batch_;
  double requested_ = 0, shownTime_ = 0;
  bool playing_ = true;
  QString error_;
};

} // namespace rv
