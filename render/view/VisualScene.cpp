#include "render/view/VisualScene.h"

#include "dynamics/core/Format.h"
#include "render/BodyMeshes.h"
#include "render/objects/ApexObject.h"
#include "render/objects/BodyAxesObject.h"
#include "render/objects/BodyObject.h"
#include "render/objects/ContactTraceObject.h"
#include "render/objects/FrameObjects.h"
#include "render/objects/PhaseCurveObject.h"
#include "render/objects/PlaneObject.h"
#include "render/objects/SceneAxesObject.h"
#include "render/objects/SurfaceObject.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <numbers>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkLightKit.h>
#include <vtkPolyData.h>
#include <vtkPropCollection.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

namespace rv {

VisualScene::VisualScene(const Model& model, const ViewOptions& options, const Eigen::VectorXd& x0)
    : model_(model), options_(options) {
  renderer_ = vtkSmartPointer<vtkRenderer>::New();
  renderer_->GradientBackgroundOn();
  renderer_->SetBackground(0.80, 0.83, 0.88);  // bottom
  renderer_->SetBackground2(0.36, 0.45, 0.58); // top
  // no FXAA: with VTK 9.1 on a no-blit headless window it renders a black picture
  vtkNew<vtkLightKit> lights;
  lights->AddLightsToRenderer(renderer_);

  overlay_ = vtkSmartPointer<vtkTextActor>::New();
  overlay_->GetTextProperty()->SetFontSize(16);
  overlay_->GetTextProperty()->SetColor(0.08, 0.08, 0.12);
  overlay_->GetTextProperty()->SetFontFamilyToCourier();
  overlay_->SetDisplayPosition(10, 8);
  overlay_->SetVisibility(options.overlay);
  renderer_->AddActor2D(overlay_);

  const auto& names = model.info().integralNames;
  for (std::size_t i = 0; i < names.size(); ++i)
    if (names[i] == "E") energyIndex_ = static_cast<int>(i);

  const auto pose = model.pose(x0.data());
  const long cap = options.maxTracePoints;
  auto geometry = model.geometry();
  vtkSmartPointer<vtkPolyData> mesh;        // a body drawn from a file: its box sets the sizes and axes
  vtkSmartPointer<vtkPolyData> supportMesh; // an implicit support, sampled
  if (const auto* drawn = dynamic_cast<const DrawnFromMesh*>(&model)) {
    if (const auto file = drawn->bodyMesh())
      mesh = readBodyMesh(*file);
    else if (const auto surface = drawn->bodySurface())
      mesh = sampleImplicitSurface(*surface);
    if (mesh) geometry = boundingGeometry(mesh);
    if (const auto surface = drawn->supportSurface()) supportMesh = sampleImplicitSupport(*surface);
  }
  std::array<double, 3> lo{}, hi{}; // where the scene axes go unless the scene gives their range
  if (geometry && pose && options.kind == ViewKind::Apex) {
    scale_ = 1; // the unit sphere
    const LookingIn frame = options.lookingIn;
    add(std::make_unique<UnitSphereObject>("sphere"));
    for (int i = 0; i < 3; ++i)
      add(std::make_unique<ApexObject>(std::string("apex_") + "xyz"[i], i, frame, cap));
    const Eigen::Vector3d half = geometry->shape == BodyShape::Paraboloid
                                     ? Eigen::Vector3d(0.5, 0.5, 0.3)
                                     : Eigen::Vector3d(geometry->semiAxes);
    const Eigen::Vector3d box = 0.7 * half / half.maxCoeff();
    add(std::make_unique<BodyBoxObject>("box", frame, std::array<double, 3>{box[0], box[1], box[2]}));
    add(std::make_unique<VectorObject>("vector", frame));
    lo = {-1, -1, -1}, hi = {1, 1, 1};
    // a key to the colours, top left: which axis each apex is the tip of
    for (int i = 0; i < 3; ++i) {
      const char axis = "xyz"[i];
      keyLines_.push_back(frame == LookingIn::Absolute ? format("body axis e%d seen from space", i + 1)
                          : i == 2                     ? std::string("vertical z seen from the body (gamma)")
                                                       : format("space axis %c seen from the body", axis));
      vtkNew<vtkTextActor> key;
      key->SetInput(keyLines_.back().c_str());
      key->GetTextProperty()->SetFontSize(14);
      key->GetTextProperty()->SetBold(true);
      const Rgb c = axisColour(i);
      key->GetTextProperty()->SetColor(c[0], c[1], c[2]);
      key->GetTextProperty()->SetShadow(true); // legible over the blue sky too (a background box is not
                                               // rescaled in large snapshots)
      // above the time line, in display coordinates as it is (large snapshots rescale those)
      key->SetDisplayPosition(10, 8 + 22 * (3 - i));
      key->SetVisibility(options.overlay);
      renderer_->AddActor2D(key);
    }
  } else if (geometry && pose) {
    scale_ = bodySize(*geometry);
    const auto support = model.support();
    if (support || supportMesh) {
      auto surface = support ? std::make_unique<SurfaceObject>("surface", *support)
                             : std::make_unique<SurfaceObject>("surface", supportMesh);
      surface->hideTheFarSide(pose->contact, pose->centre);
      add(std::move(surface));
    } else
      add(std::make_unique<PlaneObject>("plane", scale_, 40 * scale_));
    add(std::make_unique<ContactTraceObject>("trace", ContactTraceObject::On::Support, scale_, cap));
    add(std::make_unique<BodyObject>(geometry->shape == BodyShape::Ball ? "ball" : "body", *geometry, mesh));
    add(std::make_unique<ContactTraceObject>("body_trace", ContactTraceObject::On::Body, scale_, cap));
    add(std::make_unique<BodyAxesObject>("axes", *geometry, scale_));
    // a box the body stands in (they grow as it rolls away): one four body sizes wide left its edges outside
    // the camera's frame, and the axes seemed not to be drawn at all
    const Eigen::Vector3d c = pose->contact;
    lo = {c[0] - 1.5 * scale_, c[1] - 1.5 * scale_, 0.0},
    hi = {c[0] + 1.5 * scale_, c[1] + 1.5 * scale_, 2.2 * scale_};
  } else {
    scale_ = std::max(1.0, x0.head(std::min<Eigen::Index>(3, x0.size())).norm());
    add(std::make_unique<PhaseCurveObject>(model.isMap() ? "points" : "curve", scale_, cap, model.isMap()));
    lo = {-scale_, -scale_, -scale_}, hi = {scale_, scale_, scale_};
  }
  auto axes = std::make_unique<SceneAxesObject>("scene_axes", options.axes, lo, hi);
  axes->setFollowsMotion(options.kind != ViewKind::Apex);
  if (geometry && pose && options.kind != ViewKind::Apex) axes->setLift(6e-3 * scale_); // above the floor
  add(std::move(axes));
  show(0.0, x0);
  resetCamera();
  floorObserver_ = renderer_->AddObserver(vtkCommand::StartEvent, this, &VisualScene::keepCameraAboveFloor);
}

VisualScene::~VisualScene() {
  renderer_->RemoveObserver(floorObserver_);
}

void VisualScene::keepCameraAboveFloor() {
  // a camera under the floor sees the underside of the plane (one grey sheet) and the body through it
  if (!find("plane") || options_.kind != ViewKind::Motion || options_.lookingIn != LookingIn::Absolute)
    return;
  if (options_.camera.elevation < 0) return; // the scene itself asks to look from below: its choice
  vtkCamera* cam = renderer_->GetActiveCamera();
  double p[3], f[3];
  cam->GetPosition(p);
  cam->GetFocalPoint(f);
  const double lowest = 0.05 * scale_;
  if (p[2] >= lowest) return;
  const Eigen::Vector3d v(p[0] - f[0], p[1] - f[1], p[2] - f[2]);
  const double dist = v.norm();
  if (dist <= 0) return;
  const double sinEl = std::clamp((lowest - f[2]) / dist, -1.0, 1.0);
  Eigen::Vector2d across = v.head<2>();
  if (across.norm() < 1e-12 * dist) across = Eigen::Vector2d::UnitX();
  across *= dist * std::sqrt(1 - sinEl * sinEl) / across.norm();
  cam->SetPosition(f[0] + across[0], f[1] + across[1], f[2] + dist * sinEl);
  cam->OrthogonalizeViewUp();
  renderer_->ResetCameraClippingRange();
}

vtkRenderer* VisualScene::renderer() const {
  return renderer_;
}

void VisualScene::addTo(vtkRenderWindow* window) const {
  window->SetMultiSamples(options_.multisamples);
  window->AddRenderer(renderer_);
}

VisualObject& VisualScene::add(std::unique_ptr<VisualObject> object) {
  for (auto& o : objects_)
    if (o->name() == object->name()) o.reset();
  std::erase(objects_, nullptr);
  const auto viewProps = [this] {
    std::vector<vtkProp*> out;
    vtkCollectionSimpleIterator it;
    renderer_->GetViewProps()->InitTraversal(it);
    while (vtkProp* p = renderer_->GetViewProps()->GetNextProp(it))
      out.push_back(p);
    return out;
  };
  const auto before = viewProps();
  object->attach(renderer_);
  auto& mine = props_[object->name()];
  mine.clear();
  for (vtkProp* p : viewProps())
    if (std::find(before.begin(), before.end(), p) == before.end()) mine.push_back(p);
  ObjectOptions options = options_.object(object->name());
  if (!options_.objects.count(object->name())) options.enabled = object->shownByDefault();
  object->apply(options);
  objects_.push_back(std::move(object));
  return *objects_.back();
}

std::vector<vtkProp*> VisualScene::props(const std::string& name) const {
  const auto it = props_.find(name);
  return it == props_.end() ? std::vector<vtkProp*>{} : it->second;
}

VisualObject* VisualScene::find(const std::string& name) const {
  for (const auto& o : objects_)
    if (o->name() == name) return o.get();
  return nullptr;
}

void VisualScene::setOptions(const std::string& name, const ObjectOptions& options) {
  options_.objects[name] = options;
  if (auto* o = find(name)) o->apply(options);
}

void VisualScene::setAxes(const AxesOptions& axes) {
  options_.axes = axes;
  if (auto* a = dynamic_cast<SceneAxesObject*>(find("scene_axes"))) a->setAxes(axes);
}

void VisualScene::advance(double t, const Eigen::VectorXd& x) {
  const auto pose = model_.pose(x.data());
  const FrameState s{t, x.data(), model_, pose};
  for (auto& o : objects_)
    o->advance(s);
}

void VisualScene::show(double t, const Eigen::VectorXd& x) {
  const auto pose = model_.pose(x.data());
  const FrameState s{t, x.data(), model_, pose};
  for (auto& o : objects_)
    o->show(s);
  const Eigen::Vector3d focus = pose ? pose->centre : Eigen::Vector3d::Zero();
  if (options_.camera.follow && pose && options_.kind == ViewKind::Motion &&
      options_.lookingIn == LookingIn::Absolute) {
    // carry the camera along with the body, keeping whatever view the user has turned to
    vtkCamera* cam = renderer_->GetActiveCamera();
    const Eigen::Vector3d d = focus - focus_;
    double f[3], p[3];
    cam->GetFocalPoint(f);
    cam->GetPosition(p);
    cam->SetFocalPoint(f[0] + d[0], f[1] + d[1], f[2] + d[2]);
    cam->SetPosition(p[0] + d[0], p[1] + d[1], p[2] + d[2]);
    renderer_->ResetCameraClippingRange();
  }
  if (pose && options_.kind == ViewKind::Motion && options_.lookingIn == LookingIn::Body) {
    // looking in the body's frame: the camera is carried by the body, so the body stands still on screen and
    // the plane turns and slides under it
    vtkCamera* cam = renderer_->GetActiveCamera();
    const double el = options_.camera.elevation * std::numbers::pi / 180;
    const double az = options_.camera.azimuth * std::numbers::pi / 180;
    const Eigen::Vector3d dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
    const double dist = options_.camera.distance > 0 ? options_.camera.distance : 5 * scale_;
    const Eigen::Vector3d eye = pose->centre + pose->rotation * (dist * dir);
    const Eigen::Vector3d up = pose->rotation * Eigen::Vector3d::UnitZ();
    cam->SetFocalPoint(pose->centre[0], pose->centre[1], pose->centre[2]);
    cam->SetPosition(eye[0], eye[1], eye[2]);
    cam->SetViewUp(up[0], up[1], up[2]);
    renderer_->ResetCameraClippingRange();
  }
  focus_ = focus;

  char text[160];
  if (energyIndex_ >= 0) {
    const double e = model_.integrals(x.data())[energyIndex_];
    if (!haveEnergy0_) energy0_ = e, haveEnergy0_ = true;
    const double rel = (e - energy0_) / (energy0_ != 0 ? std::abs(energy0_) : 1.0);
    energyError_ = rel;
    // compact: at a gallery thumbnail's 320 pixels the padded line ("t =     40.000    dE/E = ...") was cut
    std::snprintf(text, sizeof text, "t = %.3f   dE/E = %+.2e", t, rel);
  } else {
    std::snprintf(text, sizeof text, "t = %.3f", t);
  }
  overlay_->SetInput(text);
  if (!pose && cameraAsPlaced()) placeCamera(); // the growing curve framed, until the user takes the camera
}

namespace {
std::array<double, 10> cameraState(vtkCamera* cam) {
  std::array<double, 10> s{};
  cam->GetPosition(&s[0]);
  cam->GetFocalPoint(&s[3]);
  cam->GetViewUp(&s[6]);
  s[9] = cam->GetViewAngle();
  return s;
}
} // namespace

bool VisualScene::cameraAsPlaced() const {
  return cameraState(renderer_->GetActiveCamera()) == placed_;
}

void VisualScene::clear() {
  for (auto& o : objects_)
    o->clear();
  haveEnergy0_ = false;
}

void VisualScene::resetCamera() {
  placeCamera();
}

void VisualScene::placeCamera() {
  vtkCamera* cam = renderer_->GetActiveCamera();
  const double el = options_.camera.elevation * std::numbers::pi / 180;
  const double az = options_.camera.azimuth * std::numbers::pi / 180;
  const Eigen::Vector3d dir(std::cos(el) * std::cos(az), std::cos(el) * std::sin(az), std::sin(el));
  if (std::abs(std::cos(el)) < 1e-6)
    cam->SetViewUp(0, 1, 0); // looking straight down (2D maps): y up on the screen
  else
    cam->SetViewUp(0, 0, 1);
  if (options_.kind == ViewKind::Apex && model_.geometry()) {
    // the unit sphere at the origin, the camera fixed
    const double dist = options_.camera.distance > 0 ? options_.camera.distance : 6.5;
    cam->SetFocalPoint(0, 0, 0);
    cam->SetPosition(dist * dir[0], dist * dir[1], dist * dir[2]);
    cam->SetViewAngle(30);
    renderer_->ResetCameraClippingRange();
    placed_ = cameraState(cam);
    return;
  }
  if (!model_.geometry()) {
    // frame whatever has been drawn so far, from the requested direction
    cam->SetFocalPoint(0, 0, 0);
    cam->SetPosition(dir[0], dir[1], dir[2]);
    renderer_->ResetCamera();
    placed_ = cameraState(cam);
    return;
  }
  // a ball is framed with room for its trace; an elongated body's size is its longest half-axis already
  const auto geometry = model_.geometry();
  const double framing = geometry && geometry->shape == BodyShape::Ball ? 9 : 5;
  double dist = options_.camera.distance > 0 ? options_.camera.distance : framing * scale_;
  Eigen::Vector3d focus = focus_;
  if (const auto* surface = find("surface"); surface && !options_.camera.follow) {
    // a fixed surface under the ball: frame all of it
    double b[6];
    renderer_->ComputeVisiblePropBounds(b);
    focus = Eigen::Vector3d((b[0] + b[1]) / 2, (b[2] + b[3]) / 2, (b[4] + b[5]) / 2);
    if (options_.camera.distance <= 0) dist = 1.9 * std::max({b[1] - b[0], b[3] - b[2], b[5] - b[4]});
  }
  const Eigen::Vector3d eye = focus + dist * dir;
  cam->SetFocalPoint(focus[0], focus[1], focus[2]);
  cam->SetPosition(eye[0], eye[1], eye[2]);
  cam->SetViewAngle(30);
  renderer_->ResetCameraClippingRange();
  placed_ = cameraState(cam);
}

void playTo(VisualScene& scene, Integrator& integrator, double t, Eigen::VectorXd& work) {
  const int dir = integrator.direction();
  while (dir * (integrator.time() - t) < 0) {
    integrator.step();
    if (dir * (integrator.time() - t) < 0) scene.advance(integrator.time(), integrator.state());
  }
  if (integrator.time() == t)
    work = integrator.state();
  else
    integrator.sampleAt(t, work);
  scene.show(t, work);
}

} // namespace rv
