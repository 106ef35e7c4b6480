#include "render/video/VideoSettings.h"

#include "dynamics/tools/ToolRegistry.h"

#include <mutex>

namespace rv {

const ParameterTable& videoTable() {
  static const ParameterTable t{
      {.id = "fps",
       .label = "Frames per second",
       .defaultValue = 25,
       .min = 1,
       .max = 240,
       .description = "frames per second of video (the GUI's Record too)",
       .integer = true},
      {.id = "width",
       .label = "Width",
       .defaultValue = 1280,
       .min = 16,
       .max = 16384,
       .unit = "pixels",
       .description = "the frame's width in pixels, even (rollviz video; Record takes the view's size)",
       .integer = true},
      {.id = "height",
       .label = "Height",
       .defaultValue = 720,
       .min = 16,
       .max = 16384,
       .unit = "pixels",
       .description = "the frame's height in pixels, even (rollviz video; Record takes the view's size)",
       .integer = true},
      {.id = "duration",
       .label = "Duration",
       .defaultValue = 5,
       .min = 1e-3,
       .max = 1e6,
       .unit = "s",
       .description = "seconds of video (rollviz video); view.speed sets the simulation time per second"},
      {.id = "crf",
       .label = "Quality (CRF)",
       .defaultValue = 20,
       .min = 0,
       .max = 51,
       .description =
           "H.264 constant rate factor: 0 lossless, 18 visually lossless, 23 x264's default, 51 worst",
       .integer = true},
      {.id = "preset",
       .label = "Encoder preset",
       .defaultValue = 2,
       .min = 0,
       .max = 8,
       .description = "x264's speed against size at the same quality: ultrafast writes fastest and largest, "
                      "veryslow smallest",
       .integer = true,
       .choices = {"ultrafast", "superfast", "veryfast", "faster", "fast", "medium", "slow", "slower",
                   "veryslow"}},
  };
  return t;
}

void registerVideoSection() {
  static std::once_flag once;
  std::call_once(once, [] { addToolSection({"video", "Video", &videoTable()}); });
}

} // namespace rv
