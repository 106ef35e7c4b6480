#include "app/gui/VisualizerSettings.h"

#include <QCheckBox>
#include <QColorDialog>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSlider>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>
#include <cmath>
#include <cstdio>

namespace rv {

std::string colourText(const Rgb& c) {
  char s[8];
  std::snprintf(s, sizeof s, "#%02x%02x%02x", int(std::lround(255 * c[0])), int(std::lround(255 * c[1])),
                int(std::lround(255 * c[2])));
  return s;
}

namespace {
void paintButton(QPushButton* b, const std::optional<Rgb>& c) {
  b->setText(c ? QString::fromStdString(colourText(*c)) : "default");
  b->setStyleSheet(c ? QString("background: %1").arg(QString::fromStdString(colourText(*c))) : QString());
}
std::optional<Rgb> askColour(QWidget* parent, const std::optional<Rgb>& now) {
  const QColor start = now ? QColor::fromRgbF((*now)[0], (*now)[1], (*now)[2]) : QColor(Qt::white);
  const QColor c = QColorDialog::getColor(start, parent, "Colour");
  if (!c.isValid()) return std::nullopt;
  return Rgb{c.redF(), c.greenF(), c.blueF()};
}
} // namespace

VisualizerSettings::VisualizerSettings(QWidget* parent) : QWidget(parent) {
  auto* tabs = new QTabWidget(this);
  auto* layout = new QVBoxLayout(this);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(tabs);

  auto* objects = new QWidget;
  auto* of = new QFormLayout(objects);
  object_ = new QComboBox;
  enabled_ = new QCheckBox;
  colour_ = new QPushButton("default");
  transparency_ = new QSlider(Qt::Horizontal);
  transparency_->setRange(0, 100);
  density_ = new QDoubleSpinBox;
  density_->setRange(0.05, 20);
  density_->setSingleStep(0.25);
  trace_ = new QCheckBox;
  traceColour_ = new QPushButton("default");
  of->addRow("Object", object_);
  of->addRow("Enabled", enabled_);
  of->addRow("Object colour", colour_);
  auto* transparencyRow = new QWidget;
  auto* tr = new QHBoxLayout(transparencyRow);
  tr->setContentsMargins(0, 0, 0, 0);
  tr->addWidget(transparency_, 1);
  auto* percent = new QLabel("0 %");
  percent->setObjectName("transparency_value");
  percent->setMinimumWidth(percent->fontMetrics().horizontalAdvance("100 %"));
  tr->addWidget(percent);
  connect(transparency_, &QSlider::valueChanged, percent,
          [percent](int v) { percent->setText(QString("%1 %").arg(v)); });
  of->addRow("Transparency", transparencyRow);
  of->addRow("Grid density", density_);
  of->addRow("Trace enabled", trace_);
  of->addRow("Trace colour", traceColour_);
  enabled_->setToolTip("show or hide the object");
  transparency_->setToolTip("0: opaque, 100: invisible");
  density_->setToolTip("how often the grid (texture) repeats, relative to the object's own");
  trace_->setToolTip(
      "the trace of the object (apexes: with or without trace; bodies: the contact's trace on them)");
  tabs->addTab(objects, "objects");

  auto* axis = new QWidget;
  auto* af = new QFormLayout(axis);
  axesStyle_ = new QComboBox;
  axesStyle_->addItems({"none", "normal", "box"});
  ticks_ = new QCheckBox;
  ticks_->setChecked(true);
  autoRange_ = new QCheckBox;
  autoRange_->setChecked(true);
  autoRange_->setToolTip("the region the scene is drawn in; clear it to give the range");
  af->addRow("Axes", axesStyle_);
  af->addRow("Draw ticks and subticks", ticks_);
  af->addRow("Range from the scene", autoRange_);
  for (auto* list : {&min_, &max_}) {
    auto* row = new QWidget;
    auto* h = new QHBoxLayout(row);
    h->setContentsMargins(0, 0, 0, 0);
    for (int i = 0; i < 3; ++i) {
      auto* b = new QDoubleSpinBox;
      b->setRange(-1e6, 1e6);
      b->setDecimals(3);
      b->setValue(list == &min_ ? -1 : 1);
      h->addWidget(b);
      list->push_back(b);
      connect(b, &QDoubleSpinBox::valueChanged, this, [this] { emitAxes(); });
    }
    af->addRow(list == &min_ ? "Range min (x, y, z)" : "Range max (x, y, z)", row);
  }
  tickmarks_ = new QSpinBox;
  tickmarks_->setRange(1, 50);
  tickmarks_->setValue(5);
  subticks_ = new QSpinBox;
  subticks_->setRange(0, 20);
  subticks_->setValue(4);
  af->addRow("Number of tickmarks", tickmarks_);
  af->addRow("Number of subticks", subticks_);
  tabs->addTab(axis, "axis");

  connect(object_, &QComboBox::currentIndexChanged, this, [this] { showObject(); });
  connect(enabled_, &QCheckBox::toggled, this, [this] { emitObject(); });
  connect(trace_, &QCheckBox::toggled, this, [this] { emitObject(); });
  connect(transparency_, &QSlider::valueChanged, this, [this] { emitObject(); });
  connect(density_, &QDoubleSpinBox::valueChanged, this, [this] { emitObject(); });
  connect(colour_, &QPushButton::clicked, this, [this] {
    if (const auto c = askColour(this, options_.object(object_->currentText().toStdString()).colour))
      pickColour(*c);
  });
  connect(traceColour_, &QPushButton::clicked, this, [this] {
    const std::string name = object_->currentText().toStdString();
    if (const auto c = askColour(this, options_.object(name).traceColour)) {
      options_.objects[name] = options_.object(name);
      options_.objects[name].traceColour = c;
      paintButton(traceColour_, c);
      emitObject();
    }
  });
  connect(axesStyle_, &QComboBox::currentIndexChanged, this, [this] { emitAxes(); });
  connect(ticks_, &QCheckBox::toggled, this, [this] { emitAxes(); });
  connect(autoRange_, &QCheckBox::toggled, this, [this] { emitAxes(); });
  connect(tickmarks_, &QSpinBox::valueChanged, this, [this] { emitAxes(); });
  connect(subticks_, &QSpinBox::valueChanged, this, [this] { emitAxes(); });
}

void VisualizerSettings::setObjects(const std::vector<std::string>& names, const ViewOptions& options) {
  blocked_ = true;
  options_ = options;
  const QString current = object_->currentText();
  object_->clear();
  for (const auto& n : names)
    if (n != "scene_axes") object_->addItem(QString::fromStdString(n));
  if (const int i = object_->findText(current); i >= 0) object_->setCurrentIndex(i);
  const AxesOptions& a = options.axes;
  axesStyle_->setCurrentIndex(static_cast<int>(a.style));
  ticks_->setChecked(a.ticks);
  autoRange_->setChecked(!a.min || !a.max);
  for (int i = 0; i < 3; ++i) {
    if (a.min) min_[i]->setValue((*a.min)[i]);
    if (a.max) max_[i]->setValue((*a.max)[i]);
  }
  tickmarks_->setValue(a.tickmarks);
  subticks_->setValue(a.subticks);
  blocked_ = false;
  showObject();
}

void VisualizerSettings::selectObject(const std::string& name) {
  object_->setCurrentText(QString::fromStdString(name));
}

void VisualizerSettings::pickColour(const Rgb& colour) {
  const std::string name = object_->currentText().toStdString();
  options_.objects[name] = options_.object(name);
  options_.objects[name].colour = colour;
  paintButton(colour_, colour);
  emitObject();
}

void VisualizerSettings::showObject() {
  const bool wasBlocked = blocked_; // (called inside setObjects, which must stay blocked to its end)
  blocked_ = true;
  const ObjectOptions& o = options_.object(object_->currentText().toStdString());
  enabled_->setChecked(o.enabled);
  trace_->setChecked(o.trace);
  transparency_->setValue(static_cast<int>(std::lround(100 * (1 - o.opacity.value_or(1.0)))));
  density_->setValue(o.gridDensity);
  paintButton(colour_, o.colour);
  paintButton(traceColour_, o.traceColour);
  blocked_ = wasBlocked;
}

void VisualizerSettings::emitObject() {
  if (blocked_ || object_->currentIndex() < 0) return;
  const std::string name = object_->currentText().toStdString();
  ObjectOptions o = options_.object(name);
  o.enabled = enabled_->isChecked();
  o.trace = trace_->isChecked();
  if (transparency_->value() > 0 || o.opacity) o.opacity = 1 - transparency_->value() / 100.0;
  o.gridDensity = density_->value();
  options_.objects[name] = o;
  emit objectEdited(name, o);
}

void VisualizerSettings::emitAxes() {
  if (blocked_) return;
  AxesOptions a;
  a.style = static_cast<AxesOptions::Style>(axesStyle_->currentIndex());
  a.ticks = ticks_->isChecked();
  if (!autoRange_->isChecked()) {
    std::array<double, 3> lo{}, hi{};
    for (int i = 0; i < 3; ++i)
      lo[i] = min_[i]->value(), hi[i] = std::max(max_[i]->value(), lo[i] + 1e-9);
    a.min = lo, a.max = hi;
  }
  a.tickmarks = tickmarks_->value();
  a.subticks = subticks_->value();
  options_.axes = a;
  emit axesEdited(a);
}

} // namespace rv
