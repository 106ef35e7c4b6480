// ScenePage.h -- a scene's or a session's motion as a self-contained web page (render/export/WebPage.h): the
// scene's video section says how long it plays and at what rate, the view's speed how fast; a session adds
// its Poincare map beside the 3D view. One definition for `rollviz page`, the GUI's File > Export web page
// and Python's Scene.page / Session.page.
#pragma once
#include "dynamics/jobs/Task.h"
#include "render/export/WebPage.h"
#include "scenes/Scene.h"
#include "scenes/Session.h"

#include <functional>
#include <optional>
#include <string>

namespace rv {

/// What a front end was given beside the scene (unset: the scene's video.duration, video.fps, view.speed),
/// and the names its messages use for them.
struct PageOverrides {
  std::optional<double> duration, speed;
  std::optional<int> fps;
  std::string durationName = "--duration", fpsName = "--fps", speedName = "--speed";
};

/// The page's settings for a scene: its title, description, parameters, state names and timing. InputError
/// naming the override (or the scene's key) for a duration, rate or speed out of range.
PageSpec pageSpec(const Scene& scene, const PageOverrides& given = {});

/// A session's map as drawn in the GUI: every trajectory's shown points (its Set range) in its colour, the
/// fixed points and families its tools drew (a search: its path, its steps and a marker where it ended).
PageMap sessionPageMap(const Session& session);

/// Writes the page of `scene` (with `session`'s map when given) to `path` (.html; InputError otherwise).
/// Returns the frames written, 0 when `progress` cancelled (nothing written).
long writeScenePage(const Scene& scene, const Session* session, const std::string& path,
                    const PageOverrides& given = {}, const std::function<bool(long, long)>& progress = {});

/// Writing a page as a job's work (the GUI's File > Export web page: listed in the tool manager with its
/// progress, off the GUI thread). A stop leaves nothing written; the next run starts again.
class PageTask final : public Task {
public:
  /// `document` is the scene as the window runs it, `source` names it in messages; `session` (optional) the
  /// map shown beside the motion.
  PageTask(nlohmann::json document, std::string source, std::optional<Session> session, std::string path);
  std::string name() const override { return "Web page"; }
  std::string describe() const override;
  bool run(const ToolControl& control) override;
  void reset() override {}
  bool ownsItsScene() const override { return true; }
  const std::string& path() const { return path_; }

private:
  nlohmann::json document_;
  std::string source_;
  std::optional<Session> session_;
  std::string path_;
};

} // namespace rv
