// PyTools.cpp -- every registered tool (dynamics/tools/ToolRegistry.h) as a call on a scene:
// Scene._run(tool, progress=None, **settings). A plain keyword is a setting of the tool's scene section
// (megno(time=...) is megno.time), else of the section of the tool it hangs under in the manual's tree
// (continuation(guess=...) is fixedpoint.guess); a dotted keyword names any scene key. The settings apply to
// this call only and are validated by the scene loader, so its messages (ValueError) are the CLI's. The
// package's __init__.py makes a Scene method of each tool from _tools(). Results are dicts of NumPy arrays
// and numbers, the same numbers the CLI writes.
#include "app/python/PyCommon.h"
#include "app/python/PyJob.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/tools/PoincareMap.h"
#include "dynamics/tools/ToolSettings.h"
#include "scenes/SceneTools.h"
#include "scenes/SectionTextKeys.h"
#include "scenes/Sweep.h"
#include "scenes/ToolRunner.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fmt/core.h>
#include <map>
#include <mutex>
#include <optional>
#include <thread>
#include <unistd.h>

namespace rv::py {

namespace {

// rows of equal length as an n x k array
pyb::array_t<double> table(std::vector<double>&& flat, std::size_t columns) {
  const auto k = static_cast<pyb::ssize_t>(columns);
  const auto n = k ? static_cast<pyb::ssize_t>(flat.size()) / k : 0;
  return toArray(std::move(flat), {n, k});
}

// the scene sections a plain keyword of the tool may belong to: its own, its ancestors' in the tree, then the
// others it reads
std::vector<std::string> sectionsOf(const ToolEntry& tool) {
  // Lyapunov exponents and MEGNO follow the trajectory, not its crossings of the section: the Poincare map's
  // settings (points, section, direction, its crossing accuracy) would be taken and do nothing
  const bool followsTrajectory = tool.id == "lyapunov" || tool.id == "megno";
  std::vector<std::string> out;
  for (const ToolEntry* t = &tool; t;
       t = t->parent.empty() ? nullptr : &ToolRegistry::global().get(t->parent))
    if (!t->section.empty() && std::find(out.begin(), out.end(), t->section) == out.end() &&
        !(followsTrajectory && t->section == "poincare"))
      out.push_back(t->section);
  for (const auto& s : tool.alsoSections)
    if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
  return out;
}

// a plain keyword's scene key: the first of the tool's sections that takes it
SceneOverride placeKeyword(const Scene& scene, const ToolEntry& tool, const std::string& key,
                           const pyb::handle& value) {
  if (key.find('.') != std::string::npos) return toOverride(key, value);
  const auto sections = sectionsOf(tool);
  if (sections.empty())
    throw InputError(tool.id + "(" + key + "=...): " + tool.id +
                     " has no settings of its own; give a dotted scene key (**{\"section.key\": value})");
  std::optional<std::string> firstError, valueError;
  for (const auto& s : sections) {
    SceneOverride o = toOverride(s + "." + key, value);
    try {
      (void)withOverrides(scene, {o});
      return o;
    } catch (const InputError& e) {
      const std::string m = e.what();
      if (!firstError) firstError = m;
      // a known key with a bad value says more than "unknown" or "belongs to another section"
      if (!valueError && m.find("unknown parameter") == std::string::npos &&
          m.find("belongs to") == std::string::npos)
        valueError = m;
    }
  }
  throw InputError(valueError ? *valueError : *firstError);
}

bool isNumbers(const nlohmann::json& j) {
  return j.is_array() && !j.empty() &&
         std::all_of(j.begin(), j.end(), [](const auto& v) { return v.is_number(); });
}

// A runner's Python result (ToolResult::python) as Python values: a list of numbers is an array, a list of
// equally long lists of numbers a 2D array, a field named in `complex` ([re, im] pairs, or rows of them) a
// complex array, an object keyed by integers ("1", "2": JSON has no other keys) a dict of ints.
pyb::object toPython(const nlohmann::json& j, const std::vector<std::string>& complex,
                     bool isComplex = false) {
  if (j.is_object()) {
    const bool numbered = !j.empty() && std::all_of(j.items().begin(), j.items().end(), [](const auto& item) {
      const std::string& k = item.key();
      return !k.empty() && k.size() < 10 &&
             std::all_of(k.begin(), k.end(), [](char ch) { return ch >= '0' && ch <= '9'; });
    });
    pyb::dict d;
    for (const auto& [k, v] : j.items()) {
      pyb::object value = toPython(v, complex, std::find(complex.begin(), complex.end(), k) != complex.end());
      if (numbered)
        d[pyb::int_(std::stoi(k))] = value;
      else
        d[k.c_str()] = value;
    }
    return d;
  }
  if (j.is_array()) {
    const auto pair = [](const nlohmann::json& z) { return isNumbers(z) && z.size() == 2; };
    if (isComplex && (j.empty() || pair(j.front()))) { // [[re, im], ...]
      std::vector<std::complex<double>> z;
      for (const auto& p : j)
        z.emplace_back(p[0].get<double>(), p[1].get<double>());
      return toArray(std::move(z));
    }
    if (isComplex && j.front().is_array()) { // rows of [re, im] pairs, as long each
      std::vector<std::complex<double>> z;
      const std::size_t m = j.front().size();
      for (const auto& row : j) {
        if (row.size() != m) throw ComputationError("rows of multipliers of unequal length");
        for (const auto& p : row)
          z.emplace_back(p[0].get<double>(), p[1].get<double>());
      }
      return toArray(std::move(z), {static_cast<pyb::ssize_t>(j.size()), static_cast<pyb::ssize_t>(m)});
    }
    if (isNumbers(j)) return toArray(j.get<std::vector<double>>());
    const std::size_t width = j.empty() || !j.front().is_array() ? 0 : j.front().size();
    if (width > 0 && std::all_of(j.begin(), j.end(),
                                 [&](const auto& row) { return isNumbers(row) && row.size() == width; })) {
      std::vector<double> flat;
      for (const auto& row : j)
        for (const auto& v : row)
          flat.push_back(v.get<double>());
      return table(std::move(flat), width);
    }
    pyb::list list;
    for (const auto& v : j)
      list.append(toPython(v, complex));
    return list;
  }
  if (j.is_string()) return pyb::str(j.get<std::string>());
  if (j.is_boolean()) return pyb::bool_(j.get<bool>());
  if (j.is_number_integer()) return pyb::int_(j.get<long long>());
  if (j.is_number()) return pyb::float_(j.get<double>());
  return pyb::none();
}

// a tool that runs through scenes/ToolRunner.h: its fields, and its table's columns as arrays (or the shape
// the runner gives Python, ToolResult::python)
pyb::object registeredTool(const ToolEntry& tool, const ToolRunner& runner, const Scene& scene,
                           const pyb::object& progress) {
  ToolResult r;
  runJob(progress, [&](const ToolControl& control) { r = rv::runTool(tool, scene, control); });
  if (!r.python.is_null()) { // its shape, and beside it each column of the table the shape does not name
    pyb::dict d = toPython(r.python, runner.complexFields);
    for (std::size_t k = 0; k < r.table.names.size(); ++k)
      if (!d.contains(r.table.names[k].c_str()))
        d[r.table.names[k].c_str()] = toArray(std::vector<double>(r.table.values[k]));
    for (const auto& t : r.text)
      if (!d.contains(t.name.c_str())) d[t.name.c_str()] = t.values;
    if (r.stopped) d["stopped"] = true;
    return d;
  }
  if (!r.failure.empty()) throw ComputationError(r.failure);
  if (runner.tableIsResult) { // the table is the result: the package makes it a rollviz.Table
    std::vector<double> flat;
    for (long k = 0; k < r.table.rows(); ++k) {
      const auto row = r.table.row(k);
      flat.insert(flat.end(), row.begin(), row.end());
    }
    pyb::dict t;
    t["columns"] = r.table.names;
    t["rows"] = table(std::move(flat), r.table.names.size());
    pyb::dict d;
    d["_table"] = t;
    return d;
  }
  pyb::dict d = toPython(r.fields, runner.complexFields); // lists of numbers as arrays (exponents)
  d["stopped"] = r.stopped;
  if (r.grid.dimensions > 0) { // a grid: its axes (x, y, z) and each value column shaped (nz,) ny, nx
    const ToolGrid& g = r.grid;
    const char* axes[] = {"x", "y", "z"};
    for (int a = 0; a < g.dimensions; ++a) {
      std::vector<double> axis(static_cast<std::size_t>(g.size[a]));
      for (int i = 0; i < g.size[a]; ++i)
        axis[static_cast<std::size_t>(i)] = g.origin[a] + i * g.spacing[a];
      d[axes[a]] = toArray(std::move(axis));
    }
    d["coordinates"] = std::vector<std::string>(r.table.names.begin(), r.table.names.begin() + g.dimensions);
    std::vector<pyb::ssize_t> shape{g.size[1], g.size[0]};
    if (g.dimensions == 3) shape.insert(shape.begin(), g.size[2]);
    for (std::size_t k = g.coordinates; k < r.table.names.size(); ++k)
      d[r.table.names[k].c_str()] = toArray(std::vector<double>(r.table.values[k]), shape);
    d["complete"] = !r.stopped;
    return d;
  }
  // the table as one piece under the runner's name (a dict the package makes a Table), else column by column
  const std::string& name = runner.tableName;
  pyb::dict columns;
  pyb::dict& into = name.empty() ? d : columns;
  for (std::size_t k = 0; k < r.table.names.size(); ++k)
    if (!into.contains(r.table.names[k].c_str()))
      into[r.table.names[k].c_str()] = toArray(std::vector<double>(r.table.values[k]));
  for (const auto& t : r.text) // a column of text: a list of str
    into[t.name.c_str()] = t.values;
  if (!name.empty()) d[name.c_str()] = columns;
  return d;
}

pyb::object runTool(const Scene& scene, const std::string& id, const pyb::object& progress,
                    const pyb::kwargs& kw) {
  const ToolEntry& tool = ToolRegistry::global().get(id);
  const ToolRunner* toolRunner = findToolRunner(tool.id);
  if (!toolRunner)
    throw InputError(id + ": not a tool of a scene" +
                     (id == "sweep" ? " (rollviz.sweep(path) runs a sweep file)" : ""));
  std::vector<SceneOverride> overrides;
  for (const auto& [k, v] : kw) {
    const std::string key = pyb::str(k).cast<std::string>();
    if (std::any_of(toolRunner->arguments.begin(), toolRunner->arguments.end(),
                    [&](const ToolArgument& a) { return a.name == key; })) {
      // an argument standing for settings (x=(0, 1) is grid.x_min, x_max): its value as the CLI's text; one
      // that takes no value (doubled=True) applies when true
      const bool flag = std::any_of(toolRunner->arguments.begin(), toolRunner->arguments.end(),
                                    [&](const ToolArgument& a) { return a.name == key && a.flag; });
      if (flag && !PyObject_IsTrue(v.ptr())) continue;
      std::string text;
      if (!flag && pyb::isinstance<pyb::str>(v))
        text = v.cast<std::string>();
      else if (!flag && pyb::isinstance<pyb::sequence>(v))
        for (pyb::handle item : v)
          text += (text.empty() ? "" : ",") + pyb::str(item).cast<std::string>();
      else if (!flag)
        text = pyb::str(v).cast<std::string>();
      try {
        const auto settings = argumentSettings(*toolRunner, key, text);
        overrides.insert(overrides.end(), settings.begin(), settings.end());
      } catch (const InputError& e) {
        throw InputError(key + "=" + pyb::repr(v).cast<std::string>() + ": " + e.what());
      }
    } else {
      overrides.push_back(placeKeyword(scene, tool, key, v));
    }
  }
  return registeredTool(tool, *toolRunner, withOverrides(scene, overrides), progress);
}

pyb::dict toolDict(const ToolEntry& e) {
  pyb::dict d;
  d["id"] = e.id, d["title"] = e.title, d["parent"] = e.parent, d["description"] = e.description;
  d["section"] = e.section, d["command"] = e.command, d["chart"] = e.chartView, d["reference"] = e.reference;
  if (const ToolSection* s = findToolSection(e.section))
    d["settings"] = describeTable(*s->table);
  else
    d["settings"] = pyb::list();
  if (e.options) d["options"] = describeTable(*e.options);
  pyb::list outputs;
  for (const auto& o : e.outputs)
    outputs.append(pyb::make_tuple(o.name, o.description));
  d["outputs"] = outputs;
  pyb::dict outputQuantities; // output -> the sweep quantity it is (TOOL.OUTPUT or its own name)
  for (const auto& o : e.outputs)
    if (o.quantity) outputQuantities[o.name.c_str()] = sweepQuantityId(e, o);
  d["output_quantities"] = outputQuantities;
  pyb::list quantities;
  for (const auto& q : sweepQuantities())
    if (q.tool == e.id || e.options) quantities.append(q.id);
  d["sweep_quantities"] = quantities;
  std::vector<std::string> sections = sectionsOf(e);
  d["sections"] = sections;
  // every keyword a call takes, section by section: the table's numbers and choices, then the text keys
  pyb::list keywords;
  for (const auto& s : sections) {
    if (const ToolSection* t = findToolSection(s))
      for (pyb::handle h : describeTable(*t->table)) {
        pyb::dict k = pyb::reinterpret_borrow<pyb::dict>(h);
        k["section"] = s;
        k["type"] = k.contains("choices") ? "choice" : k["integer"].cast<bool>() ? "integer" : "number";
        keywords.append(k);
      }
    for (const auto& t : sectionTextKeys(s, false)) {
      pyb::dict k;
      k["id"] = t.key, k["description"] = t.description, k["type"] = t.type, k["section"] = s;
      k["default"] = pyb::none();
      keywords.append(k);
    }
  }
  d["keywords"] = keywords;
  std::vector<std::string> arguments;
  std::string help;
  const ToolRunner* toolRunner = findToolRunner(e.id);
  if (toolRunner)
    for (const auto& a : toolRunner->arguments) {
      arguments.push_back(a.name);
      help += (help.empty() ? "" : "; ") + a.name + ": " + a.description;
    }
  d["arguments"] = arguments;
  d["arguments_help"] = help;
  d["origin"] = e.origin;
  d["runner"] = toolRunner != nullptr; // runs through scenes/ToolRunner.h (every front end derived)
  d["table"] = toolRunner ? toolRunner->tableName : std::string(); // the result's key of its table, if one
  return d;
}

// each axis' name for xarray: a map axis (map.0) by the map coordinate it is (x, px), the others by their ids
std::vector<std::string> axisNames(const SweepSpec& spec) {
  std::vector<std::string> coordinates;
  try {
    coordinates =
        PoincareMap(*spec.base.model, spec.base.startIntegrator(), spec.base.poincare).coordinateNames();
  } catch (const std::exception&) { // no section (no map axis either): the ids
  }
  std::vector<std::string> names;
  for (const auto& a : spec.axes) {
    const bool onMap = a.id.rfind("map.", 0) == 0;
    const auto k = onMap ? static_cast<std::size_t>(std::stoi(a.id.substr(4))) : 0;
    names.push_back(onMap && k < coordinates.size() ? coordinates[k] : a.id);
  }
  return names;
}

// rollviz.sweep(path): the sweep on threads, its columns as arrays (rollviz sweep). With a checkpoint the
// points are kept in that file and a later call goes on from them; on Ctrl-C the KeyboardInterrupt carries
// the points finished so far as its second argument.
pyb::object sweep(const std::string& path, int threads, const pyb::object& progress,
                  const pyb::object& checkpoint) {
  const SweepSpec spec = loadSweep(path);
  if (threads < 0) throw InputError("threads: must be at least 1");
  if (threads == 0) threads = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  const bool kept = !checkpoint.is_none();
  const std::string storePath =
      kept ? pyb::str(checkpoint).cast<std::string>()
           : (std::filesystem::temp_directory_path() /
              fmt::format("rollviz-{}-{}.sweep-part", ::getpid(), reinterpret_cast<std::uintptr_t>(&spec)))
                 .string();
  SweepStore store(storePath, spec.resolved.dump(), spec.points(), static_cast<int>(spec.columns.size()),
                   kept ? "checkpoint" : "sweep");
  bool complete = false;
  // a temporary store goes whatever happens; a checkpoint once the sweep is complete (as the CLI's)
  struct Cleanup {
    SweepStore& store;
    bool always;
    const bool& complete;
    ~Cleanup() {
      if (always || complete) store.remove();
    }
  } cleanup{store, !kept, complete};
  // a failure's whole reason for the points this call computes (the store keeps kReasonBytes of it)
  std::mutex reasonsMutex;
  std::map<long, std::string> reasons;
  const ChunkEvaluator evaluate = [&](const std::vector<long>& chunk, const ToolControl& pc,
                                      const RecordSink& sink) {
    evaluateSweepPoints(spec, chunk, pc, [&](long index, const SweepRecord& record) {
      if (!record.ok && record.reason.size() > SweepStore::kReasonBytes) {
        const std::lock_guard lock(reasonsMutex);
        reasons[index] = record.reason;
      }
      sink(index, record);
    });
  };
  std::optional<pyb::error_already_set> interrupted;
  try {
    runJob(progress, [&](const ToolControl& control) {
      ToolControl c = control;
      c.progress = [&](double) { control.progress(static_cast<double>(store.doneCount()) / spec.points()); };
      complete = runSweepLevels(spec, store, threads, [&](ChunkScheduler& scheduler) {
        return runSweepThreads(store, scheduler, evaluate, threads, c);
      });
    });
  } catch (pyb::error_already_set& e) {
    if (!e.matches(PyExc_KeyboardInterrupt)) throw;
    interrupted.emplace(std::move(e));
    complete = false;
  }
  const long n = spec.points();
  std::vector<std::vector<double>> axes(spec.axes.size()), columns(spec.columns.size());
  std::vector<double> seconds;
  std::vector<std::string> status;
  // a refined sweep's points not computed take the value of the nearest computed one (status "painted")
  const std::vector<double> painted = spec.refine > 0 ? sweepGridValues(spec, store) : std::vector<double>{};
  for (long i = 0; i < n; ++i) {
    const auto a = spec.axisValues(i);
    for (std::size_t k = 0; k < axes.size(); ++k)
      axes[k].push_back(a[k]);
    if (!store.done(i)) {
      const bool paint = !painted.empty() && complete;
      for (std::size_t k = 0; k < columns.size(); ++k)
        columns[k].push_back(paint ? painted[static_cast<std::size_t>(i) * columns.size() + k] : NAN);
      seconds.push_back(NAN);
      status.emplace_back(paint ? "painted" : "not computed");
      continue;
    }
    const SweepRecord r = store.read(i);
    for (std::size_t k = 0; k < columns.size(); ++k)
      columns[k].push_back(k < r.values.size() ? r.values[k] : NAN);
    seconds.push_back(r.seconds);
    const auto whole = reasons.find(i);
    status.push_back(r.ok ? "ok" : "failed: " + (whole != reasons.end() ? whole->second : r.reason));
  }
  pyb::dict values;
  for (std::size_t k = 0; k < axes.size(); ++k)
    values[spec.axes[k].id.c_str()] = toArray(std::move(axes[k]));
  for (std::size_t k = 0; k < columns.size(); ++k)
    values[spec.columns[k].c_str()] = toArray(std::move(columns[k]));
  pyb::dict d;
  d["columns"] = values;
  d["axis_names"] = axisNames(spec);
  d["seconds"] = toArray(std::move(seconds));
  d["status"] = status;
  std::vector<int> shape;
  for (const auto& a : spec.axes)
    shape.push_back(a.count);
  d["shape"] = shape;
  d["quantity"] = spec.quantity->id + spec.quantityName;
  d["complete"] = complete;
  if (interrupted) {
    const std::string said =
        fmt::format("the sweep was stopped with {} of {} points finished{} (they are the "
                    "exception's second argument)",
                    store.doneCount(), n, kept ? ", kept in the checkpoint" : "");
    PyErr_SetObject(PyExc_KeyboardInterrupt, pyb::make_tuple(said, d).ptr());
    throw pyb::error_already_set();
  }
  return d;
}

} // namespace

void bindTools(pyb::module_& m, pyb::class_<Scene>& scene) {
  m.def("_tools", [] {
    pyb::list out;
    for (const auto& e : ToolRegistry::global().entries())
      out.append(toolDict(e));
    return out;
  });
  scene.def("_run", &runTool, pyb::arg("tool"), pyb::kw_only(), pyb::arg("progress") = pyb::none());
  m.def("sweep", &sweep, pyb::arg("path"), pyb::arg("threads") = 0, pyb::kw_only(),
        pyb::arg("progress") = pyb::none(), pyb::arg("checkpoint") = pyb::none(),
        "Runs a sweep file (rollviz sweep) on threads: its axes and quantity columns as arrays (first axis "
        "fastest; reshape to `shape` reversed), seconds and status per point.");
}

} // namespace rv::py
