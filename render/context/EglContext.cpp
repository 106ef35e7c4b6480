// EglContext.cpp -- headless rendering with no X server through EGL. The device is chosen as on a compute
// node: ROLLVIZ_EGL_DEVICE=N picks device N of EGL_EXT_device_enumeration's list; otherwise the first
// hardware device (EGL_EXT_platform_device), then Mesa's surfaceless platform (llvmpipe), then any software
// device. With no EGL at all, HeadlessUnavailable tells `rollviz` to hand the command to `rollviz-osmesa`.
#include "render/context/GlxShim.h"
#include "render/context/HeadlessContext.h"

#include <EGL/egl.h>
#include <EGL/eglext.h>
#include <cstdlib>
#include <cstring>
#include <optional>
#include <sstream>
#include <vtkCallbackCommand.h>
#include <vtkGenericOpenGLRenderWindow.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

namespace rv {

namespace {

// GL_VENDOR, GL_RENDERER, GL_VERSION (GL/gl.h would pull in a second GL declaration set beside VTK's GLEW)
constexpr unsigned kGlVendor = 0x1F00, kGlRenderer = 0x1F01, kGlVersion = 0x1F02;

bool hasExtension(const char* list, const char* name) {
  if (!list) return false;
  std::istringstream words(list);
  for (std::string w; words >> w;)
    if (w == name) return true;
  return false;
}

struct EglDevice {
  EGLDeviceEXT handle;
  std::string name; ///< "software (Mesa)", "/dev/dri/renderD128", ...
  bool software;
};

struct DeviceApi {
  PFNEGLGETPLATFORMDISPLAYEXTPROC platformDisplay =
      reinterpret_cast<PFNEGLGETPLATFORMDISPLAYEXTPROC>(eglGetProcAddress("eglGetPlatformDisplayEXT"));
  PFNEGLQUERYDEVICESEXTPROC queryDevices =
      reinterpret_cast<PFNEGLQUERYDEVICESEXTPROC>(eglGetProcAddress("eglQueryDevicesEXT"));
  PFNEGLQUERYDEVICESTRINGEXTPROC deviceString =
      reinterpret_cast<PFNEGLQUERYDEVICESTRINGEXTPROC>(eglGetProcAddress("eglQueryDeviceStringEXT"));
};

// The devices EGL offers, in its order (the order ROLLVIZ_EGL_DEVICE counts in); empty without the
// extensions.
std::vector<EglDevice> enumerateDevices(const DeviceApi& api) {
  const char* client = eglQueryString(EGL_NO_DISPLAY, EGL_EXTENSIONS);
  if (!api.platformDisplay || !api.queryDevices || !api.deviceString ||
      !hasExtension(client, "EGL_EXT_platform_device") ||
      !(hasExtension(client, "EGL_EXT_device_enumeration") || hasExtension(client, "EGL_EXT_device_base")))
    return {};
  EGLint n = 0;
  if (!api.queryDevices(0, nullptr, &n) || n <= 0) return {};
  std::vector<EGLDeviceEXT> handles(static_cast<std::size_t>(n));
  if (!api.queryDevices(n, handles.data(), &n)) return {};
  handles.resize(static_cast<std::size_t>(n));
  std::vector<EglDevice> devices;
  for (auto* h : handles) {
    const char* ext = api.deviceString(h, EGL_EXTENSIONS);
    EglDevice d{h, "", hasExtension(ext, "EGL_MESA_device_software")};
    const char* file = nullptr;
    if (hasExtension(ext, "EGL_EXT_device_drm_render_node"))
      file = api.deviceString(h, EGL_DRM_RENDER_NODE_FILE_EXT);
    if (!file && hasExtension(ext, "EGL_EXT_device_drm")) file = api.deviceString(h, EGL_DRM_DEVICE_FILE_EXT);
    d.name = d.software ? "software (Mesa)" : file ? file : "hardware";
    if (hasExtension(ext, "EGL_NV_device_cuda")) d.name += " (NVIDIA)";
    devices.push_back(std::move(d));
  }
  eglGetError(); // a device without DRM answers the file queries with an error; nothing to report
  return devices;
}

struct Opened {
  EGLDisplay dpy;
  EGLContext ctx;
};

// Initialises dpy and makes an OpenGL 3.2 core context current on it with no surface; says why not otherwise.
std::optional<Opened> openContext(EGLDisplay dpy, std::string& why) {
  EGLint major, minor, n = 0;
  if (dpy == EGL_NO_DISPLAY || !eglInitialize(dpy, &major, &minor)) {
    why = "no display";
    return std::nullopt;
  }
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
  const EGLint ctxAttr[] = {EGL_CONTEXT_MAJOR_VERSION,
                            3,
                            EGL_CONTEXT_MINOR_VERSION,
                            2,
                            EGL_CONTEXT_OPENGL_PROFILE_MASK,
                            EGL_CONTEXT_OPENGL_CORE_PROFILE_BIT,
                            EGL_NONE};
  EGLConfig cfg;
  EGLContext ctx = EGL_NO_CONTEXT;
  if (!eglBindAPI(EGL_OPENGL_API))
    why = "no desktop OpenGL";
  else if (!eglChooseConfig(dpy, cfgAttr, &cfg, 1, &n) || n < 1)
    why = "no RGBA8 + depth 24 config";
  else if ((ctx = eglCreateContext(dpy, cfg, EGL_NO_CONTEXT, ctxAttr)) == EGL_NO_CONTEXT)
    why = "no OpenGL 3.2 core context";
  else if (!eglMakeCurrent(dpy, EGL_NO_SURFACE, EGL_NO_SURFACE, ctx))
    why = "the context cannot be made current without a surface";
  else
    return Opened{dpy, ctx};
  if (ctx != EGL_NO_CONTEXT) eglDestroyContext(dpy, ctx);
  eglTerminate(dpy);
  return std::nullopt;
}

// ROLLVIZ_EGL_DEVICE's index, or nullopt when it is not set; InputError naming the variable when it is no
// index.
std::optional<std::size_t> requestedDevice() {
  const char* text = std::getenv(kEglDeviceVariable);
  if (!text || !*text) return std::nullopt;
  char* end = nullptr;
  const long n = std::strtol(text, &end, 10);
  if (*end || n < 0)
    throw InputError(std::string(kEglDeviceVariable) + "=" + text +
                     ": expected the number of an EGL device (`rollviz info` lists them)");
  return static_cast<std::size_t>(n);
}

std::string listOf(const std::vector<EglDevice>& devices) {
  std::string s;
  for (std::size_t i = 0; i < devices.size(); ++i)
    s += (i ? ", " : "") + std::to_string(i) + ": " + devices[i].name;
  return s;
}

class EglContext final : public HeadlessContext {
public:
  EglContext(int w, int h) {
    choose();
    info_.backend = "egl";
    auto getString = reinterpret_cast<const unsigned char* (*)(unsigned)>(eglGetProcAddress("glGetString"));
    auto text = [&](unsigned what) {
      const unsigned char* s = getString ? getString(what) : nullptr;
      return s ? std::string(reinterpret_cast<const char*>(s)) : std::string("?");
    };
    info_.vendor = text(kGlVendor);
    info_.renderer = text(kGlRenderer);
    info_.version = text(kGlVersion);
    info_.software = info_.software || isSoftwareRenderer(info_.renderer);
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
  const RendererInfo& info() const override { return info_; }

private:
  // Opens the device ROLLVIZ_EGL_DEVICE asks for, else the first that works in the order of the file header.
  void choose() {
    const DeviceApi api;
    const auto devices = enumerateDevices(api);
    for (std::size_t i = 0; i < devices.size(); ++i)
      info_.devices.push_back(std::to_string(i) + ": " + devices[i].name);
    auto tryDevice = [&](std::size_t i, std::string& why) {
      const auto opened =
          openContext(api.platformDisplay(EGL_PLATFORM_DEVICE_EXT, devices[i].handle, nullptr), why);
      if (!opened) return false;
      take(*opened, "EGL device " + std::to_string(i) + ": " + devices[i].name, devices[i].software);
      return true;
    };

    if (const auto wanted = requestedDevice()) {
      const std::string asked = std::string(kEglDeviceVariable) + "=" + std::to_string(*wanted);
      if (*wanted >= devices.size())
        throw InputError(asked + ": " +
                         (devices.empty() ? std::string("this machine's EGL cannot enumerate devices")
                                          : "there is no such EGL device (" + listOf(devices) + ")"));
      std::string why;
      if (!tryDevice(*wanted, why))
        throw ComputationError(asked + " (" + devices[*wanted].name + "): " + why);
      return;
    }
    std::string failures, why;
    auto failed = [&](const std::string& what) {
      failures += (failures.empty() ? "" : "; ") + what + ": " + why;
    };
    for (std::size_t i = 0; i < devices.size(); ++i) {
      if (devices[i].software) continue;
      if (tryDevice(i, why)) return;
      failed("device " + std::to_string(i) + " (" + devices[i].name + ")");
    }
    if (api.platformDisplay) {
      const auto opened =
          openContext(api.platformDisplay(EGL_PLATFORM_SURFACELESS_MESA, EGL_DEFAULT_DISPLAY, nullptr), why);
      if (opened) {
        take(*opened, "EGL surfaceless platform (Mesa)", false);
        return;
      }
      failed("Mesa's surfaceless platform");
    }
    for (std::size_t i = 0; i < devices.size(); ++i)
      if (devices[i].software) {
        if (tryDevice(i, why)) return;
        failed("device " + std::to_string(i) + " (" + devices[i].name + ")");
      }
    throw HeadlessUnavailable("no EGL context could be made (" +
                              (failures.empty() ? std::string("no EGL vendor library answered") : failures) +
                              "; is libgl1-mesa-dri installed?)");
  }
  void take(const Opened& opened, std::string how, bool software) {
    dpy_ = opened.dpy;
    ctx_ = opened.ctx;
    info_.context = std::move(how);
    info_.software = software;
  }

  EGLDisplay dpy_ = EGL_NO_DISPLAY;
  EGLContext ctx_ = EGL_NO_CONTEXT;
  RendererInfo info_;
  vtkSmartPointer<vtkGenericOpenGLRenderWindow> window_;
};

} // namespace

std::unique_ptr<HeadlessContext> createHeadlessContext(int width, int height) {
  return std::make_unique<EglContext>(width, height);
}

} // namespace rv
