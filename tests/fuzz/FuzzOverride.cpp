// libFuzzer target: `--set` arguments. The input's first byte picks a shipped scene, the rest are lines
// "KEY=VALUE" given as --set; the scene then loads or fails with InputError (ComputationError for a failed
// first steps). Anything else -- another exception, a crash, a sanitizer report, a hang -- is a bug.
#include "dynamics/core/Errors.h"
#include "scenes/SceneLoader.h"

#include <cstddef>
#include <cstdint>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {
const char* const kScenes[] = {"chaplygin_ball", "lorenz", "henon_heiles", "ellipsoid_on_plane",
                               "standard_map"};

nlohmann::json shipped(std::size_t i) {
  static std::vector<nlohmann::json> docs = [] {
    std::vector<nlohmann::json> v;
    for (const char* id : kScenes) {
      std::ifstream in(rv::defaultScenePath(id));
      v.push_back(nlohmann::json::parse(in));
    }
    return v;
  }();
  return docs[i % docs.size()];
}
} // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  if (size == 0) return 0;
  std::istringstream lines(std::string(reinterpret_cast<const char*>(data) + 1, size - 1));
  try {
    std::vector<rv::SceneOverride> sets;
    for (std::string line; std::getline(lines, line) && sets.size() < 16;)
      sets.push_back(rv::parseOverride(line));
    const rv::Scene scene = rv::sceneFromJson(shipped(data[0]), "fuzz.json", sets);
    auto integrator = scene.startIntegrator();
    for (int i = 0; i < 5; ++i)
      integrator->step();
  } catch (const rv::InputError&) {
  } catch (const rv::ComputationError&) {
  }
  return 0;
}
