#include "app/gui/RollingBodyDialog.h"

#include "dynamics/core/ExplainsNonFinite.h"
#include "dynamics/io/AtomicFile.h"
#include "scenes/ModelFile.h"

#include <Eigen/Dense>
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
#include <map>
#include <memory>

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

/// The body must roll from the start the form writes: its field finite there. Not so, say, for a body flatter
/// than its bowl where it touches it (a brick's faces are flatter than any bowl), or for one sliding that the
/// support would have to pull, whose run would stop at once: said here instead, naming why.
void checkStart(const ModelEntry& entry) {
  const ParameterValues defaults(entry.info->parameters);
  // interpreted: a check starts no native compilation (the window's run of the file does)
  const std::shared_ptr<const EquationSystem> system = equationSystemOf(entry);
  const std::unique_ptr<Model> model = system ? system->create(defaults) : entry.create(defaults);
  const Eigen::VectorXd x = model->stateFromNamed(
      modelFileInitial(entry).at("state").get<std::map<std::string, double>>(), "initial.state");
  Eigen::VectorXd f(x.size());
  model->rhs(x.data(), f.data());
  if (f.allFinite()) return;
  const auto* explains = dynamic_cast<const ExplainsNonFinite*>(model.get());
  const std::string cause = explains ? explains->nonFiniteCause(x.data()) : "";
  throw InputError(
      "the body cannot roll from its start (tilted on top of the support, or at the bottom of the bowl)" +
      (cause.find("flatter_than_the_support") != std::string::npos
           ? std::string(": there it is flatter than the bowl, so it would touch it along a curve; a larger "
                         "bowl, or a more curved body, rolls")
       : cause.find("definitions.leaves_the_") != std::string::npos
           ? std::string(": started so, sliding, it would have to be pulled onto what it slides on (the "
                         "normal force would be negative)")
           : std::string()) +
      (cause.empty() ? "" : " (" + cause + ")"));
}
} // namespace

RollingBodyDialog::RollingBodyDialog(QWidget* parent, std::function<void(const QString&)> open)
    : QDialog(parent), rows_(new QFormLayout), id_(new QLineEdit("my_body", this)),
      surface_(new QLineEdit(this)), profile_(new QLineEdit(this)), file_(new QLineEdit(this)),
      supportSurface_(new QLineEdit(QString::fromStdString(RollingBodyForm{}.supportSurface), this)),
      shape_(new QComboBox(this)), contact_(new QComboBox(this)), support_(new QComboBox(this)),
      side_(new QComboBox(this)), exponent_(number(this, "exponent", RollingBodyForm{}.exponent, 2)),
      bulge_(number(this, "bulge", RollingBodyForm{}.bulge, 0)), bound_(number(this, "size", 1, 1e-9)),
      mass_(number(this, "mass", 1, 1e-9)), friction_(number(this, "friction", 0.3, 0)),
      gravity_(number(this, "gravity", 1, 0)), heightsRow_(new QWidget(this)),
      profileSquared_(new QCheckBox("the expression is ρ(z)² (smooth at a rounded pole)", this)),
      axis_(new QCheckBox("body axis 3 is an axis of symmetry (axis_up; Jellett's integral for a sphere)",
                          this)),
      error_(new QLabel(this)), open_(std::move(open)) {
  setWindowTitle("New rolling body");
  const RollingBodyForm defaults;
  id_->setObjectName("id");
  surface_->setObjectName("F");
  surface_->setText("x^4 + y^4 + z^4 + 0.5*(x^2 + y^2 + z^2) - 1.5");
  profile_->setObjectName("profile");
  profile_->setText(QString::fromStdString(defaults.profile));
  profile_->setToolTip("the radius ρ about body axis 3 at the height z: an expression of z and the "
                       "parameters (z_bottom and z_top among them)");
  profileSquared_->setObjectName("profile_squared");
  profileSquared_->setChecked(defaults.profileSquared);
  file_->setObjectName("file");
  file_->setText(QDir::current().filePath("my_body.json"));
  shape_->setObjectName("shape");
  shape_->addItems({"sphere", "ellipsoid", "paraboloid", "disk", "superellipsoid", "revolution", "implicit"});
  shape_->setCurrentText(QString::fromStdString(defaults.shape));
  exponent_->setToolTip("2: the ellipsoid; larger flattens the faces towards a box's");
  bulge_->setToolTip("the weight of the ellipsoid through the same vertices that keeps the faces curved "
                     "(> 0 when the exponent is above 2)");
  support_->setObjectName("support");
  support_->addItems({"plane", "sphere", "ellipsoid", "paraboloid", "implicit"});
  supportSurface_->setObjectName("support_F");
  supportSurface_->setToolTip("the support's surface F(x, y, z) = 0 in fixed axes, F < 0 in the support (the "
                              "body rolls where F > 0); the contact is first sought from the origin");
  support_->setToolTip(
      "what the body rolls on: the plane; a sphere (on it, or inside it: a spherical bowl); "
      "an ellipsoid (on it, or inside it: an ellipsoid bowl); a paraboloid bowl (in it); any surface "
      "F(x, y, z) = 0 (implicit). On "
      "a curved support the body must be "
      "more curved than a bowl where it touches it");
  side_->setObjectName("side");
  side_->addItems({"outside", "inside"});
  side_->setToolTip("outside: the body rolls on the sphere or ellipsoid; inside: in it (a bowl)");
  contact_->setObjectName("contact");
  contact_->addItems({"marble", "rubber", "sliding"});
  contact_->setToolTip("marble: rolling without slipping; rubber: also without spinning about the normal; "
                       "sliding: viscous friction at the contact (the tippe top)");
  axis_->setObjectName("axis");
  error_->setObjectName("error");
  error_->setWordWrap(true);
  error_->setStyleSheet("color: #b00020");

  QFormLayout* form = rows_;
  form->addRow("Name", id_);
  form->addRow("Shape", shape_);
  for (std::size_t i = 0; i < 3; ++i) {
    sizes_[i] = number(this, QString("size%1").arg(i + 1), defaults.sizes[i], 1e-9);
    sizeLabels_[i] = new QLabel(this);
    form->addRow(sizeLabels_[i], sizes_[i]);
  }
  form->addRow("Exponent p ≥ 2", exponent_);
  form->addRow("Bulge ε", bulge_);
  form->addRow("Profile ρ(z)", profile_);
  form->addRow("", profileSquared_);
  auto* heights = new QHBoxLayout(heightsRow_);
  heights->setContentsMargins(0, 0, 0, 0);
  for (std::size_t i = 0; i < 2; ++i) {
    heights_[i] = number(this, i == 0 ? "z_bottom" : "z_top", defaults.heights[i]);
    heights->addWidget(heights_[i]);
  }
  form->addRow("Profile's bottom and top on axis 3", heightsRow_);
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
  form->addRow("Rolls on", support_);
  form->addRow("Side of the support", side_);
  form->addRow("Support's F(x, y, z) = 0, F < 0 in it", supportSurface_);
  for (std::size_t i = 0; i < 3; ++i) {
    supportSizes_[i] = number(this, QString("support%1").arg(i + 1), defaults.supportSizes[i], 1e-9);
    supportLabels_[i] = new QLabel(this);
    form->addRow(supportLabels_[i], supportSizes_[i]);
  }
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
  auto* intro = new QLabel("Describe the body and what it rolls on; rollviz derives its equations "
                           "(docs/rolling.md). Every number becomes a parameter of the model.",
                           this);
  intro->setWordWrap(true);
  layout->addWidget(intro);
  layout->addLayout(form);
  layout->addWidget(error_);
  layout->addWidget(buttons);
  for (QComboBox* choice : {shape_, support_, side_})
    connect(choice, &QComboBox::currentTextChanged, this, [this] { showFields(); });
  connect(contact_, &QComboBox::currentTextChanged, this,
          [this](const QString& c) { friction_->setEnabled(c == "sliding"); });
  friction_->setEnabled(false);
  showFields();
}

void RollingBodyDialog::showRow(QWidget* field, bool visible) {
  field->setVisible(visible);
  if (QWidget* label = rows_->labelForField(field)) label->setVisible(visible);
}

void RollingBodyDialog::showFields() {
  error_->clear(); // a reason given for another shape or support
  const QString s = shape_->currentText();
  const std::array<QString, 3> labels =
      s == "ellipsoid" || s == "superellipsoid"
          ? std::array<QString, 3>{"Semi-axis 1", "Semi-axis 2", "Semi-axis 3"}
      : s == "paraboloid"
          ? std::array<QString, 3>{"p (curvature radius, axis 1)", "q (curvature radius, axis 2)", ""}
      : s == "implicit" || s == "revolution" ? std::array<QString, 3>{"", "", ""}
                                             : std::array<QString, 3>{"Radius", "", ""};
  for (std::size_t i = 0; i < 3; ++i) {
    sizeLabels_[i]->setText(labels[i]);
    sizeLabels_[i]->setVisible(!labels[i].isEmpty());
    sizes_[i]->setVisible(!labels[i].isEmpty());
  }
  for (QWidget* field : {static_cast<QWidget*>(exponent_), static_cast<QWidget*>(bulge_)})
    showRow(field, s == "superellipsoid");
  for (QWidget* field :
       {static_cast<QWidget*>(profile_), static_cast<QWidget*>(profileSquared_), heightsRow_})
    showRow(field, s == "revolution");
  for (QWidget* field : {static_cast<QWidget*>(surface_), static_cast<QWidget*>(bound_)})
    showRow(field, s == "implicit");

  const QString support = support_->currentText();
  showRow(side_, support == "sphere" || support == "ellipsoid");
  showRow(supportSurface_, support == "implicit");
  const std::array<QString, 3> supportLabels =
      support == "sphere"
          ? std::array<QString, 3>{side_->currentText() == "inside" ? "Bowl's radius a" : "Sphere's radius a",
                                   "", ""}
      : support == "ellipsoid"
          ? std::array<QString, 3>{"Its semi-axis 1 (fixed axes)", "Its semi-axis 2", "Its semi-axis 3"}
      : support == "paraboloid"
          ? std::array<QString, 3>{"Bowl's p (curvature radius at the bottom, axis 1)",
                                   "Bowl's q (curvature radius at the bottom, axis 2)", ""}
      : support == "implicit" ? std::array<QString, 3>{"Its size (the part drawn about the origin)", "", ""}
                              : std::array<QString, 3>{"", "", ""};
  for (std::size_t i = 0; i < 3; ++i) {
    supportLabels_[i]->setText(supportLabels[i]);
    supportLabels_[i]->setVisible(!supportLabels[i].isEmpty());
    supportSizes_[i]->setVisible(!supportLabels[i].isEmpty());
  }
}

RollingBodyForm RollingBodyDialog::form() const {
  RollingBodyForm f;
  f.id = id_->text().trimmed().toStdString();
  f.shape = shape_->currentText().toStdString();
  f.contact = contact_->currentText().toStdString();
  f.exponent = exponent_->value();
  f.bulge = bulge_->value();
  f.profile = profile_->text().toStdString();
  f.profileSquared = profileSquared_->isChecked();
  for (std::size_t i = 0; i < 2; ++i)
    f.heights[i] = heights_[i]->value();
  f.surface = surface_->text().toStdString();
  f.size = bound_->value();
  for (std::size_t i = 0; i < 3; ++i) {
    f.sizes[i] = sizes_[i]->value();
    f.centre[i] = centre_[i]->value();
    f.inertia[i] = inertia_[i]->value();
    f.supportSizes[i] = supportSizes_[i]->value();
  }
  f.mass = mass_->value();
  f.friction = friction_->value();
  f.gravity = gravity_->value();
  f.symmetryAxis = axis_->isChecked();
  f.support = support_->currentText().toStdString();
  f.inside = side_->currentText() == "inside";
  f.supportSurface = supportSurface_->text().toStdString();
  return f;
}

bool RollingBodyDialog::create() {
  const QString path = file_->text().trimmed();
  try {
    if (!path.endsWith(".json", Qt::CaseInsensitive)) throw InputError("the model file's name ends in .json");
    const std::string text = rollingModelDocument(form()).dump(2) + "\n";
    checkStart(modelEntryFromJson(nlohmann::json::parse(text), path.toStdString())); // a model that rolls
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
