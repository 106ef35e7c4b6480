#include "app/cli/BuildInfo.h"

#include "dynamics/core/Lanes.h"
#include "render/video/Mp4Writer.h"
#include "scenes/ModelCompiler.h"
#include "scenes/ModuleLoader.h"

#include <Eigen/Core>
#include <fmt/core.h>
#include <vtkVersion.h>

#ifndef ROLLVIZ_VERSION
#define ROLLVIZ_VERSION "unknown"
#endif
#ifndef ROLLVIZ_BUILD_TYPE
#define ROLLVIZ_BUILD_TYPE "unknown"
#endif

namespace rv {

std::vector<Fact> buildFacts() {
  std::vector<Fact> facts{
      {"rollviz", ROLLVIZ_VERSION},
      {"build", fmt::format("{}, {} {}", ROLLVIZ_BUILD_TYPE,
#if defined(__clang__)
                            "clang",
#else
                            "g++",
#endif
                            __VERSION__)},
      {"VTK", vtkVersion::GetVTKVersion()},
      {"Eigen", fmt::format("{}.{}.{}", EIGEN_WORLD_VERSION, EIGEN_MAJOR_VERSION, EIGEN_MINOR_VERSION)},
      {"libav", libavVersions()},
      {"fmt", fmt::format("{}.{}.{}", FMT_VERSION / 10000, FMT_VERSION / 100 % 100, FMT_VERSION % 100)},
      {"module stamp", moduleStamp()},
      {"SIMD lanes",
       laneDescription() +
           " (sweeps of MEGNO and Lyapunov exponents over initial points and parameters with rk4; --lanes 1: "
           "one at a time, --lanes 4 or 8: that many)"}};
  std::string compiler;
  const bool compiles = modelCompilationAvailable(&compiler);
  facts.push_back(
      {"model files", compiles ? (compileModelsByDefault() ? "compiled to native code on first use ("
                                                           : "interpreted (ROLLVIZ_COMPILE_MODELS=0; ") +
                                     compiler + ")"
                               : "interpreted only: " + compiler});
  for (const auto& f : moduleFacts())
    facts.push_back(f);
  return facts;
}

std::vector<Fact> moduleFacts() {
  std::vector<Fact> facts;
  const auto list = [](const std::vector<std::string>& ids) {
    std::string s;
    for (const auto& id : ids)
      s += (s.empty() ? "" : ", ") + id;
    return s;
  };
  for (const auto& m : loadedModules()) {
    std::string added;
    for (const auto& [kind, ids] : {std::pair{"problems", &m.models}, std::pair{"tools", &m.tools},
                                    std::pair{"integrators", &m.integrators}})
      if (!ids->empty()) added += fmt::format("{}{}: {}", added.empty() ? "" : "; ", kind, list(*ids));
    facts.push_back({"module", m.path + (added.empty() ? " (added nothing)" : " (" + added + ")")});
  }
  if (loadedModules().empty()) {
    std::string where;
    for (const auto& d : moduleSearchPath())
      where += (where.empty() ? "" : ":") + d;
    facts.push_back({"modules", "none loaded (searched " + where + ")"});
  }
  return facts;
}

std::vector<Fact> rendererFacts(const RendererInfo& info) {
  std::vector<Fact> facts{{"backend", info.backend}, {"context", info.context}};
  if (info.backend == "egl") {
    std::string devices;
    for (const auto& d : info.devices)
      devices += (devices.empty() ? "" : "; ") + d;
    facts.push_back({"EGL devices", devices.empty() ? "none enumerated" : devices});
  }
  facts.push_back({"GL_VENDOR", info.vendor});
  facts.push_back({"GL_RENDERER", info.renderer});
  facts.push_back({"GL_VERSION", info.version});
  return facts;
}

std::string softwareRendererWarning(const RendererInfo& info) {
  if (!info.software) return {};
  if (info.backend == "osmesa")
    return fmt::format(
        "rendering on the CPU ({}): OSMesa never uses a GPU; `rollviz` (EGL) does where there is one.",
        info.renderer);
  if (info.backend != "egl") // the GUI's window, drawn by the X server's GL
    return fmt::format(
        "rendering on the CPU ({}): a 1280x720 frame costs ~20 ms, a GPU ~1 ms (over ssh -X, under "
        "xvfb or without the GPU's GL driver the window is drawn in software).",
        info.renderer);
  bool hardwareOffered = false;
  for (const auto& d : info.devices)
    hardwareOffered = hardwareOffered || d.find("software") == std::string::npos;
  return fmt::format(
      "rendering on the CPU ({}): a 1280x720 frame costs ~20 ms and a 10^6-point chart ~100 ms, "
      "a GPU ~1 ms. {}",
      info.renderer,
      hardwareOffered
          ? fmt::format("A hardware EGL device is listed: choose it with {}=N.", kEglDeviceVariable)
          : std::string("No hardware EGL device was found (on a GPU node: is the "
                        "driver's EGL vendor library installed?)."));
}

} // namespace rv
