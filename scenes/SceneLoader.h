// SceneLoader.h -- reads scene files (JSON, design.md "Scene file"), applies `--set KEY=VALUE`
// overrides and validates everything; every error reads "file:json-path: reason" (InputError).
#pragma once
#include "scenes/Scene.h"

#include <istream>
#include <set>
#include <string>
#include <vector>

namespace rv {

/// One `--set KEY=VALUE`: a plain KEY is a model parameter, a dotted one a scene field
/// (e.g. integrator.method, initial.map, view.speed). VALUE is JSON when it parses as JSON, else a string.
struct SceneOverride {
  std::string key;
  std::string value;
};

/// Parses "KEY=VALUE"; throws InputError naming the flag when there is no '='.
SceneOverride parseOverride(const std::string& text);

/// The top-level keys of a scene besides the tools' settings sections (ToolRegistry.h toolSections()).
const std::set<std::string>& sceneKeys();

/// Loads and validates a scene file (a folder, an unreadable or empty file: InputError naming it); a GUI
/// session file (scenes/Session.h) gives its scene.
Scene loadScene(const std::string& path, const std::vector<SceneOverride>& overrides = {});

/// Validates a scene document; `source` names it in messages.
Scene sceneFromJson(nlohmann::json document, const std::string& source,
                    const std::vector<SceneOverride>& overrides = {});

/// The folder of the shipped scene files (ROLLVIZ_SCENES_DIR overrides it).
std::string scenesDirectory();

/// scenes/<problem id>.json
std::string defaultScenePath(const std::string& problemId);

} // namespace rv
