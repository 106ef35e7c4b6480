// HeadlessContext.h -- an OpenGL context with no window system, driving a vtkGenericOpenGLRenderWindow.
// Two backends: EGL surfaceless (rv_render_egl, in `rollviz`) and OSMesa (rv_render_osmesa, in
// `rollviz-osmesa`); an executable links exactly one, which defines createHeadlessContext().
#pragma once
#include "dynamics/core/Errors.h"

#include <memory>
#include <string>
#include <vector>

class vtkRenderWindow;

namespace rv {

/// What draws the headless pictures: `rollviz info`, the GUI's About box and the warning on software GL.
struct RendererInfo {
  std::string backend;              ///< "egl" or "osmesa"
  std::string context;              ///< how the context was made, e.g. "EGL device 1: /dev/dri/renderD129"
  std::vector<std::string> devices; ///< the EGL devices on offer, "0: software (Mesa)", ...; empty for OSMesa
  std::string vendor, renderer, version; ///< GL_VENDOR, GL_RENDERER, GL_VERSION
  bool software = false;                 ///< a CPU rasteriser (llvmpipe, softpipe, swrast)
};

/// True for the GL_RENDERER strings of Mesa's CPU rasterisers.
inline bool isSoftwareRenderer(const std::string& glRenderer) {
  for (const char* name : {"llvmpipe", "softpipe", "swrast", "Software Rasterizer", "SWR"})
    if (glRenderer.find(name) != std::string::npos) return true;
  return false;
}

/// No headless GL could be made at all (no EGL vendor library, no display). `rollviz` then hands the whole
/// command to `rollviz-osmesa` beside it (app/cli/Cli.cpp).
struct HeadlessUnavailable : ComputationError {
  using ComputationError::ComputationError;
};

/// The environment variable that picks an EGL device by its index in `rollviz info`'s list.
inline constexpr const char* kEglDeviceVariable = "ROLLVIZ_EGL_DEVICE";

class HeadlessContext {
public:
  virtual ~HeadlessContext() = default;
  /// The render window bound to this context; its size is the picture size.
  virtual vtkRenderWindow* window() = 0;
  /// "egl" or "osmesa".
  virtual const char* backend() const = 0;
  /// The device, renderer and version behind this context.
  virtual const RendererInfo& info() const = 0;
};

/// A context of the linked backend with a width x height picture. EGL takes the device ROLLVIZ_EGL_DEVICE
/// names (InputError if there is no such device), else the first hardware device, else Mesa's surfaceless
/// platform, else a software device. Throws HeadlessUnavailable when there is no usable GL at all.
std::unique_ptr<HeadlessContext> createHeadlessContext(int width, int height);

} // namespace rv
