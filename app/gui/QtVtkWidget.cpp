// QtVtkWidget.cpp -- pitfalls solved here (../shared/stack/README.md):
// 1. VTK's make-current hook calls context()->makeCurrent(surface), never QOpenGLWidget::makeCurrent(),
//    which rebinds Qt's FBO and breaks VTK's (GL error 0x506);
// 2. chart interactor styles repaint through interactor timers: they become QTimers;
// 3. alpha is cleared to 1 after the blit, or Qt blends the widget with what is behind it;
// 4. VTK renders into its own FBO (no blit) and paintGL blits it into defaultFramebufferObject();
// 5. re-parenting the widget into another top-level window (a dock floated or docked again) gives it a new
//    OpenGL context: VTK's shaders, buffers, textures and FBO of the old one are released while it still
//    exists (aboutToBeDestroyed), and made again in the new one -- else the view stays blank or garbage.
#include "app/gui/QtVtkWidget.h"

#include "render/charts/ChartStyle.h"
#include "render/context/HeadlessContext.h"

#include <QFile>
#include <QImage>
#include <QMouseEvent>
#include <QOffscreenSurface>
#include <QOpenGLContext>
#include <QOpenGLExtraFunctions>
#include <QOpenGLFunctions>
#include <QSettings>
#include <QStringList>
#include <QTimer>
#include <QVBoxLayout>
#include <QWheelEvent>
#include <algorithm>
#include <cmath>
#include <vtkCallbackCommand.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkOpenGLFramebufferObject.h>
#include <vtkOpenGLState.h>

namespace rv {

QtVtkWidget* QtVtkWidget::inOwnWindow(QWidget* parent, const QString& title, int width, int height) {
  auto* window = new QWidget(parent, Qt::Window);
  window->setWindowTitle(title);
  auto* view = new QtVtkWidget(window);
  auto* layout = new QVBoxLayout(window);
  layout->setContentsMargins(0, 0, 0, 0);
  layout->addWidget(view);
  window->resize(width, height);
  return view;
}

namespace {
// Whether Qt's OpenGL is a CPU rasteriser (llvmpipe...): asked once, of a context in the widgets' format.
bool softwareGl() {
  static const bool software = [] {
    QOffscreenSurface surface;
    surface.setFormat(QtVtkWidget::defaultFormat());
    surface.create();
    QOpenGLContext context;
    context.setFormat(QtVtkWidget::defaultFormat());
    if (!context.create() || !context.makeCurrent(&surface)) return false;
    const GLubyte* name = context.functions()->glGetString(GL_RENDERER);
    const bool cpu = name && isSoftwareRenderer(reinterpret_cast<const char*>(name));
    context.doneCurrent();
    return cpu;
  }();
  return software;
}

// How many times larger a picture's type and pens are than the view's: the whole times the view fits in it.
int pictureScale(const QSize& picture, const QSize& shown) {
  return std::max(1, static_cast<int>(std::lround(
                         std::min(static_cast<double>(picture.width()) / std::max(1, shown.width()),
                                  static_cast<double>(picture.height()) / std::max(1, shown.height())))));
}

unsigned long pressEvent(Qt::MouseButton b) { // vtk *PressEvent; +1 is the matching *ReleaseEvent
  return b == Qt::LeftButton     ? vtkCommand::LeftButtonPressEvent
         : b == Qt::RightButton  ? vtkCommand::RightButtonPressEvent
         : b == Qt::MiddleButton ? vtkCommand::MiddleButtonPressEvent
                                 : vtkCommand::NoEvent;
}
} // namespace

QSurfaceFormat QtVtkWidget::defaultFormat() {
  QSurfaceFormat f;
  f.setRenderableType(QSurfaceFormat::OpenGL);
  f.setVersion(3, 2);
  f.setProfile(QSurfaceFormat::CoreProfile);
  f.setAlphaBufferSize(8);
  f.setDepthBufferSize(24);
  f.setSamples(0);
  return f;
}

QtVtkWidget::QtVtkWidget(QWidget* parent)
    : QOpenGLWidget(parent), window_(vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New()),
      interactor_(vtkSmartPointer<vtkGenericRenderWindowInteractor>::New()) {
  setFormat(defaultFormat());
  setMouseTracking(true);
  setFocusPolicy(Qt::StrongFocus);
  // VTK's windows ask for 8x multisampling unless told otherwise: nearly free on a GPU, but on a CPU
  // rasteriser it makes a chart's frame about 5x dearer (tests/bench: an empty 800 x 800 chart 32 -> 6 ms).
  // 3D views set their own (view.multisamples) when the scene is added.
  if (softwareGl()) window_->SetMultiSamples(0);
  window_->SetReadyForRendering(false); // until initializeGL()
  window_->SetFrameBlitModeToNoBlit();
  interactor_->SetRenderWindow(window_);
  interactor_->EnableRenderOff(); // iren->Render() only fires RenderEvent -> update()
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor_->SetInteractorStyle(style);
  interactor_->Initialize();
  vtkNew<vtkCallbackCommand> cb;
  cb->SetCallback(&QtVtkWidget::onVtkEvent);
  cb->SetClientData(this);
  for (unsigned long ev :
       {vtkCommand::WindowMakeCurrentEvent, vtkCommand::WindowIsCurrentEvent, vtkCommand::WindowFrameEvent})
    window_->AddObserver(ev, cb);
  for (unsigned long ev :
       {vtkCommand::RenderEvent, vtkCommand::CreateTimerEvent, vtkCommand::DestroyTimerEvent})
    interactor_->AddObserver(ev, cb);
}

QtVtkWidget::~QtVtkWidget() {
  // ~QOpenGLWidget destroys the context after this widget's members are gone: not a signal to us then
  if (context()) disconnect(context(), nullptr, this, nullptr);
  releaseContext();
}

void QtVtkWidget::releaseContext() {
  if (!context()) return;
  makeCurrent();
  window_->Finalize(); // every renderer's and prop's GL resources, and the window's FBO
  window_->SetReadyForRendering(false);
  doneCurrent();
}

void QtVtkWidget::onVtkEvent(vtkObject*, unsigned long ev, void* cd, void* call) {
  auto* self = static_cast<QtVtkWidget*>(cd);
  if (ev == vtkCommand::WindowMakeCurrentEvent) {
    self->context()->makeCurrent(self->context()->surface());
  } else if (ev == vtkCommand::WindowIsCurrentEvent) {
    *static_cast<bool*>(call) = QOpenGLContext::currentContext() == self->context();
  } else if (ev == vtkCommand::RenderEvent) {
    if (!self->renderWanted_ || self->renderWanted_()) self->update();
  } else if (ev == vtkCommand::WindowFrameEvent && !self->inPaint_) { // rendered outside paintGL: blit
    self->skipRender_ = true;
    self->update();
  } else if (ev == vtkCommand::CreateTimerEvent) {
    const int id = *static_cast<int*>(call);
    auto* t = new QTimer(self);
    t->setSingleShot(self->interactor_->GetTimerEventType() == vtkRenderWindowInteractor::OneShotTimer);
    QObject::connect(t, &QTimer::timeout, self, [self, id, t] {
      int tid = id;
      if (t->isSingleShot()) {
        self->timers_.erase(id);
        t->deleteLater();
      }
      self->interactor_->InvokeEvent(vtkCommand::TimerEvent, &tid);
    });
    self->timers_[id] = t;
    t->start(int(self->interactor_->GetTimerEventDuration()));
  } else if (ev == vtkCommand::DestroyTimerEvent) {
    auto it = self->timers_.find(*static_cast<int*>(call));
    if (it != self->timers_.end()) {
      it->second->deleteLater();
      self->timers_.erase(it);
    }
  }
}

void QtVtkWidget::initializeGL() {
  // called again with each new context (see 5.): the old one's resources are released before it goes
  connect(context(), &QOpenGLContext::aboutToBeDestroyed, this, &QtVtkWidget::releaseContext,
          Qt::UniqueConnection);
  window_->SetOwnContext(false);
  window_->SetForceMaximumHardwareLineWidth(1);
  window_->SetReadyForRendering(true);
  window_->OpenGLInitContext(); // glewInit() on Qt's GLX context
}

void QtVtkWidget::resizeGL(int, int) {
  interactor_->UpdateSize(static_cast<int>(std::lround(width() * devicePixelRatioF())),
                          static_cast<int>(std::lround(height() * devicePixelRatioF())));
}

void QtVtkWidget::paintGL() {
  auto* st = window_->GetState();
  st->Reset();
  st->Push();
  inPaint_ = true;
  if (!skipRender_) window_->Render();
  inPaint_ = skipRender_ = false;
  auto* f = context()->extraFunctions();
  f->glBindFramebuffer(GL_DRAW_FRAMEBUFFER, defaultFramebufferObject());
  const GLenum buf = GL_COLOR_ATTACHMENT0;
  f->glDrawBuffers(1, &buf);
  st->vtkglDisable(GL_SCISSOR_TEST);
  const int* sz = window_->GetRenderFramebuffer()->GetLastSize();
  const int dw = static_cast<int>(std::lround(width() * devicePixelRatioF())),
            dh = static_cast<int>(std::lround(height() * devicePixelRatioF()));
  window_->BlitDisplayFramebuffer(0, 0, 0, sz[0], sz[1], 0, 0, dw, dh, GL_COLOR_BUFFER_BIT, GL_LINEAR);
  f->glViewport(0, 0, dw, dh); // alpha := 1, else Qt blends the widget with what is behind it
  f->glColorMask(GL_FALSE, GL_FALSE, GL_FALSE, GL_TRUE);
  f->glClearColor(0, 0, 0, 1);
  f->glClear(GL_COLOR_BUFFER_BIT);
  f->glColorMask(GL_TRUE, GL_TRUE, GL_TRUE, GL_TRUE);
  if (tap_ && !tapSize_.isEmpty() && tapSize_ != QSize(dw, dh)) {
    // the frame again, offscreen at the tap's size (VTK's framebuffer resized for it; the screen has its
    // picture already, and the next paint renders at the widget's size again)
    const int* size = window_->GetSize();
    const int w = size[0], h = size[1];
    window_->SetSize(tapSize_.width(), tapSize_.height());
    try {
      const ScaledPicture scaled(window_, pictureScale(tapSize_, QSize(dw, dh))); // the time line grows too
      captureInto(window_, tapped_);
    } catch (const std::exception&) {
      tapped_ = Image{}; // (an empty picture: the recorder says why)
    }
    window_->SetSize(w, h);
  } else if (tap_) { // the picture as shown: Qt's framebuffer after the blit
    f->glBindFramebuffer(GL_READ_FRAMEBUFFER, defaultFramebufferObject());
    tapped_.width = dw, tapped_.height = dh;
    tapped_.rgb.resize(static_cast<std::size_t>(dw) * dh * 3);
    f->glPixelStorei(GL_PACK_ALIGNMENT, 1);
    f->glReadPixels(0, 0, dw, dh, GL_RGB, GL_UNSIGNED_BYTE, tapped_.rgb.data());
    f->glPixelStorei(GL_PACK_ALIGNMENT, 4);                   // GL's default, which VTK and Qt assume
    const std::size_t row = static_cast<std::size_t>(dw) * 3; // GL's rows run from the bottom
    for (int y = 0; y < dh / 2; ++y)
      std::swap_ranges(tapped_.rgb.begin() + static_cast<std::ptrdiff_t>(y * row),
                       tapped_.rgb.begin() + static_cast<std::ptrdiff_t>((y + 1) * row),
                       tapped_.rgb.begin() + static_cast<std::ptrdiff_t>((dh - 1 - y) * row));
  }
  st->Pop();
  if (tap_) tap_(tapped_);
}

Image QtVtkWidget::renderAt(int width, int height) {
  makeCurrent();
  auto* st = window_->GetState();
  st->Reset();
  st->Push();
  const int* size = window_->GetSize();
  const int w = size[0], h = size[1];
  window_->SetSize(width, height); // VTK's own framebuffer takes that size; Qt's is not touched
  Image picture;
  try {
    // a chart lays itself out in the frame after a size change (the first one is drawn with the old layout,
    // stretched): one frame to lay out, the next one kept
    window_->Render();
    captureInto(window_, picture);
  } catch (...) {
    window_->SetSize(w, h);
    st->Pop();
    doneCurrent();
    throw;
  }
  window_->SetSize(w, h);
  st->Pop();
  doneCurrent();
  update(); // the screen's picture again, at the widget's size
  return picture;
}

QSize PictureSize::of(const QSize& view) const {
  if (text == "x2" || text == "x4") return view * (text == "x2" ? 2 : 4);
  const QStringList parts = text.split('x');
  if (parts.size() == 2 && !parts[0].isEmpty()) return {parts[0].toInt(), parts[1].toInt()};
  return view;
}

bool PictureSize::valid(const QString& text) {
  if (text == "view" || text == "x2" || text == "x4") return true;
  const QStringList parts = text.split('x');
  bool w = false, h = false;
  const int width = parts.value(0).toInt(&w), height = parts.value(1).toInt(&h);
  return parts.size() == 2 && w && h && width >= 16 && height >= 16 && width <= 16384 && height <= 16384;
}

PictureSize PictureSize::current() {
  const QString text = QSettings().value("pictureSize", "view").toString();
  return {valid(text) ? text : QString("view")};
}

void PictureSize::setCurrent(const QString& text) {
  if (valid(text)) QSettings().setValue("pictureSize", text);
}

bool savePicture(QtVtkWidget* view, const QString& path) {
  const qreal dpr = view->devicePixelRatioF();
  const QSize shown(static_cast<int>(std::lround(view->width() * dpr)),
                    static_cast<int>(std::lround(view->height() * dpr)));
  const QSize size = PictureSize::current().of(shown);
  QImage picture;
  if (size == shown) {
    picture = view->grabFramebuffer(); // what the screen shows
  } else {
    try {
      // a chart's type, pens and markers grow with the picture (2x: the same figure, finer), its ticks kept;
      // so does a 3D view's time line
      const int scale = pictureScale(size, shown);
      // the ticks kept are those of a render at the view's own size: one now (a save just before left none)
      if (scale > 1) view->renderAt(shown.width(), shown.height());
      const ScaledPicture scaled(view->renderWindow(), scale);
      const Image rendered = view->renderAt(size.width(), size.height());
      picture = QImage(rendered.rgb.data(), rendered.width, rendered.height, rendered.width * 3,
                       QImage::Format_RGB888)
                    .copy(); // (owns its pixels once `rendered` goes)
    } catch (const std::exception&) {
      return false;
    }
  }
  // through a temporary name: a failed write leaves nothing half-written
  const QString part = path + ".part.png";
  if (!picture.save(part, "PNG")) return QFile::remove(part), false;
  QFile::remove(path);
  return QFile::rename(part, path);
}

void QtVtkWidget::mousePressEvent(QMouseEvent* e) {
  mouse(e, pressEvent(e->button()));
}
void QtVtkWidget::mouseReleaseEvent(QMouseEvent* e) {
  const unsigned long p = pressEvent(e->button());
  mouse(e, p == vtkCommand::NoEvent ? p : p + 1);
}
void QtVtkWidget::mouseMoveEvent(QMouseEvent* e) {
  mouse(e, vtkCommand::MouseMoveEvent);
}

void QtVtkWidget::mouse(QMouseEvent* e, unsigned long vtkEvent) {
  if (vtkEvent == vtkCommand::NoEvent) return;
  const double dpr = devicePixelRatioF();
  interactor_->SetEventInformationFlipY(static_cast<int>(std::lround(e->position().x() * dpr)),
                                        static_cast<int>(std::lround(e->position().y() * dpr)),
                                        e->modifiers() & Qt::ControlModifier ? 1 : 0,
                                        e->modifiers() & Qt::ShiftModifier ? 1 : 0);
  interactor_->InvokeEvent(vtkEvent, e);
}

void QtVtkWidget::wheelEvent(QWheelEvent* e) {
  const double dpr = devicePixelRatioF();
  interactor_->SetEventInformationFlipY(static_cast<int>(std::lround(e->position().x() * dpr)),
                                        static_cast<int>(std::lround(e->position().y() * dpr)));
  if (e->angleDelta().y() != 0)
    interactor_->InvokeEvent(e->angleDelta().y() > 0 ? vtkCommand::MouseWheelForwardEvent
                                                     : vtkCommand::MouseWheelBackwardEvent,
                             e);
}

} // namespace rv
