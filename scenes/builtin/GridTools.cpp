// GridTools.cpp -- the surface |Map^n(x) - x| and the region of allowed motion (manual §2.3.8-9) as tools
// (BuiltinTool.h): a grid of the map's plane (or space) evaluated by dynamics/tools/MapGrid.h, resumable, its
// rows the grid's nodes (ToolResult::grid), so the CLI writes CSV or .vti, Python gives shaped arrays and the
// chart window draws the grid -- all derived from the entry. Their call arguments (--x MIN,MAX, --z, --step,
// --order, --level) are scene settings of the grid and fixedpoint sections. Free of VTK.
#include "dynamics/core/Errors.h"
#include "dynamics/core/Format.h"
#include "dynamics/tools/FixedPoint.h"
#include "dynamics/tools/MapGrid.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/FixedPointJson.h"
#include "scenes/JsonFields.h"
#include "scenes/SceneTools.h"
#include "scenes/builtin/BuiltinTool.h"

#include <cmath>
#include <limits>

namespace rv {

namespace {

std::string number(double x) {
  return format("%.17g", x);
}

// MIN,MAX of an axis as its two settings
ToolArgument rangeArgument(const std::string& name, const std::string& which) {
  return {name, "MIN,MAX",
          "the grid's range of the " + which + " map coordinate (grid." + name + "_min, " + name + "_max)",
          [name](const std::string& value) {
            const auto r = commaNumbers(value);
            if (r.size() != 2 || !(r[0] <= r[1])) throw InputError("expected MIN,MAX with MIN <= MAX");
            return std::vector<SceneOverride>{{"grid." + name + "_min", number(r[0])},
                                              {"grid." + name + "_max", number(r[1])}};
          }};
}

std::vector<ToolArgument> gridArguments(bool ram) {
  std::vector<ToolArgument> a{
      rangeArgument("x", "first"),
      rangeArgument("y", "second"),
      {"z", "Z|MIN,MAX",
       "3D maps: the plane z = Z of a 2D grid (grid.z), or MIN,MAX: a 3D grid in space (grid.section 3D, "
       "z_min, z_max)",
       [](const std::string& value) {
         const auto r = commaNumbers(value);
         if (r.size() == 1)
           return std::vector<SceneOverride>{{"grid.section", "\"2D\""}, {"grid.z", number(r[0])}};
         if (r.size() != 2 || !(r[0] <= r[1])) throw InputError("expected Z or MIN,MAX with MIN <= MAX");
         return std::vector<SceneOverride>{
             {"grid.section", "\"3D\""}, {"grid.z_min", number(r[0])}, {"grid.z_max", number(r[1])}};
       }},
      {"step", "S", "the grid's step along every axis (grid.step_x, step_y, step_z)",
       [](const std::string& value) {
         const auto r = commaNumbers(value);
         if (r.size() != 1 || !(r[0] > 0)) throw InputError("expected one positive step");
         std::vector<SceneOverride> o;
         for (const char* k : {"grid.step_x", "grid.step_y", "grid.step_z"})
           o.push_back({k, number(r[0])});
         return o;
       }},
      {"order", "N", "the order n of the map Map^n (fixedpoint.order)", [](const std::string& value) {
         const auto r = commaNumbers(value);
         if (r.size() != 1 || r[0] < 1 || r[0] != std::floor(r[0]))
           throw InputError("expected an order n >= 1");
         return std::vector<SceneOverride>{{"fixedpoint.order", number(r[0])}};
       }}};
  if (ram)
    a.push_back({"level", "OBSERVABLE",
                 "2D maps: the observable whose value is the energy level's height above the region "
                 "(grid.level; default: the state component the section completes)",
                 [](const std::string& value) {
                   return std::vector<SceneOverride>{{"grid.level", nlohmann::json(value).dump()}};
                 }});
  return a;
}

// A grid of the scene's map, evaluated row by row on grid.threads threads (the same numbers on any), and for
// the surface the search path of the scene's fixed point drawn on it (manual: "show the point on the
// surface") when the scene gives fixedpoint.guess.
class GridRun final : public ToolRun {
public:
  GridRun(const Scene& scene, MapGrid::Kind kind)
      : kind_(kind), sceneMap_(Scene(scene), {}, false), map_(sceneMap_.map()),
        grid_(map_, kind, gridSettingsTable().read(scene.tool("grid")),
              scene.document.value("grid", nlohmann::json::object()).value("level", std::string())),
        searches_(kind == MapGrid::Kind::Surface && !scene.guess.empty()) {}

  bool advance(const ToolControl& control) override {
    if (!grid_.run(control)) return false;
    if (searches_ && !searched_) {
      path_.clear();
      try {
        (void)findFixedPoint(map_, sceneMap_.guess(), sceneMap_.search(), control,
                             [&](const SearchPoint& p) { path_.push_back(toVector(p.point)); });
        searchEnd_ = "converged";
      } catch (const ComputationError& e) { // a failed search is still worth seeing
        searchEnd_ = e.what();
      } catch (const Stopped&) {
        return false;
      }
      searched_ = true;
    }
    return true;
  }

  ToolResult result() const override {
    const GridSettings& g = grid_.settings();
    const GridValues& r = grid_.result();
    const bool surface = kind_ == MapGrid::Kind::Surface;
    const int columns = g.threeD || map_.dimension() == 3 ? 3 : 2;
    ToolResult out;
    out.grid.dimensions = g.threeD ? 3 : 2;
    out.grid.coordinates = columns;
    out.grid.size = r.size;
    for (int a = 0; a < 3; ++a)
      out.grid.origin[a] = g.axes[a].min, out.grid.spacing[a] = g.axes[a].step;
    if (!g.threeD) out.grid.origin[2] = map_.dimension() == 3 ? g.zValue : 0, out.grid.spacing[2] = 1;
    auto& t = out.table;
    t.names.assign(map_.coordinateNames().begin(), map_.coordinateNames().begin() + columns);
    t.names.emplace_back(surface ? "distance" : "allowed");
    if (!surface) t.names.emplace_back("level");
    t.values.assign(t.names.size(), {});
    double least = std::numeric_limits<double>::infinity();
    std::vector<double> leastAt;
    long allowed = 0;
    for (int k = 0; k < r.size[2]; ++k)
      for (int j = 0; j < r.size[1]; ++j)
        for (int i = 0; i < r.size[0]; ++i) {
          const std::size_t at = (static_cast<std::size_t>(k) * r.size[1] + j) * r.size[0] + i;
          const Eigen::VectorXd node = grid_.node(i, j, k);
          for (int c = 0; c < columns; ++c)
            t.values[c].push_back(node[c]);
          const double v = r.values[at];
          t.values[columns].push_back(v);
          if (!surface) t.values[columns + 1].push_back(r.level.empty() ? NAN : r.level[at]);
          if (surface && v < least) least = v, leastAt.assign(node.data(), node.data() + columns);
          if (!surface && v == 1) ++allowed;
        }
    out.fields = {{"nodes", t.rows()}, {"done", r.done}};
    if (surface) {
      nlohmann::json path = nlohmann::json::array();
      for (const auto& p : path_)
        path.push_back(p);
      out.fields["least"] =
          leastAt.empty() ? nlohmann::json(nullptr) : nlohmann::json{{"distance", least}, {"at", leastAt}};
      out.fields["search_path"] = path;
      if (!searchEnd_.empty()) out.fields["search"] = searchEnd_;
    } else {
      out.fields["allowed_fraction"] =
          r.done > 0 ? static_cast<double>(allowed) / static_cast<double>(r.done) : 0.0;
      out.fields["level_name"] = grid_.levelName();
    }
    return out;
  }

  void save(Snapshot& state) const override { grid_.save(state); }
  void restore(Snapshot& state) override { grid_.restore(state); }

private:
  MapGrid::Kind kind_;
  SceneMap sceneMap_;
  ReturnMap map_;
  MapGrid grid_;
  bool searches_, searched_ = false;
  std::vector<std::vector<double>> path_;
  std::string searchEnd_;
};

ToolRunner gridRunner(MapGrid::Kind kind) {
  return {.start = [kind](const Scene& s) { return std::make_unique<GridRun>(s, kind); },
          .arguments = gridArguments(kind == MapGrid::Kind::AllowedRegion),
          .grid = true,
          .resultIndependent = {"threads"}};
}

} // namespace

BuiltinTool surfaceTool() {
  return {
      .entry = {.id = "surface",
                .title = "Surface |Map(x) - x|",
                .description = "on the grid section's rectangle (a chart window)",
                .section = "grid",
                .command = "surface",
                .commandHelp = "the surface z = |Map^n(x) - x| on a grid: CSV or .vti image data",
                .chartView = "surface",
                .outputs =
                    {{"<map coordinates>", "the grid's node (x fastest)"},
                     {"distance",
                      "|Map^n(x) - x| at the node: zeros are fixed points (NaN: the map is undefined)"},
                     {"least", "the node of the least distance: distance, at (a guess for a fixed point)"},
                     {"nodes", "how many nodes the grid has"},
                     {"done", "how many of them are evaluated"},
                     {"search_path",
                      "with fixedpoint.guess: the search's path from it, drawn on the surface (else empty)"}},
                .reference = "manual §2.3.8",
                .computation = "dynamics/tools/MapGrid.h (MapGrid); runner scenes/builtin/GridTools.cpp",
                .alsoSections = {"fixedpoint"}},
      .settings = ToolSection{.title = "Surface |Map(x) - x| and region of allowed motion",
                              .table = &gridSettingsTable().table()},
      .runner = gridRunner(MapGrid::Kind::Surface)};
}

BuiltinTool ramTool() {
  return {
      .entry = {.id = "ram",
                .title = "Region of allowed motion",
                .description = "on the grid section's rectangle (a chart window)",
                .section = "grid",
                .command = "ram",
                .commandHelp =
                    "the region of allowed motion on a grid of the map's plane: CSV or .vti image data",
                .chartView = "ram",
                .outputs = {{"<map coordinates>", "the grid's node (x fastest)"},
                            {"allowed", "1 where motion is allowed at the node, 0 where not"},
                            {"level",
                             "2D maps: the height of the energy level above the region (NaN elsewhere)"},
                            {"level_name", "the observable whose value `level` is (grid.level)"},
                            {"allowed_fraction", "the share of the evaluated nodes where motion is allowed"},
                            {"nodes", "how many nodes the grid has"},
                            {"done", "how many of them are evaluated"}},
                .reference = "manual §2.3.9",
                .computation = "dynamics/tools/MapGrid.h (MapGrid); runner scenes/builtin/GridTools.cpp",
                .alsoSections = {"fixedpoint"}}, // its settings: the surface's section
      .runner = gridRunner(MapGrid::Kind::AllowedRegion)};
}

} // namespace rv
