// QtVtkWidget.h -- a Qt 6 QOpenGLWidget hosting a vtkGenericOpenGLRenderWindow (Debian's QVTK widget is
// built for Qt 5 and cannot share a process with Qt 6). Mouse and wheel go to a VTK interactor.
#pragma once
#include "render/Snapshot.h"

#include <QOpenGLWidget>
#include <QSize>
#include <QString>
#include <functional>
#include <map>
#include <vtkCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkGenericRenderWindowInteractor.h>
#include <vtkSmartPointer.h>

class QMouseEvent;
class QTimer;
class QWheelEvent;

namespace rv {

class QtVtkWidget : public QOpenGLWidget {
  Q_OBJECT
public:
  explicit QtVtkWidget(QWidget* parent = nullptr);
  ~QtVtkWidget() override;
  vtkGenericOpenGLRenderWindow* renderWindow() const { return window_; }
  vtkGenericRenderWindowInteractor* interactor() const { return interactor_; }
  /// A view alone in a top-level window of its own (a child of `parent`, closed with it); the window is
  /// view->window().
  static QtVtkWidget* inOwnWindow(QWidget* parent, const QString& title, int width = 560, int height = 560);
  /// OpenGL 3.2 core, no multisampling: what VTK 9.1 needs. Set as the default before QApplication.
  static QSurfaceFormat defaultFormat();
  /// Receives every picture painted (RGB, rows from the top); an empty function stops it. What a screen
  /// recording is made of. With a `size` other than the view's, each frame is rendered again offscreen at
  /// that size for the tap (as renderAt does); an empty size: the picture as shown.
  void setFrameTap(std::function<void(const Image&)> tap, QSize size = {}) {
    tap_ = std::move(tap);
    tapSize_ = size;
  }
  /// The view rendered offscreen at `width` x `height` pixels, whatever the widget's size (the scene fills
  /// the frame as it would a window of that size); the widget keeps its own size and picture.
  Image renderAt(int width, int height);
  /// Asked before a render VTK requests on its own (a chart's scene, modified, renders itself 40 ms later):
  /// false when the owner has painted the change since, and that frame would only repeat the last one.
  void setRenderWanted(std::function<bool()> wanted) { renderWanted_ = std::move(wanted); }

protected:
  void initializeGL() override;
  void resizeGL(int, int) override;
  void paintGL() override;
  void mousePressEvent(QMouseEvent* e) override;
  void mouseReleaseEvent(QMouseEvent* e) override;
  void mouseMoveEvent(QMouseEvent* e) override;
  void wheelEvent(QWheelEvent* e) override;

private:
  /// Releases what VTK holds in the widget's OpenGL context (it is about to be destroyed).
  void releaseContext();
  void mouse(QMouseEvent* e, unsigned long vtkEvent);
  static void onVtkEvent(vtkObject*, unsigned long ev, void* self, void* callData);
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
  vtkSmartPointer<vtkGenericRenderWindowInteractor> interactor_;
  std::map<int, QTimer*> timers_;
  bool inPaint_ = false, skipRender_ = false;
  std::function<void(const Image&)> tap_;
  QSize tapSize_; ///< the size the tap's pictures are rendered at (empty: as shown)
  std::function<bool()> renderWanted_;
  Image tapped_; // reused: a frame's pixels are not reallocated on every paint
};

/// The size pictures of views are saved at (Snapshot, Record, File > Export map, a chart's Save PNG), one
/// setting for all, kept between runs (File > Picture size): "view" (as shown), "x2" or "x4" (times the
/// view), or "WIDTHxHEIGHT" (e.g. 1920x1080), rendered offscreen at that size.
struct PictureSize {
  QString text = "view";
  /// The pixels of a picture of a view that shows `view` pixels.
  QSize of(const QSize& view) const;
  /// Whether `text` is one of the forms above (a size from 16 to 16384 pixels a side).
  static bool valid(const QString& text);
  static PictureSize current();
  static void setCurrent(const QString& text);
};

/// Writes the view's picture as PNG at PictureSize::current() through a temporary name; false when it cannot.
bool savePicture(QtVtkWidget* view, const QString& path);

} // namespace rv
