#include "app/gui/ControlPanel.h"

#include "app/gui/ParameterForm.h"
#include "dynamics/tools/ToolSettings.h"

#include <QPushButton>
#include <QScrollArea>
#include <QTabWidget>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <functional>

namespace rv {

ControlPanel::ControlPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  tabs_ = new QTabWidget(this);
  tabs_->setObjectName("tabs");
  layout->addWidget(tabs_, 1);
  auto* apply = new QPushButton("Apply", this);
  apply->setObjectName("apply");
  apply->setToolTip("Run the scene again with these values");
  layout->addWidget(apply);
  connect(apply, &QPushButton::clicked, this, [this] {
    if (scene_) emit this->apply(editedDocument());
  });

  // the Tools tab: the manual's tree of tools (§2.3), each created on the scene as it is now
  auto* tools = new QWidget;
  auto* tl = new QVBoxLayout(tools);
  toolTree_ = new QTreeWidget;
  toolTree_->setHeaderLabels({"tool", "what it does"});
  struct Node {
    const char *id, *title, *tip;
    std::vector<Node> children;
  };
  const std::vector<Node> tree = {
      {"poincare",
       "Poincaré map",
       "a trajectory from the scene's initial point on the map window",
       {{"spectrum", "Fourier spectrum", "of spectrum.function along the trajectory (a chart window)", {}},
        {"lyapunov", "Lyapunov exponents", "against time (a chart window)", {}},
        {"map3d", "Map3D", "the map in three dimensions (a chart window)", {}},
        {"plot", "2D / 3D plot", "observables of the plot section against each other (a chart window)", {}}}},
      {"fixedpoint",
       "Fixed points",
       "Newton (or gradient) search from fixedpoint.guess; the path on the map",
       {{"continuation", "Continuation", "the family in continuation.parameter up to continuation.to", {}},
        {"separatrix", "Separatrices", "the four branches at the fixed point", {}},
        {"bifurcation_tree", "Bifurcation tree", "period doublings along the continuation", {}}}},
      {"surface", "Surface |Map(x) - x|", "on the grid section's rectangle (a chart window)", {}},
      {"ram", "Region of allowed motion", "on the grid section's rectangle (a chart window)", {}},
      {"diagram", "Topological analysis", "the bifurcation diagram on the plane of first integrals", {}}};
  const std::function<void(QTreeWidgetItem*, const Node&)> addNode = [&](QTreeWidgetItem* parent,
                                                                         const Node& n) {
    auto* it = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(toolTree_);
    it->setText(0, n.title);
    it->setText(1, n.tip);
    it->setToolTip(0, n.tip);
    it->setData(0, Qt::UserRole, QString(n.id));
    for (const auto& c : n.children)
      addNode(it, c);
  };
  for (const auto& n : tree)
    addNode(nullptr, n);
  toolTree_->expandAll();
  toolTree_->resizeColumnToContents(0);
  auto* createButton = new QPushButton("Create");
  createButton->setObjectName("create");
  createButton->setToolTip("start the selected tool on the scene (its settings: the tabs of the fixed-point "
                           "family, and the scene's sections)");
  tl->addWidget(toolTree_, 1);
  tl->addWidget(createButton);
  const auto createSelected = [this] {
    if (const auto* it = toolTree_->currentItem())
      emit create(it->data(0, Qt::UserRole).toString().toStdString());
  };
  connect(createButton, &QPushButton::clicked, this, createSelected);
  connect(toolTree_, &QTreeWidget::itemDoubleClicked, this, createSelected);
  toolsTab_ = tools;
}

void ControlPanel::selectTool(const std::string& id) {
  for (QTreeWidgetItemIterator it(toolTree_); *it; ++it)
    if ((*it)->data(0, Qt::UserRole).toString().toStdString() == id) toolTree_->setCurrentItem(*it);
}

void ControlPanel::setScene(const Scene& scene) {
  scene_ = &scene;
  while (tabs_->count() > 0) {
    QWidget* w = tabs_->widget(0);
    tabs_->removeTab(0);
    if (w != toolsTab_) w->deleteLater();
  }
  forms_.clear();
  const auto add = [&](const std::string& key, const QString& title, const ParameterTable& table,
                       const ParameterValues& values) {
    auto* form = new ParameterForm(table);
    form->setValues(values);
    auto* scroll = new QScrollArea;
    scroll->setWidget(form);
    scroll->setWidgetResizable(true);
    tabs_->addTab(scroll, title);
    forms_.emplace_back(key, form);
  };
  add("problem", "Problem", scene.model->info().parameters, scene.model->parameters());
  add("method", "Method", *scene.integratorEntry->parameters, *scene.integratorParameters);
  tabs_->addTab(toolsTab_, "Tools");
  for (const auto& t : toolSections())
    add(t.key, QString::fromStdString(t.title), *t.table, scene.tool(t.key));
}

nlohmann::json ControlPanel::editedDocument() const {
  nlohmann::json doc = scene_->document;
  for (const auto& [key, form] : forms_) {
    const ParameterValues v = form->values();
    const std::string section = key == "problem" ? "parameters" : key == "method" ? "integrator" : key;
    for (const auto& id : form->touched()) {
      const auto& spec = form->table().specs()[form->table().find(id)];
      if (!spec.choices.empty())
        doc[section][id] = v.choice(id);
      else
        doc[section][id] = v[id];
    }
  }
  return doc;
}

ParameterForm* ControlPanel::form(const std::string& key) const {
  for (const auto& [k, f] : forms_)
    if (k == key) return f;
  return nullptr;
}

} // namespace rv
