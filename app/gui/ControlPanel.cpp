#include "app/gui/ControlPanel.h"

#include "app/gui/ParameterForm.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/tools/ToolRegistry.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/ModelFile.h"
#include "scenes/SectionTextKeys.h"

#include <QComboBox>
#include <QDoubleValidator>
#include <QFormLayout>
#include <QLabel>
#include <QLineEdit>
#include <QLocale>
#include <QMenu>
#include <QPushButton>
#include <QScrollArea>
#include <QTabWidget>
#include <QToolButton>
#include <QTreeWidget>
#include <QVBoxLayout>
#include <functional>
#include <map>
#include <regex>

namespace rv {

ControlPanel::ControlPanel(QWidget* parent) : QWidget(parent) {
  auto* layout = new QVBoxLayout(this);
  tabs_ = new QTabWidget(this);
  tabs_->setObjectName("tabs");
  tabs_->setElideMode(Qt::ElideNone); // whole titles, scroll arrows when they do not fit
  tabs_->setUsesScrollButtons(true);
  // every tab by name in one menu: the tool sections make more tabs than a panel's width shows
  auto* allTabs = new QToolButton(tabs_);
  allTabs->setObjectName("all_tabs");
  allTabs->setText("\u2261");
  allTabs->setToolTip("go to a tab of the panel");
  allTabs->setPopupMode(QToolButton::InstantPopup);
  auto* tabMenu = new QMenu(allTabs);
  allTabs->setMenu(tabMenu);
  connect(tabMenu, &QMenu::aboutToShow, this, [this, tabMenu] {
    tabMenu->clear();
    for (int i = 0; i < tabs_->count(); ++i) {
      QAction* a = tabMenu->addAction(tabs_->tabText(i), this, [this, i] { tabs_->setCurrentIndex(i); });
      a->setCheckable(true);
      a->setChecked(i == tabs_->currentIndex());
    }
  });
  tabs_->setCornerWidget(allTabs, Qt::TopRightCorner);
  layout->addWidget(tabs_, 1);
  // what the problem says of the values typed (a moment of inertia that is 0, a triangle inequality broken):
  // at once, naming the tab and the field, not first at Apply
  objection_ = new QLabel(this);
  objection_->setObjectName("objection");
  objection_->setStyleSheet("color: #b00020");
  objection_->setWordWrap(true);
  objection_->hide();
  layout->addWidget(objection_);
  auto* apply = apply_ = new QPushButton("Apply", this);
  apply->setObjectName("apply");
  layout->addWidget(apply);
  setPending(false);
  connect(apply, &QPushButton::clicked, this, [this] {
    if (scene_) emit this->apply(editedDocument());
  });

  // the Tools tab: the manual's tree of tools (§2.3), each created on the scene as it is now
  auto* tools = new QWidget;
  auto* tl = new QVBoxLayout(tools);
  toolTree_ = new QTreeWidget;
  toolTree_->setHeaderLabels({"tool", "what it does"});
  std::map<std::string, QTreeWidgetItem*> items; // a parent comes before its children in the registry
  for (const auto& e : ToolRegistry::global().entries()) {
    QTreeWidgetItem* parent = e.parent.empty() ? nullptr : items.at(e.parent);
    auto* it = parent ? new QTreeWidgetItem(parent) : new QTreeWidgetItem(toolTree_);
    it->setText(0, QString::fromStdString(e.title));
    it->setText(1, QString::fromStdString(e.description));
    it->setToolTip(0, QString::fromStdString(e.description + " (" + e.reference + ")"));
    it->setToolTip(1, it->toolTip(0));
    it->setData(0, Qt::UserRole, QString::fromStdString(e.id));
    items[e.id] = it;
  }
  toolTree_->expandAll();
  toolTree_->resizeColumnToContents(0);
  // the selected tool's whole description under the tree (its column is cut off in a narrow panel)
  auto* about = new QLabel;
  about->setObjectName("tool_about");
  about->setWordWrap(true);
  about->setTextInteractionFlags(Qt::TextSelectableByMouse);
  connect(toolTree_, &QTreeWidget::currentItemChanged, about, [about](QTreeWidgetItem* it) {
    about->setText(it ? it->text(0) + ": " + it->toolTip(0) : QString());
  });
  auto* createButton = new QPushButton("Create");
  createButton->setObjectName("create");
  createButton->setToolTip("start the selected tool on the scene (its settings: the tabs of the fixed-point "
                           "family, and the scene's sections)");
  tl->addWidget(toolTree_, 1);
  tl->addWidget(about);
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
  setPending(false); // the values shown are the scene's
  objection_->hide();
  // the tab shown stays shown when the scene runs again (Apply on the Method tab stays there)
  const QString shown = tabs_->count() > 0 ? tabs_->tabText(tabs_->currentIndex()) : QString();
  while (tabs_->count() > 0) {
    QWidget* w = tabs_->widget(0);
    tabs_->removeTab(0);
    if (w != toolsTab_) w->deleteLater();
  }
  forms_.clear();
  // a tab: optional fields above the form of a parameter table
  const auto add = [&](const std::string& key, const QString& title, const ParameterTable& table,
                       const ParameterValues& values, QWidget* chooser = nullptr) {
    auto* form = new ParameterForm(table);
    connect(form, &ParameterForm::rejected, this, &ControlPanel::message);
    connect(form, &ParameterForm::edited, this, [this] {
      refreshPending();
      checkProblem();
    });
    form->setValues(values);
    auto* scroll = new QScrollArea;
    scroll->setWidget(form);
    scroll->setWidgetResizable(true);
    scroll->setHorizontalScrollBarPolicy(Qt::ScrollBarAlwaysOff); // the form fits the panel's width
    QWidget* tab = scroll;
    if (chooser) {
      tab = new QWidget;
      auto* l = new QVBoxLayout(tab);
      l->setContentsMargins(0, 4, 0, 0);
      l->addWidget(chooser);
      l->addWidget(scroll, 1);
    }
    tabs_->addTab(tab, title);
    forms_.emplace_back(key, form);
    return scroll;
  };
  auto* problems = new QComboBox;
  problems->setObjectName("problem_choice");
  for (const auto& e : ModelRegistry::global().entries()) {
    problems->addItem(QString::fromStdString(e.info->id));
    problems->setItemData(problems->count() - 1, QString::fromStdString(e.info->title), Qt::ToolTipRole);
  }
  for (const ModelEntry* e : loadedModelFiles()) // the model files opened so far join the list
    if (!modelFileOf(*e).empty() && problems->findText(QString::fromStdString(e->info->id)) < 0) {
      problems->addItem(QString::fromStdString(e->info->id));
      problems->setItemData(problems->count() - 1,
                            QString::fromStdString(e->info->title + " (" + modelFileOf(*e) + ")"),
                            Qt::ToolTipRole);
    }
  if (problems->findText(QString::fromStdString(scene.model->info().id)) < 0) { // an inline model
    problems->addItem(QString::fromStdString(scene.model->info().id));
    problems->setItemData(problems->count() - 1, QString::fromStdString(scene.model->info().title),
                          Qt::ToolTipRole);
  }
  problems->setCurrentText(QString::fromStdString(scene.model->info().id));
  problems->setToolTip("the problem: choosing another opens its default scene");
  connect(problems, &QComboBox::activated, this, [this, problems](int i) {
    const std::string id = problems->itemText(i).toStdString();
    if (scene_ && id != scene_->model->info().id) emit problemChosen(id);
  });
  add("problem", "Problem", scene.model->info().parameters, scene.model->parameters(), problems);
  methodBox_ = nullptr, methodScroll_ = nullptr;
  method_ = scene.integratorEntry->id;
  if (!scene.model->isMap()) { // an explicit map is iterated: no method to choose
    methodBox_ = new QComboBox;
    methodBox_->setObjectName("method_choice");
    for (const auto& e : IntegratorRegistry::global().entries()) {
      methodBox_->addItem(QString::fromStdString(e.id));
      methodBox_->setItemData(methodBox_->count() - 1,
                              QString::fromStdString(e.title + " (" + e.reference + ")"), Qt::ToolTipRole);
    }
    methodBox_->setCurrentText(QString::fromStdString(method_));
    methodBox_->setToolTip("the integration method (manual §2.2); Apply runs the scene with it");
    connect(methodBox_, &QComboBox::activated, this,
            [this](int i) { chooseMethod(methodBox_->itemText(i).toStdString()); });
    methodScroll_ =
        add("method", "Method", *scene.integratorEntry->parameters, *scene.integratorParameters, methodBox_);
  }
  tabs_->addTab(toolsTab_, "Tools");
  choosers_.clear();
  numbers_.clear();
  for (const auto& t : toolSections()) {
    if (t.table->size() == 0) continue; // text keys only (the diagram's): the tool's chart window picks them
    const auto& section = scene.document.value(t.key, nlohmann::json::object());
    auto* above = new QWidget;
    auto* fields = new QFormLayout(above);
    fields->setContentsMargins(4, 0, 4, 0);
    // a choice among `ids` for text key `key` ("": the scene's default), the scene's value shown
    const auto choice = [&](const std::string& key, const std::vector<std::string>& ids,
                            const std::string& tip) {
      auto* chooser = new QComboBox;
      chooser->setObjectName(QString::fromStdString(t.key + "_" + key));
      chooser->addItem("");
      for (const auto& id : ids)
        chooser->addItem(QString::fromStdString(id));
      if (section.contains(key) && section[key].is_string())
        chooser->setCurrentText(QString::fromStdString(section[key].get<std::string>()));
      chooser->setToolTip(QString::fromStdString(key + ": " + tip));
      connect(chooser, &QComboBox::activated, this, &ControlPanel::refreshPending);
      choosers_.emplace_back(t.key + "." + key, chooser);
      fields->addRow(QString::fromStdString(key), chooser);
    };
    // the observable a section names (the Poincare section, the spectrum's function): a flow's observables
    if (!t.observableKey.empty() && !scene.model->isMap()) {
      std::vector<std::string> ids;
      for (const auto& o : scene.model->observables())
        ids.push_back(o.id);
      choice(t.observableKey, ids, "the observable of " + t.title);
    }
    // its settings that are no numbers of its table (continuation.parameter and .to), as the scene loader
    // declares them: a problem's parameter chosen, a number typed (empty: not set)
    for (const auto& k : sectionTextKeys(t.key, false)) {
      if (k.parameter) {
        std::vector<std::string> ids;
        for (const auto& spec : scene.model->info().parameters.specs())
          ids.push_back(spec.id);
        choice(k.key, ids, k.description);
      } else if (k.type == "number") {
        auto* edit = new QLineEdit;
        edit->setObjectName(QString::fromStdString(t.key + "_" + k.key));
        auto* valid = new QDoubleValidator(edit);
        valid->setLocale(QLocale::c());
        edit->setValidator(valid);
        if (section.contains(k.key) && section[k.key].is_number())
          edit->setText(QString::number(section[k.key].get<double>(), 'g', 17));
        edit->setPlaceholderText("not set");
        edit->setToolTip(QString::fromStdString(k.key + ": " + k.description));
        connect(edit, &QLineEdit::textEdited, this, &ControlPanel::refreshPending);
        numbers_.emplace_back(t.key + "." + k.key, edit);
        fields->addRow(QString::fromStdString(k.key), edit);
      }
    }
    if (fields->rowCount() == 0) delete above, above = nullptr;
    add(t.key, QString::fromStdString(t.title), *t.table, scene.tool(t.key), above);
  }
  for (int i = 0; i < tabs_->count(); ++i)
    if (tabs_->tabText(i) == shown) tabs_->setCurrentIndex(i);
}

bool ControlPanel::chooseMethod(const std::string& id) {
  const IntegratorEntry* entry = nullptr;
  for (const auto& e : IntegratorRegistry::global().entries())
    if (e.id == id) entry = &e;
  if (!entry || !scene_ || !methodScroll_) return false;
  if (id == method_) return true;
  method_ = id;
  methodBox_->setCurrentText(QString::fromStdString(id));
  // the scene's own values for its method, the table's defaults for another
  auto* form = new ParameterForm(*entry->parameters);
  connect(form, &ParameterForm::rejected, this, &ControlPanel::message);
  connect(form, &ParameterForm::edited, this, &ControlPanel::refreshPending);
  form->setValues(id == scene_->integratorEntry->id ? *scene_->integratorParameters
                                                    : ParameterValues(*entry->parameters));
  methodScroll_->setWidget(form); // deletes the old form
  for (auto& [key, f] : forms_)
    if (key == "method") f = form;
  refreshPending();
  return true;
}

QString ControlPanel::objection() const {
  return objection_->text();
}

void ControlPanel::checkProblem() {
  QString said;
  if (const ParameterForm* problem = form("problem"); problem && scene_) {
    try {
      scene_->modelEntry->create(problem->values()); // the problem's own checks: one definition
    } catch (const std::exception& e) {
      said = "Problem tab, " + QString::fromStdString(e.what()) + " (Apply refuses these values)";
    }
  }
  objection_->setText(said);
  objection_->setVisible(!said.isEmpty());
}

QString ControlPanel::inPanelWords(const std::string& error, const std::string& source) {
  // "SOURCE:section.key: why" (the scene loader's words) -> "TAB tab, key: why"
  std::string rest = error;
  if (!source.empty() && rest.rfind(source + ":", 0) == 0) rest = rest.substr(source.size() + 1);
  static const std::regex where(R"(^([a-z_]+)(?:\.([A-Za-z0-9_]+))?: (.*)$)");
  std::smatch m;
  if (!std::regex_match(rest, m, where)) return QString::fromStdString(error);
  const std::string section = m[1].str();
  std::string tab;
  if (section == "parameters")
    tab = "Problem";
  else if (section == "integrator")
    tab = "Method";
  else if (const ToolSection* t = findToolSection(section))
    tab = t->title;
  else
    return QString::fromStdString(error); // not a tab's value (the initial state, the view): as it is
  return QString::fromStdString(tab + " tab, " + (m[2].matched ? m[2].str() + ": " : "") + m[3].str());
}

void ControlPanel::refreshPending() {
  // pending while what Apply would run differs from the scene: a value put back to the scene's is not
  setPending(scene_ && editedDocument() != scene_->document);
}

void ControlPanel::setPending(bool pending) {
  pending_ = pending;
  QFont font = apply_->font();
  font.setBold(pending);
  apply_->setFont(font);
  apply_->setText(pending ? "Apply ●" : "Apply");
  apply_->setToolTip(pending ? "Run the scene with the changed values (in bold): they wait for Apply"
                             : "Run the scene again with these values");
}

nlohmann::json ControlPanel::editedDocument() const {
  nlohmann::json doc = scene_->document;
  if (method_ != scene_->integratorEntry->id) // another method: the old one's settings do not apply
    doc["integrator"] = {{"method", method_}};
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
  const auto split = [](const std::string& path) {
    return std::pair{path.substr(0, path.find('.')), path.substr(path.find('.') + 1)};
  };
  for (const auto& [path, chooser] : choosers_) {
    const auto [section, key] = split(path);
    const std::string chosen = chooser->currentText().toStdString();
    const auto& old = scene_->document.value(section, nlohmann::json::object());
    if (!chosen.empty() && old.value(key, std::string()) != chosen) doc[section][key] = chosen;
  }
  for (const auto& [path, edit] : numbers_) {
    const auto [section, key] = split(path);
    const auto& old = scene_->document.value(section, nlohmann::json::object());
    const QString typed = edit->text().trimmed();
    bool ok = false;
    const double value = QLocale::c().toDouble(typed, &ok);
    if (typed.isEmpty()) { // cleared: not set
      if (old.contains(key)) doc[section].erase(key);
    } else if (ok && (!old.contains(key) || !old[key].is_number() || old[key].get<double>() != value)) {
      doc[section][key] = value;
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
