// ViewEdits.cpp -- the user's appearance edits: laid over a scene's view, written into its document.
#include "app/gui/ViewEdits.h"

#include "app/gui/VisualizerSettings.h"

namespace rv {

ViewOptions ViewEdits::over(const ViewOptions& base) const {
  ViewOptions v = base;
  for (const auto& [name, o] : objects_)
    v.objects[name] = o;
  if (axes_) v.axes = *axes_;
  if (follow_) v.camera.follow = *follow_;
  return v;
}

void ViewEdits::writeInto(nlohmann::json& doc) const {
  for (const auto& [name, o] : objects_) {
    auto& j = doc["view"]["objects"][name];
    j["enabled"] = o.enabled;
    if (o.colour) j["color"] = colourText(*o.colour);
    if (o.traceColour) j["trace_color"] = colourText(*o.traceColour);
    if (o.opacity) j["opacity"] = *o.opacity;
    if (o.gridDensity != 1) j["grid_density"] = o.gridDensity;
    if (!o.trace) j["trace"] = false;
    j["style"] = o.style == SurfaceStyle::Grid ? "grid" : o.style == SurfaceStyle::Both ? "both" : "fill";
  }
  if (axes_) {
    const AxesOptions& a = *axes_;
    auto& j = doc["view"]["axes"];
    j["style"] = a.style == AxesOptions::Style::Box      ? "box"
                 : a.style == AxesOptions::Style::Normal ? "normal"
                                                         : "none";
    j["ticks"] = a.ticks;
    if (a.min && a.max) j["min"] = *a.min, j["max"] = *a.max;
    j["tickmarks"] = a.tickmarks;
    j["subticks"] = a.subticks;
  }
  if (follow_) doc["view"]["camera"]["follow"] = *follow_;
}

} // namespace rv
