// Figure.h -- a chart written as a figure in the format its file's extension names: PNG (pixels), SVG or PDF
// (vectors, through VTK's GL2PS exporter: lines and markers as paths, text as text -- searchable,
// selectable).
#pragma once
#include "render/Snapshot.h"

#include <string>
#include <vector>

class vtkRenderWindow;

namespace rv {

enum class FigureFormat { Png, Svg, Pdf };

/// The extensions of the figure formats: ".png", ".svg", ".pdf".
const std::vector<std::string>& figureExtensions();

/// The format `path`'s extension names (any case); InputError "WHAT PATH: unsupported format ..." listing the
/// supported ones otherwise.
FigureFormat figureFormat(const std::string& path, const std::string& what);

/// Writes the chart shown in `window` to `path` in the format its extension names, through a temporary name.
/// `options` apply to PNG (a scale, a transparent background); a vector figure has the window's size. The
/// window's GL context must be current (headless windows are; a GUI widget makes its own current first).
/// InputError naming `what` for an unsupported extension or a path that cannot be written; ComputationError
/// when writing fails. The pictures inside charts (cells, colour bars) go into vector figures as rectangles
/// (render/charts/VectorPictures.h).
void writeFigure(vtkRenderWindow* window, const std::string& path, const std::string& what = "-o",
                 const SnapshotOptions& options = {});

} // namespace rv
