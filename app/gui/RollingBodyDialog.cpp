#include "app/gui/RollingBodyDialog.h"

#include "dynamics/io/AtomicFile.h"
#include "scenes/ModelFile.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QDir>
#include <QDoubleSpinBox>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QLineEdit>
#include <QPushButton>
#include <QVBoxLayout>
#include <fstream>

namespace rv {

namespace {
QDoubleSpinBox* number(QWidget* parent, const QString& name, double value, double min = -1e6) {
  auto* box = new QDoubleSpinBox(parent);
  box->setObjectName(name);
  box->setDecimals(6);
  box->setRange(min, 1e6);
  box->setValue(value);
  return box;
}
} // namespace

RollingBodyDialog::RollingBodyDialog(QWidget* parent, std::function<void(const QString&)> open)
    : QDialog(parent), id_(new QLineEdit("my_body", this)), surface_(new QLineEdit(this)),
      file_(new QLineEdit(this)), shape_(new QComboBox(this)), contact_(new QComboBox(this)),
      bound_(number(this, "size", 1, 1e-9)), mass_(number(this, "mass", 1, 1e-9)),
      friction_(number(this, "friction", 0.3, 0)), gravity_(number(this, "gravity", 1, 0)),
      axis_(new QCheckBox("body axis 3 is an axis of symmetry (axis_up; Jellett's integral for a sphere)",
                          this)),
      error_(new QLabel(this)), open_(std::move(open)) {
  setWindowTitle("New rolling body");
  const RollingBodyForm defaults;
  id_->setObjectName("id");
  surface_->setObjectName("F");
  surface_->setText("x^4 + y^4 + z^4 + 0.5*(x^2 + y^2 + z^2) - 1.5");
  file_->setObjectName("file");
  file_->setText(QDir::current().filePath("my_body.json"));
  shape_->setObjectName("shape");
  shape_->addItems({"sphere", "ellipsoid", "paraboloid", "disk", "implicit"});
  shape_->setCurrentText(QString::fromStdString(defaults.shape));
  contact_->setObjectName("contact");
  contact_->addItems({"marble", "rubber", "sliding"});
  contact_->setToolTip("marble: rolling without slipping; rubber: also without spinning about the normal; "
                       "sliding: viscous friction at the contact (the tippe top)");
  axis_->setObjectName("axis");
  error_->setObjectName("error");
  error_->setWordWrap(true);
  error_->setStyleSheet("color: #b00020");

  auto* form = new QFormLayout;
  form->addRow("Name", id_);
  form->addRow("Shape", shape_);
  for (std::size_t i = 0; i < 3; ++i) {
    sizes_[i] = number(this, QString("size%1").arg(i + 1), defaults.sizes[i], 1e-9);
    sizeLabels_[i] = new QLabel(this);
    form->addRow(sizeLabels_[i], sizes_[i]);
  }
  form->addRow("F(x, y, z) = 0, F < 0 inside", surface_);
  form->addRow("Bounding size", bound_);
  const auto row = [&](const QString& label, std::array<QDoubleSpinBox*, 3>& boxes, const QString& name,
                       const std::array<double, 3>& values, double min) {
    auto* line = new QHBoxLayout;
    for (std::size_t i = 0; i < 3; ++i) {
      boxes[i] = number(this, QString("%1%2").arg(name).arg(i + 1), values[i], min);
      line->addWidget(boxes[i]);
    }
    form->addRow(label, line);
  };
  row("Shape's centre from the centre of mass", centre_, "centre", defaults.centre, -1e6);
  form->addRow("Mass", mass_);
  row("Central principal moments", inertia_, "I", defaults.inertia, 1e-9);
  form->addRow("Contact", contact_);
  form->addRow("Friction μ (sliding)", friction_);
  form->addRow("Gravity g", gravity_);
  form->addRow(axis_);
  auto* fileLine = new QHBoxLayout;
  fileLine->addWidget(file_);
  auto* browse = new QPushButton("Browse…", this);
  fileLine->addWidget(browse);
  form->addRow("Model file", fileLine);
  connect(browse, &QPushButton::clicked, this, [this] {
    const QString path = QFileDialog::getSaveFileName(this, "Write the rolling model to", file_->text(),
                                                      "Model files (*.json)");
    if (!path.isEmpty()) file_->setText(path);
  });

  auto* buttons = new QDialogButtonBox(QDialogButtonBox::Cancel, this);
  auto* createButton = buttons->addButton("Create and open", QDialogButtonBox::AcceptRole);
  createButton->setObjectName("create");
  connect(buttons, &QDialogButtonBox::accepted, this, [this] { create(); });
  connect(buttons, &QDialogButtonBox::rejected, this, &QDialog::reject);
  auto* layout = new QVBoxLayout(this);
  auto* intro = new QLabel("Describe the body; rollviz derives its equations (docs/rolling.md). Every number "
                           "becomes a parameter of the model.",
                           this);
  intro->setWordWrap(true);
  layout->addWidget(intro);
  layout->addLayout(form);
  layout->addWidget(error_);
  layout->addWidget(buttons);
  connect(shape_, &QComboBox::currentTextChanged, this, [this] { showShape(); });
  connect(contact_, &QComboBox::currentTextChanged, this,
          [this](const QString& c) { friction_->setEnabled(c == "sliding"); });
  friction_->setEnabled(false);
  showShape();
}

void RollingBodyDialog::showShape() {
  const QString s = shape_->currentText();
  const std::array<QString, 3> labels =
      s == "ellipsoid" ? std::array<QString, 3>{"Semi-axis 1", "Semi-axis 2", "Semi-axis 3"}
      : s == "paraboloid"
          ? std::array<QString, 3>{"p (curvature radius, axis 1)", "q (curvature radius, axis 2)", ""}
      : s == "implicit" ? std::array<QString, 3>{"", "", ""}
                        : std::array<QString, 3>{"Radius", "", ""};
  for (std::size_t i = 0; i < 3; ++i) {
    sizeLabels_[i]->setText(labels[i]);
    sizeLabels_[i]->setVisible(!labels[i].isEmpty());
    sizes_[i]->setVisible(!labels[i].isEmpty());
  }
  surface_->setEnabled(s == "implicit");
  bound_->setEnabled(s == "implicit");
}

RollingBodyForm RollingBodyDialog::form() const {
  RollingBodyForm f;
  f.id = id_->text().trimmed().toStdString();
  f.shape = shape_->currentText().toStdString();
  f.contact = contact_->currentText().toStdString();
  f.surface = surface_->text().toStdString();
  f.size = bound_->value();
  for (std::size_t i = 0; i < 3; ++i) {
    f.sizes[i] = sizes_[i]->value();
    f.centre[i] = centre_[i]->value();
    f.inertia[i] = inertia_[i]->value();
  }
  f.mass = mass_->value();
  f.friction = friction_->value();
  f.gravity = gravity_->value();
  f.symmetryAxis = axis_->isChecked();
  return f;
}

bool RollingBodyDialog::create() {
  const QString path = file_->text().trimmed();
  try {
    if (!path.endsWith(".json", Qt::CaseInsensitive)) throw InputError("the model file's name ends in .json");
    const std::string text = rollingModelDocument(form()).dump(2) + "\n";
    modelEntryFromJson(nlohmann::json::parse(text), path.toStdString()); // the body must make a model
    AtomicFile out(path.toStdString(), "the model file");
    {
      std::ofstream f(out.tempPath());
      f << text;
      if (!f) throw InputError(path.toStdString() + ": cannot be written");
    }
    out.commit();
  } catch (const std::exception& e) {
    error_->setText(QString::fromStdString(e.what()));
    return false;
  }
  error_->clear();
  accept();
  if (open_) open_(path);
  return true;
}

} // namespace rv
