// VideoSettings.h -- the scene's "video" section: what `rollviz video`, the GUI's Record and the Python
// module make a video with (frame rate, size, length, and the H.264 encoder's quality and speed). Declared
// here with the other settings sections (ToolRegistry.h toolSections) so that scenes, --set, the GUI's tabs
// and Python read one table; render/video/VideoExport.h turns it into a VideoSpec. Pure data: nothing here
// encodes.
#pragma once
#include "dynamics/core/ParameterTable.h"

namespace rv {

/// fps, width, height, duration, crf, preset (x264's names, "ultrafast" .. "veryslow").
const ParameterTable& videoTable();

} // namespace rv
