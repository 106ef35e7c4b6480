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
#include "dynamics/tools/ToolSettings.h"
#include "scenes/FixedPointJson.h"
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

// A tool's call: the scene with its settings applied, the keywords that are no scene keys, the callback.
struct Call {
  Scene scene;
  std::map<std::string, pyb::object> args;
  pyb::object progress;
  bool has(const std::string& k) const { return args.count(k) > 0; }
  template <class T> T get(const std::string& k, T fallback) const {
    const auto it = args.find(k);
    return it == args.end() || it->second.is_none() ? fallback : it->second.cast<T>();
  }
};

struct Runner {
  std::vector<std::string> args; ///< keywords of the call that are no scene keys
  std::string help;              ///< what they mean (docstrings)
  std::function<pyb::object(Call&)> run;
};

pyb::array_t<std::complex<double>> complexArray(const std::vector<std::complex<double>>& m) {
  return toArray(std::vector<std::complex<double>>(m));
}

// rows of equal length as an n x k array
pyb::array_t<double> table(std::vector<double>&& flat, std::size_t columns) {
  const auto k = static_cast<pyb::ssize_t>(columns);
  const auto n = k ? static_cast<pyb::ssize_t>(flat.size()) / k : 0;
  return toArray(std::move(flat), {n, k});
}

std::unique_ptr<SceneMap> sceneMap(const Call& c, bool needGuess = true) {
  MapToolOverrides o;
  return std::make_unique<SceneMap>(c.scene, o, needGuess);
}

pyb::object poincare(Call& c) {
  std::vector<double> flat;
  std::size_t width = 0;
  runJob(c.progress, [&](const ToolControl& control) {
    const auto map = scenePoincareMap(c.scene);
    width = map->coordinateNames().size() + 2;
    while (auto p = map->next(control)) {
      flat.insert(flat.end(), p->coordinates.begin(), p->coordinates.end());
      flat.push_back(p->time);
      flat.push_back(p->sheet);
    }
  });
  return table(std::move(flat), width);
}

pyb::dict fixedPointDict(const FixedPointResult& r, const ReturnMap& map) {
  pyb::dict d;
  d["point"] = toArray(toVector(r.point));
  d["coordinates"] = map.coordinateNames();
  d["multipliers"] = complexArray(r.multipliers);
  d["type"] = toString(r.type);
  d["residual"] = r.residual;
  d["iterations"] = r.iterations;
  d["evaluations"] = r.evaluations;
  d["order"] = map.order();
  std::vector<double> path;
  for (const auto& q : r.path) {
    const auto p = toVector(q.point);
    path.insert(path.end(), p.begin(), p.end());
  }
  d["path"] = table(std::move(path), static_cast<std::size_t>(r.point.size()));
  return d;
}

// the fixed point the scene's map search finds; a stop request ends the call as a failure naming the tool
FixedPointResult searchFixedPoint(const SceneMap& s, const ReturnMap& map, const ToolControl& control,
                                  const std::string& tool) {
  try {
    return findFixedPoint(map, s.guess(), s.search(), control);
  } catch (const Stopped&) {
    throw ComputationError(tool + ": stopped");
  }
}

pyb::object fixedpoint(Call& c) {
  const auto s = sceneMap(c);
  const ReturnMap map = s->map();
  FixedPointResult r;
  runJob(c.progress,
         [&](const ToolControl& control) { r = searchFixedPoint(*s, map, control, "fixedpoint"); });
  return fixedPointDict(r, map);
}

pyb::dict changeDict(const TypeChange& t, const std::string& parameter) {
  pyb::dict d;
  d["parameter"] = t.parameter;
  d["kind"] = toString(t.kind);
  d["from"] = toString(t.from);
  d["to"] = toString(t.to);
  d["point"] = toArray(toVector(t.at.fixedPoint.point));
  d["multipliers"] = complexArray(t.at.fixedPoint.multipliers);
  d["description"] = describe(t, parameter);
  return d;
}

// a family's points, multipliers, types and changes as a dict
pyb::dict familyDict(const Continuation& family, const ContinuationSettings& cs, const ReturnMap& map,
                     const std::string& failure) {
  std::vector<double> param, points, residual;
  std::vector<std::complex<double>> multipliers;
  std::vector<std::string> types;
  std::size_t m = 0;
  for (const auto& p : family.points()) {
    param.push_back(p.parameter);
    const auto x = toVector(p.fixedPoint.point);
    points.insert(points.end(), x.begin(), x.end());
    multipliers.insert(multipliers.end(), p.fixedPoint.multipliers.begin(), p.fixedPoint.multipliers.end());
    m = p.fixedPoint.multipliers.size();
    residual.push_back(p.fixedPoint.residual);
    types.emplace_back(toString(p.fixedPoint.type));
  }
  pyb::list changes;
  for (const auto& t : family.changes())
    changes.append(changeDict(t, cs.parameter));
  const auto n = static_cast<pyb::ssize_t>(param.size());
  pyb::dict d;
  d["parameter"] = cs.parameter;
  d["parameter_values"] = toArray(std::move(param));
  d["coordinates"] = map.coordinateNames();
  d["points"] = table(std::move(points), map.coordinateNames().size());
  d["multipliers"] = toArray(std::move(multipliers), {n, static_cast<pyb::ssize_t>(m)});
  d["residual"] = toArray(std::move(residual));
  d["types"] = types;
  d["changes"] = changes;
  d["failure"] = failure;
  d["end"] = failure.empty() ? family.end() : failure; // why the family ends
  return d;
}

pyb::object continuation(Call& c) {
  const auto s = sceneMap(c);
  const ContinuationSettings cs = s->continuation();
  const auto run = s->continuationRun();
  std::string failure;
  runJob(c.progress, [&](const ToolControl& control) {
    try {
      run->run(control);
    } catch (const ComputationError& e) {
      if (run->points().empty() || (cs.switchAt > 0 && !run->doubled())) throw;
      failure = e.what(); // the family up to here is a result: keep it, and say why it ends
    }
  });
  if (!run->doubled()) return familyDict(*run, cs, s->map(), failure);
  // switched (continuation.switch): the family of doubled order, its parent under "parent"
  SectionSettings twice = s->section();
  twice.order *= 2;
  const ReturnMap map(*s->scene().model, s->integrators(), twice);
  pyb::dict d = familyDict(*run->doubled(), cs, map, failure);
  d["order"] = twice.order;
  d["parent"] = familyDict(*run, cs, s->map(), "");
  return d;
}

pyb::object multipliers(Call& c) {
  const auto s = sceneMap(c);
  std::vector<std::vector<std::complex<double>>> path;
  runJob(c.progress, [&](const ToolControl& control) { path = multiplierPath(*s, control); });
  pyb::list out;
  for (const auto& m : path)
    out.append(complexArray(m));
  return out;
}

pyb::object separatrix(Call& c) {
  const auto s = sceneMap(c);
  const ReturnMap map = s->map();
  if (map.dimension() != 2) throw InputError("separatrix: separatrices are drawn for 2D maps only");
  const ParameterValues& sv = s->scene().tool("separatrix");
  std::vector<int> list;
  if (!c.has("branches"))
    list = {static_cast<int>(sv["branch"])};
  else if (pyb::isinstance<pyb::str>(c.args["branches"]) && c.get<std::string>("branches", "") == "all")
    list = {1, 2, 3, 4};
  else
    for (int b : c.args["branches"].cast<std::vector<int>>()) {
      if (b < 1 || b > 4) throw InputError("branches: branches are 1, 2, 3, 4 (or \"all\")");
      list.push_back(b);
    }
  pyb::dict d;
  std::vector<std::pair<int, SeparatrixResult>> results;
  FixedPointResult fp;
  runJob(c.progress, [&](const ToolControl& control) {
    fp = searchFixedPoint(*s, map, control, "separatrix");
    for (int b : list) {
      SeparatrixSettings ss = separatrixSettings(sv, s->search());
      ss.branch = b;
      results.emplace_back(b, growSeparatrix(map, fp, ss, control));
      if (results.back().second.stoppedBecause == "stopped") break;
    }
  });
  d["fixedpoint"] = fixedPointDict(fp, map);
  pyb::dict branches;
  for (auto& [b, r] : results) {
    std::vector<double> flat;
    for (const auto& p : r.points) {
      const auto x = toVector(p);
      flat.insert(flat.end(), x.begin(), x.end());
    }
    pyb::dict x;
    x["points"] = table(std::move(flat), 2);
    x["parameters"] = toArray(std::vector<double>(r.parameters));
    x["multiplier"] = r.multiplier;
    x["unstable"] = r.unstable;
    x["linear_region"] = r.linearRegion;
    x["ended_by"] = r.stoppedBecause;
    branches[pyb::int_(b)] = x;
  }
  d["branches"] = branches;
  return d;
}

pyb::object bifurcationTree(Call& c) {
  const auto s = sceneMap(c);
  const ContinuationSettings cs = s->continuation();
  const BifurcationTreeSettings t = bifurcationTreeSettings(s->scene().tool("bifurcation_tree"), cs);
  const double start = s->spec().modelParameters[cs.parameter];
  std::vector<double> rows;
  std::vector<std::string> types;
  BifurcationTreeResult r;
  const ReturnMap map = s->map();
  runJob(c.progress, [&](const ToolControl& control) {
    try {
      bifurcationTree(
          s->spec().modelAt(cs.parameter), s->integrators(), s->section(), start, s->guess(), t, control,
          [&](const TreeBranch& b, const ContinuationPoint& p) {
            rows.push_back(b.level), rows.push_back(b.order), rows.push_back(p.parameter);
            const auto x = toVector(p.fixedPoint.point);
            rows.insert(rows.end(), x.begin(), x.end());
            types.emplace_back(toString(p.fixedPoint.type));
          },
          [](const PeriodDoubling&) {}, &r);
    } catch (const Stopped&) {
    }
  });
  pyb::list doublings;
  for (const auto& x : r.doublings) {
    pyb::dict d;
    d["level"] = x.level, d["order"] = x.order, d["parameter"] = x.parameter;
    doublings.append(d);
  }
  std::vector<std::string> columns{"level", "order", cs.parameter};
  for (const auto& n : map.coordinateNames())
    columns.push_back(n);
  pyb::dict d;
  d["parameter"] = cs.parameter;
  d["columns"] = columns;
  d["rows"] = table(std::move(rows), columns.size());
  d["types"] = types;
  d["doublings"] = doublings;
  d["ratios"] = r.ratios();
  d["end"] = r.end;
  return d;
}

pyb::object plot(Call& c) {
  std::vector<std::vector<double>> points;
  runJob(c.progress, [&](const ToolControl& control) {
    auto integ = c.scene.startIntegrator();
    points = samplePlot(*c.scene.model, *integ, c.scene.plot.settings, control);
  });
  std::vector<double> flat;
  std::size_t width = 0;
  for (const auto& p : points) {
    flat.insert(flat.end(), p.begin(), p.end());
    width = p.size();
  }
  return table(std::move(flat), width);
}

const std::map<std::string, Runner>& runners() {
  static const std::map<std::string, Runner> r{
      {"poincare", {{}, "", poincare}},
      {"map3d", {{}, "", poincare}},
      {"plot", {{}, "", plot}},
      {"fixedpoint", {{}, "", fixedpoint}},
      {"continuation", {{}, "", continuation}},
      {"multipliers", {{}, "", multipliers}},
      {"separatrix",
       {{"branches"}, "branches: a list of 1..4 or \"all\" (default: separatrix.branch)", separatrix}},
      {"bifurcation_tree", {{}, "", bifurcationTree}},
  };
  return r;
}

// the scene sections a plain keyword of the tool may belong to: its own, its ancestors' in the tree, then the
// others it reads
std::vector<std::string> sectionsOf(const ToolEntry& tool) {
  std::vector<std::string> out;
  for (const ToolEntry* t = &tool; t;
       t = t->parent.empty() ? nullptr : &ToolRegistry::global().get(t->parent))
    if (!t->section.empty() && std::find(out.begin(), out.end(), t->section) == out.end())
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

// a tool that runs through scenes/ToolRunner.h: its fields, and its table's columns as arrays
pyb::object registeredTool(const ToolEntry& tool, Call& c) {
  ToolResult r;
  runJob(c.progress, [&](const ToolControl& control) { r = rv::runTool(tool, c.scene, control); });
  pyb::dict d = pyb::module_::import("json").attr("loads")(toolResultJson(r).dump());
  d["stopped"] = r.stopped;
  for (const auto& [name, value] : r.fields.items()) // a list of numbers is an array (exponents)
    if (value.is_array() && !value.empty() &&
        std::all_of(value.begin(), value.end(), [](const auto& v) { return v.is_number(); }))
      d[name.c_str()] = toArray(value.get<std::vector<double>>());
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
  const std::string& name = findToolRunner(tool.id)->tableName;
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

// the Python call of a tool: written here, or the generic one of a tool with a runner
const Runner* runnerOf(const ToolEntry& tool) {
  if (const auto it = runners().find(tool.id); it != runners().end()) return &it->second;
  if (!findToolRunner(tool.id)) return nullptr;
  static std::map<std::string, Runner> generic;
  auto [it, fresh] = generic.try_emplace(tool.id);
  if (fresh) it->second.run = [&tool](Call& c) { return registeredTool(tool, c); };
  return &it->second;
}

pyb::object runTool(const Scene& scene, const std::string& id, const pyb::object& progress,
                    const pyb::kwargs& kw) {
  const ToolEntry& tool = ToolRegistry::global().get(id);
  const Runner* found = runnerOf(tool);
  if (!found)
    throw InputError(id + ": not a tool of a scene" +
                     (id == "sweep" ? " (rollviz.sweep(path) runs a sweep file)" : ""));
  const Runner& runner = *found;
  Call call{scene, {}, progress};
  std::vector<SceneOverride> overrides;
  const ToolRunner* toolRunner = findToolRunner(tool.id);
  for (const auto& [k, v] : kw) {
    const std::string key = pyb::str(k).cast<std::string>();
    if (std::find(runner.args.begin(), runner.args.end(), key) != runner.args.end()) {
      call.args[key] = pyb::reinterpret_borrow<pyb::object>(v);
    } else if (toolRunner && std::any_of(toolRunner->arguments.begin(), toolRunner->arguments.end(),
                                         [&](const ToolArgument& a) { return a.name == key; })) {
      // an argument standing for settings (x=(0, 1) is grid.x_min, x_max): its value as the CLI's text
      std::string text;
      if (pyb::isinstance<pyb::str>(v))
        text = v.cast<std::string>();
      else if (pyb::isinstance<pyb::sequence>(v))
        for (pyb::handle item : v)
          text += (text.empty() ? "" : ",") + pyb::str(item).cast<std::string>();
      else
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
  call.scene = withOverrides(scene, overrides);
  return runner.run(call);
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
  const Runner* runner = runnerOf(e);
  std::vector<std::string> arguments = runner ? runner->args : std::vector<std::string>{};
  std::string help = runner ? runner->help : std::string();
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
  const BatchEvaluator evaluate = [&](const std::vector<long>& indices, const ToolControl& pc) {
    auto records = evaluateSweepPoints(spec, indices, pc);
    for (std::size_t k = 0; k < records.size(); ++k)
      if (!records[k].ok && records[k].reason.size() > SweepStore::kReasonBytes) {
        const std::lock_guard lock(reasonsMutex);
        reasons[indices[k]] = records[k].reason;
      }
    return records;
  };
  std::optional<pyb::error_already_set> interrupted;
  try {
    runJob(progress, [&](const ToolControl& control) {
      ToolControl c = control;
      c.progress = [&](double) { control.progress(static_cast<double>(store.doneCount()) / spec.points()); };
      complete = runSweepLevels(spec, store, threads, [&](ChunkScheduler& scheduler) {
        return runSweepThreads(store, scheduler, evaluate, sweepBatch(spec), threads, c);
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
