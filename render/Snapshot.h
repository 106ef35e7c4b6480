// Snapshot.h -- pictures of a render window: RGB pixels for tests and video, PNG files for users.
#pragma once
#include <string>
#include <vector>

class vtkRenderWindow;

namespace rv {

/// An 8-bit RGB picture, rows from the top.
struct Image {
  int width = 0, height = 0;
  std::vector<unsigned char> rgb;
};

/// Renders the window and reads its pixels back.
Image capture(vtkRenderWindow* window);
/// The same into `into`, reusing its storage: a video's frames then cost no allocation (and no page faults).
void captureInto(vtkRenderWindow* window, Image& into);

/// How a snapshot differs from the window it is taken of.
struct SnapshotOptions {
  int scale = 1; ///< the picture is scale x the window's size, rendered in tiles (vtkRenderLargeImage)
  bool transparent = false; ///< RGBA with the background transparent (scale 1 only)
};

/// Renders the window and writes a PNG to `path` through a temporary name (AtomicFile).
/// Throws InputError when the path cannot be written (naming `what`) or the options conflict,
/// ComputationError when writing fails.
void writePng(vtkRenderWindow* window, const std::string& path, const std::string& what = "-o",
              const SnapshotOptions& options = {});

/// Writes an Image as PNG (used for test artifacts and difference images).
void writePng(const Image& image, const std::string& path);

/// Reads a PNG into an RGB Image; throws ComputationError when it cannot.
Image readPng(const std::string& path);

} // namespace rv
