// libFuzzer target: any bytes as a scene file. Loading either succeeds (and the scene then takes a few
// integration steps) or fails with InputError / ComputationError; any other exception, a crash, a sanitizer
// report, a hang or unbounded memory is a bug. Seeded with scenes/ (tests/fuzz/run.sh).
#include "dynamics/core/Errors.h"
#include "scenes/JsonFields.h"
#include "scenes/SceneLoader.h"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const rv::Scene scene = rv::sceneFromJson(rv::parseSceneJson(in, "fuzz.json"), "fuzz.json");
    auto integrator = scene.startIntegrator();
    for (int i = 0; i < 5; ++i)
      integrator->step();
  } catch (const rv::InputError&) {
  } catch (const rv::ComputationError&) {
  }
  return 0;
}
