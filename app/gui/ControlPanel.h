// ControlPanel.h -- the control panel (manual §2.1): tabs generated from the parameter tables of the problem,
// the integration method and the fixed-point family of tools; Apply re-runs the scene with the edited values
// (only the fields the user touched are written into the scene document).
#pragma once
#include "scenes/Scene.h"

#include <QWidget>
#include <nlohmann/json.hpp>
#include <vector>

class QTabWidget;

namespace rv {

class ParameterForm;

class ControlPanel : public QWidget {
  Q_OBJECT
public:
  explicit ControlPanel(QWidget* parent = nullptr);
  /// Rebuilds the tabs for a scene (which must outlive the next setScene).
  void setScene(const Scene& scene);
  /// The scene's document with the edits applied.
  nlohmann::json editedDocument() const;
  /// The form of a tab: "problem", "method" or a tool section key (for tests).
  ParameterForm* form(const std::string& key) const;

signals:
  /// Apply was pressed: the document to run.
  void apply(const nlohmann::json& document);

private:
  QTabWidget* tabs_;
  const Scene* scene_ = nullptr;
  std::vector<std::pair<std::string, ParameterForm*>> forms_;
};

} // namespace rv
