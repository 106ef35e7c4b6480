// OsMesaContext.cpp -- headless rendering through OSMesa (software Mesa into a memory buffer). Works only
// when libOSMesa precedes libOpenGL/libGL in symbol lookup (see render/CMakeLists.txt); the wrong order
// renders black pictures with no error, so tests check that pictures are not one colour.
#include "render/context/GlxShim.h"
#include "render/context/HeadlessContext.h"

#include "dynamics/core/Errors.h"

#include <GL/osmesa.h>
#include <string>
#include <vector>
#include <vtkCallbackCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

namespace rv {

namespace {

class OsMesaContext final : public HeadlessContext {
public:
  OsMesaContext(int w, int h) : buffer_(std::size_t(w) * h * 4), w_(w), h_(h) {
    const int attr[] = {OSMESA_FORMAT,
                        OSMESA_RGBA,
                        OSMESA_DEPTH_BITS,
                        24,
                        OSMESA_PROFILE,
                        OSMESA_CORE_PROFILE,
                        OSMESA_CONTEXT_MAJOR_VERSION,
                        3,
                        OSMESA_CONTEXT_MINOR_VERSION,
                        2,
                        0};
    ctx_ = OSMesaCreateContextAttribs(attr, nullptr);
    if (!ctx_ || !makeCurrent()) throw ComputationError("cannot create an OpenGL 3.2 core OSMesa context");
    glxshim::loader = [](const char* n) { return reinterpret_cast<glxshim::Proc>(OSMesaGetProcAddress(n)); };
    info_.backend = "osmesa";
    info_.context = "OSMesa (software, into memory)";
    info_.vendor = text(GL_VENDOR);
    info_.renderer = text(GL_RENDERER);
    info_.version = text(GL_VERSION);
    info_.software = true; // OSMesa renders on the CPU whatever its rasteriser

    window_ = vtkSmartPointer<vtkGenericOpenGLRenderWindow>::New();
    vtkNew<vtkCallbackCommand> cb;
    cb->SetClientData(this);
    cb->SetCallback([](vtkObject*, unsigned long ev, void* cd, void* call) {
      auto* self = static_cast<OsMesaContext*>(cd);
      if (ev == vtkCommand::WindowMakeCurrentEvent)
        self->makeCurrent();
      else
        *static_cast<bool*>(call) = OSMesaGetCurrentContext() == self->ctx_;
    });
    window_->AddObserver(vtkCommand::WindowMakeCurrentEvent, cb);
    window_->AddObserver(vtkCommand::WindowIsCurrentEvent, cb);
    window_->SetSize(w, h);
    window_->SetOwnContext(false);
    window_->SetReadyForRendering(true);
    window_->SetFrameBlitModeToNoBlit();
  }
  ~OsMesaContext() override {
    makeCurrent();
    window_->Finalize();
    window_ = nullptr;
    OSMesaDestroyContext(ctx_);
  }
  vtkRenderWindow* window() override { return window_; }
  const char* backend() const override { return "osmesa"; }
  const RendererInfo& info() const override { return info_; }

private:
  static std::string text(GLenum what) {
    const GLubyte* s = glGetString(what);
    return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
  }
  bool makeCurrent() { return OSMesaMakeCurrent(ctx_, buffer_.data(), GL_UNSIGNED_BYTE, w_, h_); }
  OSMesaContext ctx_ = nullptr;
  std::vector<unsigned char> buffer_;
  int w_, h_;
  RendererInfo info_;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
};

} // namespace

std::unique_ptr<HeadlessContext> createHeadlessContext(int width, int height) {
  return std::make_unique<OsMesaContext>(width, height);
}

} // namespace rv
