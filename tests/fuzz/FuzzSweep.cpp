// libFuzzer target: any bytes as a sweep file (run from the project root, so that "scene": "scenes/..."
// loads). Validation either succeeds -- and then the scenes of the grid's first and last points are built --
// or fails with InputError (a grid point with no valid scene: InputError too); any other exception, a crash,
// a sanitizer report, a hang or unbounded memory is a bug. No point is computed: that is the tools' own
// fuzzing.
#include "dynamics/core/Errors.h"
#include "scenes/JsonFields.h"
#include "scenes/SceneLoader.h"
#include "scenes/Sweep.h"

#include <cstddef>
#include <cstdint>
#include <sstream>
#include <string>

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  std::istringstream in(std::string(reinterpret_cast<const char*>(data), size));
  try {
    const rv::SweepSpec spec = rv::sweepFromJson(rv::parseSceneJson(in, "fuzz.json"), "fuzz.json");
    (void)rv::sweepCsvHeader(spec);
    for (const long i : {0L, spec.points() - 1}) {
      try {
        (void)rv::sweepPointScene(spec, i);
      } catch (const rv::InputError&) {
      }
    }
  } catch (const rv::InputError&) {
  } catch (const rv::ComputationError&) {
  }
  return 0;
}
