// HeadlessContext.h -- an OpenGL context with no window system, driving a vtkGenericOpenGLRenderWindow.
// Two backends: EGL surfaceless (rv_render_egl, in `rollviz`) and OSMesa (rv_render_osmesa, in
// `rollviz-osmesa`); an executable links exactly one, which defines createHeadlessContext().
#pragma once
#include <memory>

class vtkRenderWindow;

namespace rv {

class HeadlessContext {
public:
  virtual ~HeadlessContext() = default;
  /// The render window bound to this context; its size is the picture size.
  virtual vtkRenderWindow* window() = 0;
  /// "egl" or "osmesa".
  virtual const char* backend() const = 0;
};

/// A context of the linked backend with a width x height picture. Throws ComputationError when there is
/// no usable GL.
std::unique_ptr<HeadlessContext> createHeadlessContext(int width, int height);

} // namespace rv
