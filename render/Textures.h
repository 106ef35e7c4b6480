// Textures.h -- procedural textures (no image files needed): the ball's meridian/parallel pattern and the
// plane's checkerboard with a grid.
#pragma once
#include "render/ViewOptions.h"

#include <functional>
#include <vtkSmartPointer.h>

class vtkTexture;

namespace rv {

/// Longitude-latitude map for vtkTexturedSphereSource: eight coloured sectors, two hemispheres in two
/// tones, dark meridians and parallels every 30 degrees.
vtkSmartPointer<vtkTexture> makeBallTexture(const Rgb& colour);

/// One checkerboard cell pair (2 x 2 cells) with grid lines on the cell edges; repeats.
vtkSmartPointer<vtkTexture> makeCheckerTexture(const Rgb& light, const Rgb& dark, const Rgb& line);

/// The texture an object's options ask for: its own (`texture` empty: `own()`), none ("none": nullptr), or a
/// PNG file, repeated `gridDensity` times as often as the object's own. Throws ComputationError when the PNG
/// cannot be read.
vtkSmartPointer<vtkTexture> textureFor(const ObjectOptions& options,
                                       const std::function<vtkSmartPointer<vtkTexture>()>& own);

} // namespace rv
