// ViewEdits.h -- the appearance edits a user makes in the 3D view (settings panel, toolbar: an object's
// colour, style and trace, the axes, Follow body), kept over re-runs of the same scene and laid over the
// scene's own view; Save writes them into the scene document (the keys of docs/scenes.md "view"), so that
// the saved scene opens as it was shown. Another scene file starts with none.
#pragma once
#include "render/ViewOptions.h"

#include <nlohmann/json.hpp>
#include <optional>
#include <string>

namespace rv {

class ViewEdits {
public:
  void setObject(const std::string& name, const ObjectOptions& options) { objects_[name] = options; }
  void setAxes(const AxesOptions& axes) { axes_ = axes; }
  void setFollow(bool follow) { follow_ = follow; }
  /// Forgets every edit (another scene file: its own appearance).
  void clear() { *this = {}; }
  /// The edited axes, if the user edited them.
  const std::optional<AxesOptions>& axes() const { return axes_; }
  /// The scene's view `base` with the edits laid over it.
  ViewOptions over(const ViewOptions& base) const;
  /// Writes the edits into a scene document's "view" (only what was edited).
  void writeInto(nlohmann::json& document) const;

private:
  std::map<std::string, ObjectOptions> objects_;
  std::optional<AxesOptions> axes_;
  std::optional<bool> follow_; ///< Follow body, once toggled (over view.camera.follow)
};

} // namespace rv
