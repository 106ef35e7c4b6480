#include "app/gui/ControlPanel.h"

#include "app/gui/ParameterForm.h"
#include "dynamics/tools/ToolSettings.h"

#include <QPushButton>
#include <QScrollArea>
#include <QTabWidget>
#include <QVBoxLayout>

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
}

void ControlPanel::setScene(const Scene& scene) {
  scene_ = &scene;
  while (tabs_->count() > 0) {
    QWidget* w = tabs_->widget(0);
    tabs_->removeTab(0);
    w->deleteLater();
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
