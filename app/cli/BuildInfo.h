// BuildInfo.h -- what `rollviz info` and the GUI's About box say about this executable and its renderer.
#pragma once
#include "render/context/HeadlessContext.h"

#include <string>
#include <vector>

namespace rv {

/// One line of the report: a name and its value.
struct Fact {
  std::string name, value;
};

/// The version, the build and the libraries this executable was built with, and the modules it loaded.
std::vector<Fact> buildFacts();
/// A "module" line per loaded module (its file and what it added), or "modules: none loaded (searched ...)".
std::vector<Fact> moduleFacts();

/// The headless renderer: backend, how the context was made, the EGL devices on offer,
/// GL_VENDOR/RENDERER/VERSION.
std::vector<Fact> rendererFacts(const RendererInfo& info);

/// A warning when the renderer rasterises on the CPU (what it costs, what to do); empty on a GPU.
std::string softwareRendererWarning(const RendererInfo& info);

} // namespace rv
