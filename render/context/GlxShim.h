// GlxShim.h -- lets Debian's VTK 9.1 (GLEW 2.2, GLX build) run on an EGL or OSMesa context.
// libGLEW resolves every GL entry point through glXGetProcAddressARB and then requires
// glXGetCurrentDisplay() != NULL; VTK 9.1 aborts its GL initialisation on any glewInit() error.
// These definitions, exported from the executable (ROLLVIZ_GLX_SHIM_EXPORTS), take precedence over
// libGLX's. With no loader set they forward to libGLX, so a GLX (Qt/Xvfb) process is unaffected.
// Include in exactly one translation unit per executable (each headless backend's .cpp).
#pragma once
#include <cstring>
#include <dlfcn.h>

namespace rv::glxshim {
using Proc = void (*)();
using Loader = Proc (*)(const char*);
inline Loader loader = nullptr; ///< set by a headless backend once its context is current
inline char fakeDisplay[64];
template <class F> F real(const char* name) {
  return reinterpret_cast<F>(dlsym(RTLD_NEXT, name));
}
} // namespace rv::glxshim

extern "C" {
static void* rvShimGetCurrentDisplay() {
  return rv::glxshim::fakeDisplay;
}

__attribute__((visibility("default"))) rv::glxshim::Proc glXGetProcAddressARB(const unsigned char* name) {
  using namespace rv::glxshim;
  if (!loader) return real<Proc (*)(const unsigned char*)>("glXGetProcAddressARB")(name);
  if (!std::strcmp(reinterpret_cast<const char*>(name), "glXGetCurrentDisplay"))
    return reinterpret_cast<Proc>(&rvShimGetCurrentDisplay);
  return loader(reinterpret_cast<const char*>(name));
}
__attribute__((visibility("default"))) rv::glxshim::Proc glXGetProcAddress(const unsigned char* name) {
  return glXGetProcAddressARB(name);
}
__attribute__((visibility("default"))) int glXQueryVersion(void* dpy, int* major, int* minor) {
  using namespace rv::glxshim;
  if (!loader) return real<int (*)(void*, int*, int*)>("glXQueryVersion")(dpy, major, minor);
  *major = 1, *minor = 4;
  return 1;
}
__attribute__((visibility("default"))) const char* glXGetClientString(void* dpy, int name) {
  using namespace rv::glxshim;
  if (!loader) return real<const char* (*)(void*, int)>("glXGetClientString")(dpy, name);
  return "";
}
}
