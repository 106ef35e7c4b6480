// EglContext.cpp -- headless rendering with no X server: Mesa's EGL surfaceless platform (llvmpipe).
#include "render/context/GlxShim.h"
#include "render/context/HeadlessContext.h"

#include "dynamics/core/Errors.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <vtkCallbackCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

namespace rv {

namespace {

class EglContext final : public HeadlessContext {
public:
  EglContext(int w, int h) {
    auto getPlatformDisplay =
        reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
    if (getPlatformDisplay)
      dpy_ = getPlatformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr);
    EGLint major, minor, n = 0;
    if (dpy_ == EGL_NO_DISPLAY || !eglInitialize(dpy_, &major, &minor))
      throw ComputationError("no EGL surfaceless display (is libgl1-mesa-dri installed?)");
    eglBindAPI(EGL_OPENGL_API);
    const EGLint cfgAttr[] = {EGL_SURFACE_TYPE,
                              0,
                              EGL_RENDERABLE_TYPE,
                              EGL_OPENGL_BIT,
                              EGL_RED_SIZE,
                              8,
                              EGL_GREEN_SIZE,
                              8,
                              EGL_BLUE_SIZE,
                              8,
                              EGL_ALPHA_SIZE,
                              8,
                              EGL_DEPTH_SIZE,
                              24,
                              EGL_NONE};
    EGLConfig cfg;
    if (!eglChooseConfig(dpy_, cfgAttr, &cfg, 1, &n) || n < 1)
      throw ComputationError("no suitable EGL config");
    const EGLint ctxAttr[] = {EGL_CONTEXT_MAJOR_VERSION,
                              3,
                              EGL_CONTEXT_MINOR_VERSION,
                              2,
                              EGL_CONTEXT_OPENGL_PROFILE_MASK,
                              EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                              EGL_NONE};
    ctx_ = eglCreateContext(dpy_, cfg, EGL_NO_CONTEXT, ctxAttr);
    if (ctx_ == EGL_NO_CONTEXT || !eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_))
      throw ComputationError("cannot create an OpenGL 3.2 core EGL context");
    glxshim::loader = [](const char* name) {
      return reinterpret_cast<glxshim::Proc>(eglGetProcAddress(name));
    };

    window_ = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    vtkNew<vtkCallbackCommand> cb;
    cb->SetClientData(this);
    cb->SetCallback([](vtkObject*, unsigned long ev, void* cd, void* call) {
      auto* self = static_cast<EglContext*>(cd);
      if (ev == vtkCommand::WindowMakeCurrentEvent)
        eglMakeCurrent(self->dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, self->ctx_);
      else // WindowIsCurrentEvent
        *static_cast<bool*>(call) = eglGetCurrentContext() == self->ctx_;
    });
    window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, cb);
    window_->AddObserver(vtkCommand::WindowIsCurrentEvent, cb);
    window_->SetSize(w, h);
    window_->SetOwnContext(false);
    window_->SetReadyForRendering(true);
    window_->SetFrameBlitModeToNoBlit(); // no default framebuffer: the picture stays in VTK's FBOs
  }
  ~EglContext() override {
    eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx_);
    window_->Finalize(); // release VTK's GL objects while the context is current
    window_ = nullptr;
    eglMakeCurrent(dpy_, EGL_NO_SURFACE, EGL_NO_SURFACE, EGL_NO_CONTEXT);
    eglDestroyContext(dpy_, ctx_);
    eglTerminate(dpy_);
  }
  vtkRenderWindow* window() override { return window_; }
  const char* backend() const override { return "egl"; }

private:
  EGLDisplay dpy_ = EGL_NO_DISPLAY;
  EGLContext ctx_ = EGL_NO_CONTEXT;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
};

} // namespace

std::unique_ptr<HeadlessContext> createHeadlessContext(int width, int height) {
  return std::make_unique<EglContext>(width, height);
}

} // namespace rv
