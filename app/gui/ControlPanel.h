// ControlPanel.h -- the control panel (manual §2.1): tabs generated from the parameter tables of the problem
// (with the choice of problem), the integration method (with the choice of method) and the fixed-point family
// of tools; Apply re-runs the scene with the edited values (only the fields the user touched are written into
// the scene document; a newly chosen method replaces the scene's integrator section).
#pragma once
#include "scenes/Scene.h"

#include <QWidget>
#include <nlohmann/json.hpp>
#include <vector>

class QComboBox;
class QLineEdit;
class QPushButton;
class QLabel;
class QScrollArea;
class QTabWidget;

namespace rv {

class ParameterForm;
}
class QTreeWidget;
namespace rv {

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

  /// The manual's tool tree (Tools tab), ids as the `create` signal gives them: poincare > spectrum,
  /// lyapunov, map3d; fixedpoint > continuation, separatrix, bifurcation_tree; surface; ram; diagram.
  QTreeWidget* toolTree() const { return toolTree_; }
  /// Selects a tool of the tree by id (tests).
  void selectTool(const std::string& id);
  /// Chooses the integration method: the Method tab shows its parameters (their defaults) and Apply runs
  /// the scene with it. False for an unknown id.
  bool chooseMethod(const std::string& id);
  /// The method Apply uses.
  const std::string& method() const { return method_; }
  /// Whether values were changed since the scene was set: they wait for Apply (which then shows bold with a
  /// dot, and the changed fields' labels bold).
  bool pending() const { return pending_; }
  /// What the problem objects to in the values typed (its tab and field named; empty: nothing), shown above
  /// Apply as soon as a value changes.
  QString objection() const;
  /// A scene loader's refusal ("FILE:section.key: why") in the panel's words: "TAB tab, key: why" when the
  /// value is one of a tab's; else as it is.
  static QString inPanelWords(const std::string& error, const std::string& source);

signals:
  /// Apply was pressed: the document to run.
  void apply(const nlohmann::json& document);
  /// Create was pressed on a tool of the tree.
  void create(const std::string& tool);
  /// Another problem was chosen in the Problem tab (its default scene should open).
  void problemChosen(const std::string& problem);
  /// Something typed was refused (a parameter form's rejected()).
  void message(const QString& text);

private:
  void setPending(bool pending);
  void refreshPending();
  void checkProblem();
  QLabel* objection_ = nullptr;
  bool pending_ = false;
  QPushButton* apply_ = nullptr;
  QTabWidget* tabs_;
  QTreeWidget* toolTree_;
  QWidget* toolsTab_;
  const Scene* scene_ = nullptr;
  std::string method_;
  QComboBox* methodBox_ = nullptr;
  QScrollArea* methodScroll_ = nullptr;
  std::vector<std::pair<std::string, ParameterForm*>> forms_;
  /// "section.key" and its chooser: an observable or a parameter a section names ("": the scene's default)
  std::vector<std::pair<std::string, QComboBox*>> choosers_;
  std::vector<std::pair<std::string, QLineEdit*>> numbers_; ///< "section.key" and the number typed there
};

} // namespace rv
