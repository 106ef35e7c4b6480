#include "scenes/Gallery.h"

#include "dynamics/core/Errors.h"
#include "scenes/SceneLoader.h"

#include <algorithm>
#include <filesystem>

namespace rv {

std::string galleryDirectory() {
  return (std::filesystem::path(scenesDirectory()) / "gallery").string();
}

std::vector<GalleryScene> galleryScenes() {
  namespace fs = std::filesystem;
  std::vector<std::string> files;
  std::error_code ec;
  for (const auto& f : fs::directory_iterator(galleryDirectory(), ec))
    if (f.path().extension() == ".json") files.push_back(f.path().string());
  std::sort(files.begin(), files.end());
  std::vector<GalleryScene> scenes;
  for (const auto& file : files) {
    const Scene scene = loadScene(file);
    GalleryScene g;
    g.id = fs::path(file).stem().string();
    g.path = file;
    g.title = scene.document.value("title", std::string());
    g.description = scene.document.value("description", std::string());
    if (g.title.empty() || g.description.empty())
      throw InputError(file + ": a gallery scene needs a title and a description (what to watch)");
    g.time = scene.tool("video")["duration"] * scene.view.speed;
    scenes.push_back(std::move(g));
  }
  return scenes;
}

std::string galleryThumbnail(const GalleryScene& scene) {
  return (std::filesystem::path(scenesDirectory()).parent_path() / "assets" / "baselines" /
          ("gallery_" + scene.id + ".png"))
      .string();
}

} // namespace rv
