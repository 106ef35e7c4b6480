// PyModule.cpp -- the Python module `rollviz` (pybind11): scenes, integration, pictures and videos, the lists
// of problems and tools. The tools themselves are bound in PyTools.cpp; the package's __init__.py turns each
// registered tool into a Scene method. Errors: InputError -> ValueError with the CLI's message,
// ComputationError -> rollviz.ComputationError; long calls run as jobs (PyJob.h): the GIL is released,
// Ctrl-C raises KeyboardInterrupt, `progress=callable` reports.
#include "app/python/PyCommon.h"
#include "app/python/PyJob.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/TimeSampler.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/io/FileNames.h"
#include "render/Snapshot.h"
#include "render/charts/ChartStyle.h"
#include "render/context/HeadlessContext.h"
#include "render/export/Figure.h"
#include "render/export/VtkXmlFiles.h"
#include "render/video/VideoExport.h"
#include "render/view/VisualScene.h"
#include "rollviz/Version.h"
#include "scenes/ModelFile.h"
#include "scenes/ModuleLoader.h"
#include "scenes/SceneCharts.h"
#include "scenes/ScenePage.h"
#include "scenes/Session.h"

#include <cmath>
#include <filesystem>
#include <fstream>
#include <vtkRenderWindow.h>

namespace rv::py {

nlohmann::json toJson(const pyb::handle& v, const std::string& what) {
  if (v.is_none()) return nullptr;
  if (pyb::isinstance<pyb::bool_>(v)) return v.cast<bool>();
  if (pyb::isinstance<pyb::int_>(v)) return v.cast<long long>();
  if (pyb::isinstance<pyb::float_>(v)) return v.cast<double>();
  if (pyb::isinstance<pyb::str>(v)) return v.cast<std::string>();
  if (pyb::isinstance<pyb::dict>(v)) {
    nlohmann::json j = nlohmann::json::object();
    for (const auto& [k, x] : v.cast<pyb::dict>())
      j[pyb::str(k).cast<std::string>()] = toJson(x, what);
    return j;
  }
  if (pyb::isinstance<pyb::sequence>(v) || pyb::hasattr(v, "tolist")) {
    const pyb::object list =
        pyb::hasattr(v, "tolist") ? v.attr("tolist")() : pyb::reinterpret_borrow<pyb::object>(v);
    if (!pyb::isinstance<pyb::sequence>(list)) return toJson(list, what); // a NumPy scalar
    nlohmann::json j = nlohmann::json::array();
    for (const auto& x : list.cast<pyb::sequence>())
      j.push_back(toJson(x, what));
    return j;
  }
  if (PyNumber_Check(v.ptr())) return pyb::float_(pyb::reinterpret_borrow<pyb::object>(v)).cast<double>();
  throw InputError(what + ": cannot use a value of type " +
                   pyb::str(v.get_type().attr("__name__")).cast<std::string>());
}

SceneOverride toOverride(const std::string& key, const pyb::handle& value) {
  return {key, toJson(value, key).dump()};
}

Scene withOverrides(const Scene& scene, const std::vector<SceneOverride>& overrides) {
  if (overrides.empty()) return scene;
  return sceneFromJson(scene.document, scene.source, overrides);
}

pyb::list describeTable(const ParameterTable& table) {
  pyb::list out;
  for (const auto& s : table.specs()) {
    pyb::dict d;
    d["id"] = s.id;
    d["description"] = s.description;
    if (s.choices.empty()) {
      d["default"] = s.defaultValue;
      d["min"] = s.min, d["max"] = s.max;
      d["integer"] = s.integer;
    } else {
      d["default"] = s.choices[static_cast<std::size_t>(s.defaultValue)];
      d["choices"] = s.choices;
    }
    if (!s.unit.empty()) d["unit"] = s.unit;
    out.append(d);
  }
  return out;
}

namespace {

std::pair<int, int> pictureSize(const pyb::handle& size, const char* what) {
  const auto wh = size.cast<std::pair<int, int>>();
  if (wh.first < 16 || wh.second < 16 || wh.first > 16384 || wh.second > 16384)
    throw InputError(std::string(what) + ": expected (width, height), each in [16, 16384]");
  return wh;
}

std::vector<SceneOverride> overridesOf(const pyb::kwargs& kw) {
  std::vector<SceneOverride> o;
  for (const auto& [k, v] : kw)
    o.push_back(toOverride(pyb::str(k).cast<std::string>(), v));
  return o;
}

pyb::array_t<unsigned char> toPicture(Image&& image) {
  const int w = image.width, h = image.height;
  return toArray(std::move(image.rgb), {h, w, 3});
}

// integrate_at(times, columns, resume, t0): the observables at given times, forward from t0 when they are >=
// t0 and backward when they are <= t0, from the dense output of one integration; with `resume` (what a former
// call returned) the integration goes on from where that one's integrator stopped, bit for bit as one call.
// Returns (X, the integrator's snapshot at the end).
pyb::tuple integrateAt(const Scene& shared, const std::vector<double>& times,
                       const std::vector<std::string>& ids, const pyb::object& resume,
                       const pyb::object& progress, double t0) {
  // a copy: another Python thread may change the scene object while this runs without the GIL
  const Scene scene = shared; // NOLINT(performance-unnecessary-copy-initialization)
  if (!std::isfinite(t0)) throw InputError("t0 must be a finite number");
  const bool backward = !times.empty() && times.back() < t0;
  const std::vector<int> cols = observableColumns(*scene.model, ids, "columns");
  const auto& obs = scene.model->observables();
  Snapshot saved;
  if (!resume.is_none()) saved.values = resume.cast<std::vector<double>>();
  std::vector<double> x;
  x.reserve(times.size() * cols.size());
  runJob(progress, [&](const ToolControl& control) {
    auto integrator = scene.runSpec().makeIntegrator(*scene.model);
    integrator->start(*scene.model, t0, scene.initialState, backward ? -1 : +1);
    if (!saved.values.empty()) integrator->restore(saved);
    const double span = times.empty() ? 0 : std::abs(times.back() - t0);
    sampleAt(*integrator, times, [&](double t, const Eigen::VectorXd& state) {
      for (const int c : cols)
        x.push_back(obs[static_cast<std::size_t>(c)].value(t, state.data()));
      control.progress(span > 0 ? std::abs(t - t0) / span : 1.0);
      return !control.stopRequested();
    });
    saved = Snapshot{};
    integrator->save(saved);
  });
  const auto k = static_cast<pyb::ssize_t>(cols.size());
  const auto rows = k ? static_cast<pyb::ssize_t>(x.size()) / k : 0;
  return pyb::make_tuple(toArray(std::move(x), {rows, k}), toArray(std::move(saved.values)));
}

// the 3D view at `time`, the traces covering [0, time] (as `rollviz render` shows it)
std::unique_ptr<VisualScene> playedTo(const Scene& scene, double time) {
  if (!(std::isfinite(time) && time >= 0)) throw InputError("time: must be a finite number >= 0");
  auto integrator = scene.startIntegrator();
  auto visual = std::make_unique<VisualScene>(*scene.model, scene.view, scene.initialState);
  Eigen::VectorXd x;
  playTo(*visual, *integrator, time, x);
  return visual;
}

pyb::array_t<unsigned char> render(const Scene& shared, const pyb::handle& size, double time, int scale,
                                   bool transparent) {
  // a copy: another Python thread may set() the scene while this runs without the GIL
  const Scene scene = shared; // NOLINT(performance-unnecessary-copy-initialization)
  const auto [w, h] = pictureSize(size, "size");
  if (scale != 1 || transparent)
    throw InputError(
        "scale, transparent: only for files (Scene.snapshot); render() returns the window's RGB");
  Image image;
  {
    pyb::gil_scoped_release release;
    const auto shown = playedTo(scene, time);
    VisualScene& visual = *shown;
    auto ctx = createHeadlessContext(w, h);
    visual.addTo(ctx->window());
    image = capture(ctx->window());
    ctx->window()->RemoveRenderer(visual.renderer());
  }
  return toPicture(std::move(image));
}

void snapshot(const Scene& shared, const std::string& path, const pyb::handle& size, double time, int scale,
              bool transparent) {
  // a copy: another Python thread may set() the scene while this runs without the GIL
  const Scene scene = shared; // NOLINT(performance-unnecessary-copy-initialization)
  const auto [w, h] = pictureSize(size, "size");
  if (!hasExtension(path, ".png"))
    throw InputError("path " + path + ": a snapshot is a PNG (.png); export_view writes .vtm");
  checkWritable(path, "path");
  pyb::gil_scoped_release release;
  const auto shown = playedTo(scene, time);
  VisualScene& visual = *shown;
  auto ctx = createHeadlessContext(w, h);
  visual.addTo(ctx->window());
  writePng(ctx->window(), path, "path", SnapshotOptions{.scale = scale, .transparent = transparent});
  ctx->window()->RemoveRenderer(visual.renderer());
}

void exportView(const Scene& shared, const std::string& path, double time) {
  // a copy: another Python thread may set() the scene while this runs without the GIL
  const Scene scene = shared; // NOLINT(performance-unnecessary-copy-initialization)
  if (!hasExtension(path, ".vtm")) throw InputError("path " + path + ": the view is exported as a .vtm file");
  checkWritable(path, "path");
  pyb::gil_scoped_release release;
  const auto shown = playedTo(scene, time);
  VisualScene& visual = *shown;
  writeSceneVtm(visual, path, "path");
}

long video(const Scene& shared, const std::string& path, const pyb::object& duration, const pyb::object& fps,
           const pyb::object& size, double speed, const std::string& encoder, const pyb::object& progress) {
  // a copy: another Python thread may set() the scene while this runs without the GIL
  const Scene scene = shared; // NOLINT(performance-unnecessary-copy-initialization)
  // the scene's video section, then the arguments given
  VideoOverrides given{.sizeName = "size", .durationName = "duration", .fpsName = "fps"};
  if (!size.is_none()) given.size = pictureSize(size, "size");
  if (!duration.is_none()) given.duration = duration.cast<double>();
  if (!fps.is_none()) given.fps = fps.cast<int>();
  VideoSpec spec = videoSpec(scene.tool("video"), speed > 0 ? speed : scene.view.speed, given);
  spec.path = path;
  spec.encoder.codec = encoder;
  if (!hasExtension(path, ".mp4")) throw InputError("path " + path + ": a video is an MP4 file (.mp4)");
  checkWritable(path, "path");
  long frames = 0;
  runJob(progress, [&](const ToolControl& control) {
    auto integrator = scene.startIntegrator();
    VisualScene visual(*scene.model, scene.view, scene.initialState);
    auto ctx = createHeadlessContext(spec.width, spec.height);
    visual.addTo(ctx->window());
    frames = exportVideo(visual, ctx->window(), *integrator, spec, [&](long k, long n) {
      control.progress(static_cast<double>(k) / n);
      return !control.stopRequested();
    });
    ctx->window()->RemoveRenderer(visual.renderer());
  });
  return frames;
}

/// The page of `scene` (with `session`'s map); the overrides as `rollviz page` takes them.
long page(const Scene& scene, const Session* session, const std::string& path, const pyb::object& duration,
          const pyb::object& fps, const pyb::object& speed, const pyb::object& progress) {
  PageOverrides given{.durationName = "duration", .fpsName = "fps", .speedName = "speed"};
  if (!duration.is_none()) given.duration = duration.cast<double>();
  if (!fps.is_none()) given.fps = fps.cast<int>();
  if (!speed.is_none()) given.speed = speed.cast<double>();
  long frames = 0;
  runJob(progress, [&](const ToolControl& control) {
    frames = writeScenePage(scene, session, path, given, [&](long k, long n) {
      control.progress(static_cast<double>(k) / n);
      return !control.stopRequested();
    });
  });
  return frames;
}

pyb::array_t<unsigned char> chart(const Scene& shared, const std::string& view, const pyb::handle& size,
                                  long points, const std::string& diagram, const pyb::object& path,
                                  const std::string& style, int scale, const pyb::object& progress) {
  // a copy: another Python thread may set() the scene while this runs without the GIL
  const Scene scene = shared; // NOLINT(performance-unnecessary-copy-initialization)
  const ChartStyle dress = chartStyle(style, scale, "style");
  const auto picture = figureSize(
      dress, size.is_none() ? std::pair<int, int>{800, 800} : pictureSize(size, "size"), !size.is_none());
  const int w = picture.first, h = picture.second; // lambdas capture no structured bindings (clang 14)
  const auto& views = chartViews();
  if (std::find(views.begin(), views.end(), view) == views.end()) {
    std::string known;
    for (const auto& v : views)
      known += " " + v;
    throw InputError("view " + view + ": not a chart (known:" + known + ")");
  }
  const std::string file = path.is_none() ? std::string() : path.cast<std::string>();
  if (!file.empty()) {
    figureFormat(file, "path");
    checkWritable(file, "path");
  }
  Image image;
  runJob(progress, [&](const ToolControl& control) {
    const auto c = sceneChart(scene, view, control, points, diagram);
    auto ctx = createHeadlessContext(w, h);
    c->attach(ctx->window());
    styleCharts(ctx->window(), dress);
    image = capture(ctx->window());
    if (!file.empty()) writeFigure(ctx->window(), file, "path");
  });
  return toPicture(std::move(image));
}

pyb::dict describeEntry(const ModelEntry& entry) {
  const ModelInfo& info = *entry.info;
  const auto model = entry.create(ParameterValues(info.parameters));
  pyb::dict d;
  d["id"] = info.id;
  d["title"] = info.title;
  d["reference"] = info.reference;
  d["kind"] = model->isMap() ? "map" : "flow";
  d["parameters"] = describeTable(info.parameters);
  d["state"] = info.stateNames;
  d["integrals"] = info.integralNames;
  d["map_coordinates"] = info.mapCoordinates;
  d["invariant_measure"] = model->hasInvariantMeasure();
  pyb::list obs;
  for (const auto& o : model->observables()) {
    pyb::dict x;
    x["id"] = o.id, x["description"] = o.description;
    obs.append(x);
  }
  d["observables"] = obs;
  return d;
}

pyb::dict describeProblem(const std::string& idOrPath) {
  return describeEntry(modelEntryByName(idOrPath));
}

/// A model written as equations (scenes/ModelFile.h), for Python: the entry and how a scene names it.
struct PyModel {
  const ModelEntry* entry;
  std::string path;           ///< the model file, or ""
  nlohmann::json inlineModel; ///< the object, for a model made from a dict
  /// A scene document on this model: the file named, or the object inline (its start, when the keywords give
  /// none, is the model file's "initial").
  nlohmann::json sceneDocument() const {
    nlohmann::json doc;
    if (path.empty())
      doc["model"] = inlineModel;
    else
      doc["problem"] = path;
    return doc;
  }
};

nlohmann::json jsonOf(const pyb::handle& object) {
  const auto dumps = pyb::module_::import("json").attr("dumps");
  return nlohmann::json::parse(dumps(object).cast<std::string>());
}

} // namespace

} // namespace rv::py

PYBIND11_MODULE(_rollviz, m) {
  using namespace rv;
  using namespace rv::py;
  namespace pyb = pybind11;
  m.doc() = "rollviz: bodies rolling without slipping, and the tools of nonlinear dynamics (C++ core)";
  m.attr("__version__") = ROLLVIZ_VERSION_STRING;
  // the modules of ROLLVIZ_MODULE_PATH and ~/.local/lib/rollviz/modules, before the package builds its
  // methods
  loadModules({}, [](const std::string& w) {
    pyb::print("rollviz: warning:", w, pyb::arg("file") = pyb::module_::import("sys").attr("stderr"));
  });
  m.def(
      "modules",
      [] {
        pyb::list out;
        for (const auto& mod : loadedModules()) {
          pyb::dict d;
          d["path"] = mod.path, d["problems"] = mod.models, d["tools"] = mod.tools;
          d["integrators"] = mod.integrators;
          out.append(d);
        }
        return out;
      },
      "The modules loaded (ROLLVIZ_MODULE_PATH, ~/.local/lib/rollviz/modules): path, problems, tools, "
      "integrators each added.");

  static pyb::exception<ComputationError> computationError(m, "ComputationError", PyExc_RuntimeError);
  // by value: pybind11 takes a plain function pointer of this signature
  pyb::register_exception_translator([](std::exception_ptr p) { // NOLINT(performance-unnecessary-value-param)
    try {
      if (p) std::rethrow_exception(p);
    } catch (const InputError& e) {
      PyErr_SetString(PyExc_ValueError, e.what());
    } catch (const ComputationError& e) {
      computationError(e.what());
    }
  });

  m.def(
      "problems",
      [] {
        pyb::list out;
        for (const auto& e : ModelRegistry::global().entries()) {
          pyb::dict d;
          d["id"] = e.info->id, d["title"] = e.info->title;
          out.append(d);
        }
        return out;
      },
      "The problems (models): a list of {id, title}.");
  m.def(
      "describe", &describeProblem, pyb::arg("problem"),
      "A problem's parameters, state, first integrals, map coordinates and observables (rollviz describe).");
  m.def(
      "integrators",
      [] {
        pyb::list out;
        for (const auto& e : IntegratorRegistry::global().entries()) {
          pyb::dict d;
          d["id"] = e.id, d["title"] = e.title;
          d["parameters"] = describeTable(*e.parameters);
          out.append(d);
        }
        return out;
      },
      "The integrators: a list of {id, title, parameters}.");
  m.def(
      "_session_page",
      [](const std::string& file, const std::string& path, const pyb::object& duration,
         const pyb::object& fps, const pyb::object& speed, const pyb::object& progress) {
        const Session session = readSession(file);
        const Scene scene = loadScene(file);
        return page(scene, &session, path, duration, fps, speed, progress);
      },
      pyb::arg("file"), pyb::arg("path"), pyb::arg("duration") = pyb::none(), pyb::arg("fps") = pyb::none(),
      pyb::arg("speed") = pyb::none(), pyb::kw_only(), pyb::arg("progress") = pyb::none(),
      "The page of a saved session (rollviz page SESSION): its scene's motion beside its map.");
  m.def("scenes_directory", &scenesDirectory, "The folder of the shipped scene files.");

  pyb::class_<PyModel>(
      m, "Model",
      "A system written as equations (docs/models.md): Model.load(path) or Model(dict), then "
      "Scene(model, **set). Every tool works on it.")
      .def(pyb::init([](const pyb::dict& d) {
             const nlohmann::json j = jsonOf(d);
             return PyModel{&modelEntryFromJson(j, "<Model>"), "", j};
           }),
           pyb::arg("model"), "A model from a dict with the content of a model file.")
      .def_static(
          "load",
          [](const std::string& path) {
            const std::string absolute = std::filesystem::absolute(path).string();
            return PyModel{&modelFileEntry(absolute), absolute, {}};
          },
          pyb::arg("path"), "Loads a model file.")
      .def_property_readonly("id", [](const PyModel& m) { return m.entry->info->id; })
      .def_property_readonly("path", [](const PyModel& m) { return m.path; })
      .def(
          "describe", [](const PyModel& m) { return describeEntry(*m.entry); },
          "Its parameters, state, integrals, map coordinates and observables (as rollviz.describe).")
      .def("__repr__", [](const PyModel& m) {
        return "<rollviz.Model " + m.entry->info->id + (m.path.empty() ? "" : " from " + m.path) + ">";
      });

  pyb::class_<Scene> scene(m, "Scene",
                           "A validated scene: a problem, its parameters, method, initial state and "
                           "tool settings (rollviz's scene file).");
  scene
      .def(pyb::init([](const std::string& problem, const pyb::kwargs& kw) {
             ModelRegistry::global().get(problem); // ValueError listing the problems
             return loadScene(defaultScenePath(problem), overridesOf(kw));
           }),
           pyb::arg("problem"),
           "The shipped scene of a problem (scenes/<problem>.json) with parameters or dotted scene keys set.")
      .def(pyb::init([](const PyModel& model, const pyb::kwargs& kw) {
             return sceneFromJson(model.sceneDocument(),
                                  model.path.empty() ? "<Model>" : model.path + ".scene", overridesOf(kw));
           }),
           pyb::arg("model"),
           "A scene on a model written as equations; give its initial state as **{'initial.state': {...}} "
           "(or set 'initial.map').")
      .def_static(
          "load",
          [](const std::string& path, const pyb::kwargs& kw) { return loadScene(path, overridesOf(kw)); },
          pyb::arg("path"), "Loads a scene file; keyword arguments as for set().")
      .def_static(
          "from_json",
          [](const std::string& text, const std::string& source) {
            return sceneFromJson(nlohmann::json::parse(text), source);
          },
          pyb::arg("text"), pyb::arg("source") = "<json>", "A scene from its JSON text.")
      .def(
          "set",
          [](Scene& s, const pyb::kwargs& kw) -> Scene& {
            s = withOverrides(s, overridesOf(kw));
            return s;
          },
          pyb::return_value_policy::reference,
          "Sets model parameters (energy=0.4) and dotted scene keys (**{'integrator.method': 'everhart'}), "
          "as "
          "--set does; ValueError naming a bad key or value (the scene is left as it was). Returns the "
          "scene.")
      .def(
          "copy", [](const Scene& s) { return s; }, "An independent copy.")
      .def_property_readonly("problem", [](const Scene& s) { return s.model->info().id; })
      .def_property_readonly("source", [](const Scene& s) { return s.source; })
      .def_property_readonly(
          "parameters",
          [](const Scene& s) {
            pyb::dict d;
            const auto& table = s.model->info().parameters;
            for (std::size_t i = 0; i < table.size(); ++i)
              d[table.specs()[i].id.c_str()] = s.runSpec().modelParameters[table.specs()[i].id];
            return d;
          },
          "The model parameters' values.")
      .def_property_readonly("initial_state",
                             [](const Scene& s) {
                               return toArray(std::vector<double>(
                                   s.initialState.data(), s.initialState.data() + s.initialState.size()));
                             })
      .def_property_readonly(
          "state_names", [](const Scene& s) { return s.model->info().stateNames; },
          "The names of the state's components, in the order of initial_state.")
      .def_property_readonly("observables",
                             [](const Scene& s) {
                               std::vector<std::string> ids;
                               for (const auto& o : s.model->observables())
                                 ids.push_back(o.id);
                               return ids;
                             })
      .def_property_readonly("map_coordinates", [](const Scene& s) { return s.model->info().mapCoordinates; })
      .def(
          "to_json", [](const Scene& s) { return s.document.dump(2); },
          "The scene file's text (what save() writes).")
      .def(
          "save",
          [](const Scene& s, const std::string& path) {
            AtomicFile file(path, "path");
            {
              std::ofstream out(file.tempPath());
              out << sceneMovedTo(s.document, s.source, path).dump(2) << "\n";
              if (!out) throw ComputationError("cannot write " + path);
            }
            file.commit();
          },
          pyb::arg("path"), "Writes the scene file (through a temporary name).")
      .def("__repr__",
           [](const Scene& s) { return "<rollviz.Scene " + s.model->info().id + " from " + s.source + ">"; })
      .def("_integrate_at", &integrateAt, pyb::arg("times"), pyb::arg("columns"), pyb::kw_only(),
           pyb::arg("resume") = pyb::none(), pyb::arg("progress") = pyb::none(), pyb::arg("t0") = 0.0,
           "The columns at the given times (one direction from t = 0): what integrate(t_eval=...) calls.")
      .def(
          "render", &render, pyb::arg("size") = std::pair<int, int>{640, 480}, pyb::arg("time") = 10.0,
          pyb::arg("scale") = 1, pyb::arg("transparent") = false,
          "The 3D view at `time` (the trace covers [0, time]) as an H x W x 3 uint8 array, rendered headless "
          "(EGL) as rollviz render draws it.")
      .def("snapshot", &snapshot, pyb::arg("path"), pyb::arg("size") = std::pair<int, int>{1280, 720},
           pyb::arg("time") = 10.0, pyb::arg("scale") = 1, pyb::arg("transparent") = false,
           "Writes the 3D view at `time` as a PNG (rollviz render -o PATH).")
      .def("export_view", &exportView, pyb::arg("path"), pyb::arg("time") = 10.0,
           "Writes the 3D view at `time` as a ParaView multiblock (.vtm: bodies, plane, traces; rollviz "
           "render "
           "-o view.vtm).")
      .def("video", &video, pyb::arg("path"), pyb::arg("duration") = pyb::none(),
           pyb::arg("fps") = pyb::none(), pyb::arg("size") = pyb::none(), pyb::arg("speed") = 0.0,
           pyb::arg("encoder") = "libx264", pyb::kw_only(), pyb::arg("progress") = pyb::none(),
           "Records the 3D view into an MP4 (rollviz video); duration, fps and size default to the scene's "
           "video "
           "section (with its crf and preset), speed 0 to its view.speed. Returns frames.")
      .def(
          "page",
          [](const Scene& shared, const std::string& path, const pyb::object& duration,
             const pyb::object& fps, const pyb::object& speed, const pyb::object& progress) {
            // a copy: another Python thread may set() the scene while this runs without the GIL
            const Scene scene = shared; // NOLINT(performance-unnecessary-copy-initialization)
            return page(scene, nullptr, path, duration, fps, speed, progress);
          },
          pyb::arg("path"), pyb::arg("duration") = pyb::none(), pyb::arg("fps") = pyb::none(),
          pyb::arg("speed") = pyb::none(), pyb::kw_only(), pyb::arg("progress") = pyb::none(),
          "Writes the motion as one self-contained web page (rollviz page): duration and fps default to the "
          "scene's video section, speed to its view.speed. Returns the frames (0: stopped, nothing written).")
      .def("chart", &chart, pyb::arg("view") = "poincare", pyb::arg("size") = pyb::none(),
           pyb::arg("points") = 0, pyb::arg("diagram") = "", pyb::kw_only(), pyb::arg("path") = pyb::none(),
           pyb::arg("style") = "screen", pyb::arg("scale") = 1, pyb::arg("progress") = pyb::none(),
           "A chart of the scene (rollviz chart --view VIEW) as an H x W x 3 uint8 array; with path, also "
           "written as a figure in the format its extension names (.png, or .svg or .pdf: vectors, text as "
           "text). size: (width, height), default (800, 800); style 'paper': white, black axes and text, the "
           "type of a 3.5-inch journal column at 300 dpi (1050 x 788 unless size is given); scale N: N x the "
           "pixels with text and pens N x as large.");
  bindTools(m, scene);
}
