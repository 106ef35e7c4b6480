#include "scenes/SceneLoader.h"
#include "scenes/BuiltinTools.h"
#include "scenes/SectionTextKeys.h"
#include "scenes/Session.h"

#include "scenes/JsonFields.h"
#include "scenes/ModelFile.h"

#include "dynamics/core/Errors.h"
#include "dynamics/tools/ToolSettings.h"
#include "render/video/VideoSettings.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>

namespace rv {

using nlohmann::json;

namespace {

// three numbers [x, y, z]
std::array<double, 3> triple(const json& j, const Where& w, bool positive) {
  if (!j.is_array() || j.size() != 3) w.fail("expected three numbers [x, y, z]");
  std::array<double, 3> v{};
  for (int i = 0; i < 3; ++i) {
    v[i] = number(j[i], w / std::to_string(i));
    if (positive && !(v[i] > 0)) (w / std::to_string(i)).fail("must be positive");
  }
  return v;
}

// "none", or a PNG: a path relative to the scene file, or the name of one in assets/textures
std::string texturePath(const std::string& name, const Where& w) {
  namespace fs = std::filesystem;
  if (name == "none") return name;
  std::error_code ec; // a name too long for the system is no file either (not a filesystem_error)
  const fs::path own = fs::path(w.file).parent_path() / name;
  if (fs::is_regular_file(own, ec)) return fs::absolute(own, ec).string();
  const fs::path asset = fs::path(scenesDirectory()).parent_path() / "assets" / "textures" / (name + ".png");
  if (fs::is_regular_file(asset, ec)) return asset.string();
  w.fail("no texture \"" + name + "\" (a PNG next to the scene, a name in assets/textures, or none)");
}

ObjectOptions readObject(const json& j, const Where& w) {
  requireObject(j, w);
  onlyKeys(j, w,
           {"enabled", "color", "opacity", "style", "trace_color", "line_width", "trace", "grid_density",
            "texture", "size", "vector"});
  ObjectOptions o;
  const auto colour = [&](const char* key) {
    const std::string s = text(j[key], w / key);
    const auto c = parseColour(s);
    if (!c) (w / key).fail("expected a colour \"#rrggbb\", got \"" + s + "\"");
    return c;
  };
  if (j.contains("enabled")) o.enabled = boolean(j["enabled"], w / "enabled");
  if (j.contains("color")) o.colour = colour("color");
  if (j.contains("trace_color")) o.traceColour = colour("trace_color");
  if (j.contains("opacity")) {
    o.opacity = number(j["opacity"], w / "opacity");
    if (*o.opacity < 0 || *o.opacity > 1) (w / "opacity").fail("must lie in [0, 1]");
  }
  if (j.contains("line_width")) {
    o.lineWidth = number(j["line_width"], w / "line_width");
    if (!(o.lineWidth > 0 && o.lineWidth <= 50)) (w / "line_width").fail("must lie in (0, 50]");
  }
  if (j.contains("trace")) o.trace = boolean(j["trace"], w / "trace");
  if (j.contains("grid_density")) {
    o.gridDensity = number(j["grid_density"], w / "grid_density");
    if (!(o.gridDensity >= 0.05 && o.gridDensity <= 20)) (w / "grid_density").fail("must lie in [0.05, 20]");
  }
  if (j.contains("texture")) o.texture = texturePath(text(j["texture"], w / "texture"), w / "texture");
  if (j.contains("size")) o.size = triple(j["size"], w / "size", true);
  if (j.contains("vector")) o.vector = triple(j["vector"], w / "vector", false);
  if (j.contains("style")) {
    const std::string s = text(j["style"], w / "style");
    if (s == "fill")
      o.style = SurfaceStyle::Fill;
    else if (s == "grid")
      o.style = SurfaceStyle::Grid;
    else if (s == "both")
      o.style = SurfaceStyle::Both;
    else
      (w / "style").fail("expected fill, grid or both");
  }
  return o;
}

ViewOptions readView(const json& j, const Where& w) {
  requireObject(j, w);
  onlyKeys(j, w,
           {"objects", "camera", "overlay", "speed", "max_trace_points", "multisamples", "kind", "looking_in",
            "axes"});
  ViewOptions v;
  if (j.contains("objects")) {
    requireObject(j["objects"], w / "objects");
    for (const auto& [name, o] : j["objects"].items())
      v.objects[name] = readObject(o, w / "objects" / name);
  }
  if (j.contains("camera")) {
    const Where wc = w / "camera";
    const json& c = requireObject(j["camera"], wc);
    onlyKeys(c, wc, {"follow", "distance", "elevation", "azimuth"});
    if (c.contains("follow")) v.camera.follow = boolean(c["follow"], wc / "follow");
    if (c.contains("distance")) v.camera.distance = number(c["distance"], wc / "distance");
    if (c.contains("elevation")) v.camera.elevation = number(c["elevation"], wc / "elevation");
    if (c.contains("azimuth")) v.camera.azimuth = number(c["azimuth"], wc / "azimuth");
    if (v.camera.distance < 0) (wc / "distance").fail("must not be negative");
  }
  if (j.contains("overlay")) v.overlay = boolean(j["overlay"], w / "overlay");
  if (j.contains("speed")) {
    v.speed = number(j["speed"], w / "speed");
    if (!(v.speed > 0)) (w / "speed").fail("must be positive");
  }
  if (j.contains("multisamples")) {
    v.multisamples = static_cast<int>(number(j["multisamples"], w / "multisamples"));
    if (v.multisamples < 0 || v.multisamples > 16) (w / "multisamples").fail("must lie in [0, 16]");
  }
  if (j.contains("kind")) {
    const std::string s = text(j["kind"], w / "kind");
    if (s != "motion" && s != "apex") (w / "kind").fail("expected motion or apex, got \"" + s + "\"");
    v.kind = s == "apex" ? ViewKind::Apex : ViewKind::Motion;
  }
  if (j.contains("looking_in")) {
    const std::string s = text(j["looking_in"], w / "looking_in");
    if (s != "absolute" && s != "body")
      (w / "looking_in").fail("expected absolute or body, got \"" + s + "\"");
    v.lookingIn = s == "body" ? LookingIn::Body : LookingIn::Absolute;
  }
  if (j.contains("axes")) {
    const Where wa = w / "axes";
    const json& a = requireObject(j["axes"], wa);
    onlyKeys(a, wa, {"style", "ticks", "min", "max", "tickmarks", "subticks"});
    if (a.contains("style")) {
      const std::string s = text(a["style"], wa / "style");
      if (s == "none")
        v.axes.style = AxesOptions::Style::None;
      else if (s == "normal")
        v.axes.style = AxesOptions::Style::Normal;
      else if (s == "box")
        v.axes.style = AxesOptions::Style::Box;
      else
        (wa / "style").fail("expected none, normal or box, got \"" + s + "\"");
    }
    if (a.contains("ticks")) v.axes.ticks = boolean(a["ticks"], wa / "ticks");
    if (a.contains("min")) v.axes.min = triple(a["min"], wa / "min", false);
    if (a.contains("max")) v.axes.max = triple(a["max"], wa / "max", false);
    if (v.axes.min && v.axes.max)
      for (int i = 0; i < 3; ++i)
        if (!((*v.axes.max)[i] > (*v.axes.min)[i])) (wa / "max").fail("must exceed min on every axis");
    const auto count = [&](const char* key, int lo, int hi) {
      const double n = number(a[key], wa / key);
      if (n != std::floor(n) || n < lo || n > hi)
        (wa / key).fail("must be a whole number in [" + std::to_string(lo) + ", " + std::to_string(hi) + "]");
      return static_cast<int>(n);
    };
    if (a.contains("tickmarks")) v.axes.tickmarks = count("tickmarks", 1, 50);
    if (a.contains("subticks")) v.axes.subticks = count("subticks", 0, 20);
  }
  if (j.contains("max_trace_points")) {
    v.maxTracePoints = static_cast<long>(number(j["max_trace_points"], w / "max_trace_points"));
    if (v.maxTracePoints < 2) (w / "max_trace_points").fail("must be at least 2");
  }
  return v;
}

Eigen::VectorXd readInitial(const json& j, const Where& w, const Model& model,
                            const SectionSettings& poincare) {
  requireObject(j, w);
  onlyKeys(j, w, {"map", "root", "state", "exact"});
  if (j.contains("map") == j.contains("state")) w.fail("give exactly one of \"map\" or \"state\"");
  const bool exact = j.contains("exact") && boolean(j["exact"], w / "exact");
  if (exact && !j.contains("state")) (w / "exact").fail("takes a \"state\" (every component named)");
  if (j.contains("state")) {
    const Where ws = w / "state";
    std::map<std::string, double> named;
    for (const auto& [k, v] : requireObject(j["state"], ws).items())
      named[k] = number(v, ws / k);
    if (!exact) return model.stateFromNamed(named, ws.str());
    // every component as given, none derived or projected: a run goes on bit for bit from where another
    // ended (Python's with_state), where the model would renormalise an integrated unit vector
    const auto& names = model.info().stateNames;
    Eigen::VectorXd x(static_cast<Eigen::Index>(names.size()));
    for (std::size_t i = 0; i < names.size(); ++i) {
      const auto it = named.find(names[i]);
      if (it == named.end()) ws.fail("exact: missing state component '" + names[i] + "'");
      x[static_cast<Eigen::Index>(i)] = it->second;
    }
    if (named.size() != names.size()) model.stateFromNamed(named, ws.str()); // names no component: its error
    return x;
  }
  const Where wm = w / "map";
  const std::vector<double> point = numbers(j["map"], wm);
  MapPointSpec spec{.sectionValue = poincare.value};
  // a map point lies on the section; an angle section's value is its level
  if (j.contains("root")) {
    const double r = number(j["root"], w / "root");
    if (!(r >= 1 && r == static_cast<int>(r))) (w / "root").fail("must be a whole number >= 1");
    spec.root = static_cast<int>(r);
  }
  return model.stateFromMap(point, spec, wm.str());
}

// the plot window's range of an axis: x_min, x_max, y_min, ... (none: the data's); the keys are read in the
// order of the table below, so a maximum is read after its minimum
template <int I> void readPlotRange(const json& j, const Where& w, Scene& scene) {
  auto& range = scene.plot.chart.range;
  range[I] = number(j, w);
  if (I % 2 == 1 && range[I - 1] && !(*range[I] > *range[I - 1]))
    w.fail(std::string("must exceed ") + std::array{"x_min", "y_min", "z_min"}[I / 2]);
}

// The keys of the tool sections that are no numbers of their tables: the section each belongs to, what a
// misplaced one is told, and how it is read.
struct TextKey {
  const char* key;
  const char* section;
  const char* misplaced;
  void (*read)(const json& j, const Where& w, Scene& scene);
  const char* description = ""; ///< what it is (Python's signatures; the flag's help where `flag`)
  const char* type = "text";    ///< text, number or numbers (SectionTextKeys.h)
  bool flag = false;            ///< a flag `--KEY` of the tool's generic command
  bool parameter = false;       ///< names one of the problem's parameters (SectionTextKeys.h)
};
const TextKey textKeys[] = {
    {"section", "poincare", "",
     [](const json& j, const Where& w, Scene& scene) { scene.poincare.observable = text(j, w); },
     "the observable whose crossings of poincare.value make the section"},
    {"guess", "fixedpoint", "the guess belongs to the \"fixedpoint\" section",
     [](const json& j, const Where& w, Scene& scene) {
       const auto guess = numbers(j, w);
       scene.guess.insert(scene.guess.end(), guess.begin(), guess.end());
     },
     "the starting point of the search in map coordinates (default: the scene's initial map point)",
     "numbers"},
    {"branches", "separatrix", "belongs to the \"separatrix\" section",
     // read where it is used (scenes/builtin/MapTools.cpp), from the document; checked here
     [](const json& j, const Where& w, Scene&) {
       if (j.is_string() && j.get<std::string>() == "all") return;
       for (double b : numbers(j, w))
         if (b != 1 && b != 2 && b != 3 && b != 4) w.fail("branches are 1, 2, 3, 4 (or \"all\")");
     },
     "the branches to grow: a list of 1..4 or \"all\" (default: separatrix.branch)", "numbers"},
    {"parameter", "continuation", "belongs to the \"continuation\" section",
     [](const json& j, const Where& w, Scene& scene) {
       scene.continuationParameter = text(j, w);
       if (scene.model->info().parameters.find(scene.continuationParameter) < 0)
         w.fail("not a parameter of " + scene.model->info().id);
     },
     "the model parameter to continue in", "text", false, true},
    {"to", "continuation", "belongs to the \"continuation\" section",
     [](const json& j, const Where& w, Scene& scene) { scene.continuationTo = number(j, w); },
     "the finite value of the parameter", "number"},
    {"second_parameter", "bifurcation_curve", "belongs to the \"bifurcation_curve\" section",
     // read where it is used (scenes/builtin/BifurcationCurveTool.cpp), from the document; checked here
     [](const json& j, const Where& w, Scene& scene) {
       const std::string id = text(j, w);
       if (scene.model->info().parameters.find(id) < 0)
         w.fail("not a parameter of " + scene.model->info().id);
     },
     "the second parameter of the curve (the first is continuation.parameter)", "text", true, true},
    {"level", "grid", "belongs to the \"grid\" section",
     // read where it is used (scenes/builtin/GridTools.cpp), from the document; checked here
     [](const json& j, const Where& w, Scene& scene) {
       const std::string id = text(j, w);
       if (scene.model->findObservable(id) < 0) w.fail("not an observable of " + scene.model->info().id);
     },
     "2D maps, region of allowed motion: the observable giving the energy level's height above the region"},
    {"diagram", "diagram", "",
     // read where it is used (scenes/builtin/DiagramTool.cpp), from the document; checked here
     [](const json& j, const Where& w, Scene& scene) {
       const std::string id = text(j, w);
       std::string known;
       for (const auto& d : scene.model->diagrams()) {
         if (d.id == id) return;
         known += " " + d.id;
       }
       w.fail("unknown diagram of " + scene.model->info().id +
              (known.empty() ? " (it has no bifurcation diagrams)" : " (known:" + known + ")"));
     },
     "which of the problem's diagrams (default: its first)", "text", true},
    {"branch", "diagram", "", [](const json& j, const Where& w, Scene&) { (void)text(j, w); },
     "one branch only (default: every branch)", "text", true},
    {"min", "diagram", "", [](const json& j, const Where& w, Scene&) { (void)number(j, w); },
     "the least value of the branch parameter (default: the branch's)", "number", true},
    {"max", "diagram", "", [](const json& j, const Where& w, Scene&) { (void)number(j, w); },
     "the largest value of the branch parameter (default: the branch's)", "number", true},
    {"step", "diagram", "", [](const json& j, const Where& w, Scene&) { (void)number(j, w); },
     "the step of the branch parameter (default: the branch's)", "number", true},
    {"function", "spectrum", "",
     // read where it is used (scenes/builtin/SpectrumTool.cpp), from the document; checked here
     [](const json& j, const Where& w, Scene&) { (void)text(j, w); },
     "the observable whose spectrum is taken", "text", true},
    {"x", "plot", "",
     [](const json& j, const Where& w, Scene& scene) { scene.plot.settings.axes[0] = text(j, w); },
     "the observable on the x axis", "text", true},
    {"y", "plot", "",
     [](const json& j, const Where& w, Scene& scene) { scene.plot.settings.axes[1] = text(j, w); },
     "the observable on the y axis", "text", true},
    {"z", "plot", "",
     [](const json& j, const Where& w, Scene& scene) { scene.plot.settings.axes.push_back(text(j, w)); },
     "the observable on the z axis (a 3D plot)", "text", true},
    {"condition", "plot", "",
     [](const json& j, const Where& w, Scene& scene) { scene.plot.settings.condition = text(j, w); },
     "the condition a point must meet to be plotted", "text", true},
    {"x_min", "plot", "", readPlotRange<0>,
     "the least value of the plot window's x axis (default: the data's)", "number"},
    {"x_max", "plot", "", readPlotRange<1>,
     "the largest value of the plot window's x axis (default: the data's)", "number"},
    {"y_min", "plot", "", readPlotRange<2>,
     "the least value of the plot window's y axis (default: the data's)", "number"},
    {"y_max", "plot", "", readPlotRange<3>,
     "the largest value of the plot window's y axis (default: the data's)", "number"},
    {"z_min", "plot", "", readPlotRange<4>,
     "the least value of the plot window's z axis (default: the data's)", "number"},
    {"z_max", "plot", "", readPlotRange<5>,
     "the largest value of the plot window's z axis (default: the data's)", "number"},
};

// the tool sections: numbers and choices from their tables, plus the text keys above
void readToolSections(const json& doc, const Where& root, Scene& scene) {
  for (const auto& section : toolSections()) {
    auto values = std::make_shared<ParameterValues>(*section.table);
    if (doc.contains(section.key)) {
      const Where w = root / section.key;
      const json& j = requireObject(doc[section.key], w);
      // a table's own number of the same name wins (fixedpoint.section); a text key elsewhere is told where
      // it belongs, or is unknown there
      const auto applies = [&](const TextKey& t) {
        return section.table->find(t.key) < 0 && (section.key == t.section || *t.misplaced);
      };
      std::vector<std::string> text;
      std::string known; // what an unknown key is told: the table's ids and the section's own text keys
      for (const auto& spec : section.table->specs())
        known += " " + spec.id;
      for (const auto& t : textKeys) {
        if (applies(t)) text.emplace_back(t.key);
        if (applies(t) && section.key == t.section) known += std::string(" ") + t.key;
      }
      for (const auto& item : j.items())
        if (section.table->find(item.key()) < 0 &&
            std::find(text.begin(), text.end(), item.key()) == text.end())
          (w / item.key()).fail("unknown parameter (known:" + known + ")");
      readParameters(j, w, *values, text);
      for (const auto& t : textKeys) {
        if (!j.contains(t.key) || !applies(t)) continue;
        if (section.key != t.section) (w / t.key).fail(t.misplaced);
        t.read(j[t.key], w / t.key, scene);
      }
    }
    scene.tools.emplace(section.key, std::move(values));
  }
}

// `--set`: a plain key is a model parameter, a dotted key a path into the document
void applyOverrides(json& doc, const std::vector<SceneOverride>& overrides, const std::string& source) {
  for (const auto& o : overrides) {
    const std::string flag = "--set " + o.key;
    json value = json::parse(o.value, nullptr, false);
    if (value.is_discarded()) {
      value = o.value;
      try {
        (void)value.dump(); // the document is written out (saved scenes, checkpoints): text must be UTF-8
      } catch (const json::type_error&) {
        throw InputError(flag + ": the value is not valid UTF-8 text");
      }
    }
    if (o.key.find('.') == std::string::npos) {
      if (o.key == "problem") {
        doc["problem"] = value;
        continue;
      }
      if (!doc.contains("model") && (!doc.contains("problem") || !doc["problem"].is_string()))
        continue; // reported by validation
      const ModelEntry& entry = sceneModelEntry(doc, source);
      if (entry.info->parameters.find(o.key) < 0) {
        std::string known;
        for (const auto& s : entry.info->parameters.specs())
          known += " " + s.id;
        throw InputError(flag + ": unknown parameter of " + entry.info->id + " (known:" + known + ")");
      }
      if (!value.is_number()) throw InputError(flag + ": expected a number, got '" + o.value + "'");
      doc["parameters"][o.key] = value;
      continue;
    }
    static const std::set<std::string> sections{"integrator", "initial", "parameters", "view"};
    const std::string head = o.key.substr(0, o.key.find('.'));
    if (!sections.count(head) && !findToolSection(head))
      throw InputError(flag + ": unknown scene field '" + head + "'");
    json* node = &doc;
    std::stringstream path(o.key);
    for (std::string part; std::getline(path, part, '.');) {
      if (part.empty()) throw InputError(flag + ": empty name in the path");
      if (!node->is_object()) *node = json::object();
      node = &(*node)[part];
    }
    *node = value;
    if (o.key == "integrator.method" && value.is_string()) {
      // the old method's settings do not apply to the new one: keep only the keys the new method knows
      const IntegratorEntry* entry = nullptr;
      try {
        entry = &IntegratorRegistry::global().get(value.get<std::string>());
      } catch (const InputError&) {
        continue; // reported by validation, naming the field
      }
      for (auto it = doc["integrator"].begin(); it != doc["integrator"].end();)
        if (it.key() != "method" && entry->parameters->find(it.key()) < 0 &&
            std::none_of(overrides.begin(), overrides.end(),
                         [&](const SceneOverride& x) { return x.key == "integrator." + it.key(); }))
          it = doc["integrator"].erase(it);
        else
          ++it;
    }
  }
}

} // namespace

SceneOverride parseOverride(const std::string& text) {
  const auto eq = text.find('=');
  if (eq == std::string::npos || eq == 0) throw InputError("--set " + text + ": expected ID=VALUE");
  return {text.substr(0, eq), text.substr(eq + 1)};
}

const std::set<std::string>& sceneKeys() {
  static const std::set<std::string> keys{"problem", "model", "parameters",  "integrator", "initial",
                                          "view",    "title", "description", "results"};
  return keys;
}

namespace {
// rollviz's own tools (scenes/BuiltinTools.h), then the render layer's settings section (the video encoder's,
// render/video/VideoSettings.h), register when this library loads, before any thread reads the registry or
// the sections; sceneFromJson makes sure of it again
void registerSections() {
  registerBuiltinTools();
  registerVideoSection();
}
const bool sectionsRegistered = (registerSections(), true);
} // namespace

Scene sceneFromJson(json doc, const std::string& source, const std::vector<SceneOverride>& overrides) {
  registerSections();
  (void)sectionsRegistered;
  const Where root{source, ""};
  requireObject(doc, root);
  applyOverrides(doc, overrides, source);
  for (const auto& [key, value] : doc.items()) {
    const auto& known = sceneKeys();
    if (!known.count(key) && !findToolSection(key)) {
      std::string list;
      for (const auto& k : known)
        list += " " + k;
      for (const auto& t : toolSections())
        list += " " + t.key;
      // a tool's section that only a module declares looks like a typo: say where sections come from
      (root / key).fail("unknown key (known:" + list + "); if it is a tool's section, " + notInAnyModule());
    }
  }
  Scene scene;
  scene.source = source;
  scene.modelEntry = &sceneModelEntry(doc, source);
  const std::string& problem = scene.modelEntry->info->id;

  ParameterValues params(scene.modelEntry->info->parameters);
  if (doc.contains("parameters"))
    readParameters(requireObject(doc["parameters"], root / "parameters"), root / "parameters", params);
  try {
    scene.model = scene.modelEntry->create(params);
  } catch (const InputError& e) {
    (root / "parameters").fail(e.what());
  }

  const Where wi = root / "integrator";
  const json integ = doc.contains("integrator") ? requireObject(doc["integrator"], wi) : json::object();
  const std::string method = integ.contains("method") ? text(integ["method"], wi / "method") : "rk4";
  try {
    scene.integratorEntry = &IntegratorRegistry::global().get(method);
  } catch (const InputError& e) {
    (wi / "method").fail(e.what());
  }
  auto integratorParameters = std::make_shared<ParameterValues>(*scene.integratorEntry->parameters);
  readParameters(integ, wi, *integratorParameters, {"method"});
  scene.integratorParameters = integratorParameters;
  try {
    scene.integratorEntry->create(*integratorParameters); // validates combinations of values
  } catch (const InputError& e) {
    wi.fail(e.what());
  }

  readToolSections(doc, root, scene);
  scene.poincare = poincareSettings(scene.tool("poincare"), scene.poincare.observable);
  applyPlotTable(scene.tool("plot"), scene.plot);
  if (!scene.poincare.observable.empty() && !scene.model->isMap() &&
      scene.model->findObservable(scene.poincare.observable) < 0)
    (root / "poincare" / "section")
        .fail("unknown observable '" + scene.poincare.observable + "' of " + problem);
  if (doc.contains("initial")) {
    scene.initialState = readInitial(doc["initial"], root / "initial", *scene.model, scene.poincare);
  } else if (const json initial = modelFileInitial(*scene.modelEntry); !initial.is_null()) {
    // a model file's own start (what opening the file in the GUI shows)
    scene.initialState =
        readInitial(initial, Where{scene.modelEntry->origin, "initial"}, *scene.model, scene.poincare);
  } else {
    root.fail("missing \"initial\" (a map point or a state)");
  }
  if (doc.contains("view")) scene.view = readView(doc["view"], root / "view");
  if (doc.contains("results")) { // the GUI's Results kept with the scene: lines of text
    const json& r = doc["results"];
    if (!r.is_array()) (root / "results").fail("expected an array of lines of text");
    for (std::size_t i = 0; i < r.size(); ++i)
      if (!r[i].is_string()) (root / "results" / std::to_string(i)).fail("expected a line of text");
  }
  scene.document = std::move(doc);
  return scene;
}

Scene loadScene(const std::string& path, const std::vector<SceneOverride>& overrides) {
  std::istringstream in(readInputFile(path, "scene file"));
  nlohmann::json document = parseSceneJson(in, path);
  if (isSession(document)) { // a GUI session: its scene (relative files resolve from the scene's own file)
    const Session session = sessionFromJson(document, path);
    return sceneFromJson(session.scene, session.scenePath.empty() ? path : session.scenePath, overrides);
  }
  return sceneFromJson(std::move(document), path, overrides);
}

std::string scenesDirectory() {
  if (const char* dir = std::getenv("ROLLVIZ_SCENES_DIR")) return dir;
  return ROLLVIZ_SCENES_DIR;
}

std::string defaultScenePath(const std::string& problemId) {
  return (std::filesystem::path(scenesDirectory()) / (problemId + ".json")).string();
}

std::vector<SectionTextKey> sectionTextKeys(const std::string& section, bool flagsOnly) {
  std::vector<SectionTextKey> keys;
  for (const auto& t : textKeys)
    if (section == t.section && (t.flag || !flagsOnly))
      keys.push_back({t.key, t.description, t.type, t.parameter});
  return keys;
}

} // namespace rv
