// VideoSettings.h -- the scene's "video" section: what `rollviz video`, the GUI's Record and the Python
// module make a video with (frame rate, size, length, and the H.264 encoder's quality and speed), beside the
// encoder that reads it (VideoExport.h turns it into a VideoSpec). Registered as a settings section of the
// tool registry (dynamics/tools/ToolRegistry.h addToolSection) by the scenes layer when it loads, so that
// scenes, --set, the GUI's tabs and Python read one table, as they read the tools'. Pure data: nothing here
// encodes.
#pragma once
#include "dynamics/core/ParameterTable.h"

namespace rv {

/// fps, width, height, duration, crf, preset (x264's names, "ultrafast" .. "veryslow").
const ParameterTable& videoTable();

/// Adds the "video" section to the settings sections (once; thread-safe).
void registerVideoSection();

} // namespace rv
