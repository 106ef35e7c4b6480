// Gallery.h -- the curated scenes of scenes/gallery/: famous motions a student opens without knowing the
// numbers (`rollviz list gallery`, the GUI's File > Gallery, the guide's gallery page). Each file is an
// ordinary scene with a title and a description of what to watch; its picture is the 3D view at the end of
// its video (video.duration x view.speed), rendered by the tests against a baseline that is also its
// thumbnail.
#pragma once
#include <string>
#include <vector>

namespace rv {

/// One gallery scene.
struct GalleryScene {
  std::string id;          ///< the file's stem, e.g. "rattleback_reversal"
  std::string path;        ///< the scene file
  std::string title;       ///< the scene's title
  std::string description; ///< what to watch
  double time = 0;         ///< the picture's time: the end of its video (video.duration x view.speed)
};

/// The folder of the gallery's scenes (beside the default scenes).
std::string galleryDirectory();
/// Every gallery scene, by file name; InputError naming the file when one is not a valid scene or has no
/// title or description.
std::vector<GalleryScene> galleryScenes();
/// The thumbnail of a gallery scene (its render test's baseline, assets/baselines/gallery_ID.png).
std::string galleryThumbnail(const GalleryScene& scene);

} // namespace rv
