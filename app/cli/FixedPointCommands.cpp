// FixedPointCommands.cpp -- `rollviz fixedpoint`, `continue`, `separatrix`, `bifurcation-tree`, `surface`,
// `ram`, `diagram`: the fixed-point family of tools (dynamics/tools) on a scene's map, in the foreground,
// with progress on a terminal and Ctrl-C keeping what was computed (exit 130). Settings come from the scene's
// sections (rollviz list tools) and --set SECTION.ID=VALUE; the flags below are the everyday ones.
#include "app/cli/Checkpoint.h"
#include "app/cli/Commands.h"
#include "app/cli/Output.h"
#include "app/cli/Progress.h"
#include "dynamics/core/Errors.h"
#include "dynamics/tools/ToolSettings.h"
#include "render/export/VtkXmlFiles.h"
#include "scenes/FixedPointJson.h"
#include "scenes/JsonFields.h"
#include "scenes/SceneTools.h"

#include <cmath>
#include <fmt/core.h>
#include <fmt/format.h>
#include <fmt/ranges.h>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <sstream>

namespace rv {

namespace {

std::vector<double> parseNumbers(const std::string& text, const std::string& flag) {
  try {
    return commaNumbers(text);
  } catch (const InputError& e) {
    throw InputError(flag + " " + text + ": " + e.what());
  }
}

std::string header(const std::vector<std::string>& names) {
  std::string h;
  for (const auto& n : names)
    h += (h.empty() ? "" : ",") + n;
  return h;
}

// what every command of the family shares: the scene, the guess, the order
struct MapArgs {
  SceneArgs scene;
  std::string guess;
  int order = 0;
  std::string method;
};

void addMapArgs(CLI::App* cmd, MapArgs& a, bool withGuess = true) {
  addSceneArgs(cmd, a.scene);
  if (withGuess)
    cmd->add_option("--guess", a.guess,
                    "starting point x,y[,z] in map coordinates (default: fixedpoint.guess, or the scene's "
                    "initial map point)");
  cmd->add_option("--order", a.order, "order n of the map Map^n (default: fixedpoint.order)");
  cmd->add_option("--method", a.method, "newton | gradient (default: fixedpoint.method)");
}

// the scene with the flags folded into its tool settings
std::unique_ptr<SceneMap> setUp(const MapArgs& a, bool needGuess = true, const MapToolOverrides& extra = {}) {
  MapToolOverrides o = extra;
  o.order = a.order, o.method = a.method;
  if (!a.guess.empty()) o.guess = parseNumbers(a.guess, "--guess");
  return std::make_unique<SceneMap>(a.scene.load(), o, needGuess);
}

void printRow(FILE* f, const std::vector<double>& values, const std::string& tail = {}) {
  for (std::size_t i = 0; i < values.size(); ++i)
    std::fprintf(f, i ? ",%.17g" : "%.17g", values[i]);
  std::fprintf(f, "%s\n", tail.c_str());
}

struct ContinueArgs {
  MapArgs map;
  std::string param, output;
  double to = NAN, step = NAN;
  bool json = false, arclength = false, doubled = false;
};

void addContinueArgs(CLI::App* cmd, ContinueArgs& a) {
  addMapArgs(cmd, a.map);
  cmd->add_option("--param", a.param, "the model parameter to continue in (default: continuation.parameter)");
  cmd->add_option("--to", a.to, "finite value of the parameter (default: continuation.to)");
  cmd->add_option("--step", a.step,
                  "signed step of the parameter; with --arclength the longest step along the family "
                  "(default: continuation.step)");
  cmd->add_option("-o,--output", a.output, "CSV file (default: standard output)")
      ->check(writesOneOf({".csv"}));
  cmd->add_flag("--json", a.json, "print a JSON summary on standard output");
}

MapToolOverrides continuationOverrides(const ContinueArgs& a) {
  MapToolOverrides o;
  o.parameter = a.param;
  if (!std::isnan(a.to)) o.to = a.to;
  if (!std::isnan(a.step)) o.step = a.step;
  return o;
}

std::string continuationHeader(const std::string& param, const ReturnMap& map, std::size_t multipliers) {
  std::vector<std::string> names{param};
  for (const auto& n : map.coordinateNames())
    names.push_back(n);
  for (std::size_t i = 1; i <= multipliers; ++i) {
    names.push_back(fmt::format("re{}", i));
    names.push_back(fmt::format("im{}", i));
  }
  names.push_back("residual");
  names.push_back("type");
  return header(names);
}

void printContinuationPoint(FILE* f, const ContinuationPoint& p) {
  std::vector<double> row{p.parameter};
  for (double x : toVector(p.fixedPoint.point))
    row.push_back(x);
  for (auto z : p.fixedPoint.multipliers)
    row.push_back(z.real()), row.push_back(z.imag());
  row.push_back(p.fixedPoint.residual);
  printRow(f, row, std::string(",") + toString(p.fixedPoint.type));
}

nlohmann::json changeJson(const TypeChange& t) {
  return {{"parameter", t.parameter},
          {"kind", toString(t.kind)},
          {"from", toString(t.from)},
          {"to", toString(t.to)},
          {"point", toVector(t.at.fixedPoint.point)},
          {"multipliers", multipliersJson(t.at.fixedPoint.multipliers)}};
}

} // namespace

Command addFixedPointCommand(CLI::App* cmd) {
  auto a = std::make_shared<MapArgs>();
  auto json = std::make_shared<bool>(false), path = std::make_shared<bool>(false);
  addMapArgs(cmd, *a);
  cmd->add_flag("--json", *json,
                "print one JSON object: point, multipliers [[re, im], ...], type, residual, ...");
  cmd->add_flag("--path", *path, "also give the whole search path (the manual's \"show all points\")");
  return {cmd, [a, json, path] {
            const auto s = setUp(*a);
            const ReturnMap map = s->map();
            Progress progress("fixedpoint");
            FixedPointResult r;
            try {
              r = findFixedPoint(map, s->guess(), s->search(), interruptibleControl(progress));
            } catch (const Stopped&) {
              fmt::print(stderr, "rollviz: fixedpoint: stopped\n");
              return 130;
            }
            if (*json) {
              nlohmann::json j{{"point", toVector(r.point)},
                               {"coordinates", map.coordinateNames()},
                               {"multipliers", multipliersJson(r.multipliers)},
                               {"type", toString(r.type)},
                               {"residual", r.residual},
                               {"iterations", r.iterations},
                               {"evaluations", r.evaluations},
                               {"order", map.order()}};
              if (*path) {
                nlohmann::json p = nlohmann::json::array();
                for (const auto& q : r.path)
                  p.push_back({{"point", toVector(q.point)}, {"residual", q.residual}});
                j["path"] = p;
              }
              fmt::print("{}\n", j.dump());
              return 0;
            }
            if (*path)
              for (const auto& q : r.path)
                fmt::print("search: {:.17g}  |Map^n(x) - x| = {:.3g}\n", fmt::join(toVector(q.point), ", "),
                           q.residual);
            fmt::print("point: {:.17g}\n", fmt::join(toVector(r.point), ", "));
            for (auto z : r.multipliers)
              fmt::print("multiplier: {:.15g} {:+.15g} i  (|m| = {:.15g})\n", z.real(), z.imag(),
                         std::abs(z));
            fmt::print("type: {}\nresidual: {:.3g}\niterations: {}\nmap evaluations: {}\n", toString(r.type),
                       r.residual, r.iterations, r.evaluations);
            return 0;
          }};
}

Command addContinueCommand(CLI::App* cmd) {
  auto a = std::make_shared<ContinueArgs>();
  addContinueArgs(cmd, *a);
  cmd->add_flag("--arclength", a->arclength,
                "pseudo-arclength continuation, which passes folds (continuation.method = arclength)");
  cmd->add_flag(
      "--doubled", a->doubled,
      "branch switching: write the family of doubled order born at the first period doubling instead, "
      "continued to the end of [start, --to] on its side (continuation.switch = 1)");
  return {
      cmd, [a] {
        if (a->arclength) a->map.scene.sets.emplace_back("continuation.method=arclength");
        if (a->doubled) a->map.scene.sets.emplace_back("continuation.switch=1");
        const auto s = setUp(a->map, true, continuationOverrides(*a));
        const ContinuationSettings c = s->continuation();
        const auto run = s->continuationRun();
        Continuation& cont = *run;
        Output out(a->output);
        FILE* changes = a->output.empty() ? stderr : stdout;
        bool headed = false;
        const ReturnMap map = s->map();
        Progress progress("continue");
        std::string failure;
        bool done = false;
        try {
          done = cont.run(
              interruptibleControl(progress),
              [&](const ContinuationPoint& p) {
                if (!headed) {
                  std::fprintf(out.get(), "%s\n",
                               continuationHeader(c.parameter, map, p.fixedPoint.multipliers.size()).c_str());
                  if (cont.doubled() && !a->json)
                    fmt::print(changes,
                               "the family of order {} born at the period doubling starts at {} = {:.12g}\n",
                               2 * s->section().order, c.parameter, p.parameter);
                }
                headed = true;
                printContinuationPoint(out.get(), p);
              },
              [&](const TypeChange& t) {
                if (!a->json) fmt::print(changes, "{}\n", describe(t, c.parameter));
              });
        } catch (const ComputationError& e) {
          if (cont.points().empty() || (c.switchAt > 0 && !cont.doubled())) throw;
          failure = e.what(); // the family up to here is a result: keep it, and say why it ends
        }
        out.commit();
        if (!failure.empty()) {
          fmt::print(stderr, "rollviz: failed: {}\n", failure);
          return 1;
        }
        const auto summary = [&](const Continuation& family) {
          nlohmann::json ch = nlohmann::json::array();
          for (const auto& t : family.changes())
            ch.push_back(changeJson(t));
          return nlohmann::json{
              {"parameter", c.parameter},
              {"method", c.method == ContinuationMethod::Arclength ? "arclength" : "natural"},
              {"points", family.points().size()},
              {"last", family.points().empty() ? 0.0 : family.points().back().parameter},
              {"changes", ch},
              {"end", family.end()}};
        };
        const Continuation& result = cont.doubled() ? *cont.doubled() : cont;
        if (a->json) {
          nlohmann::json j = summary(cont);
          if (cont.doubled()) {
            j["doubled"] = summary(result);
            j["doubled"]["order"] = 2 * s->section().order;
            j["doubled"]["first"] = result.points().front().parameter;
          }
          fmt::print("{}\n", j.dump());
        } else if (done && (c.method == ContinuationMethod::Arclength || cont.doubled())) {
          fmt::print(changes, "the family ends: {}\n", result.end());
        }
        return done ? 0 : 130;
      }};
}

Command addBifurcationTreeCommand(CLI::App* cmd) {
  auto a = std::make_shared<ContinueArgs>();
  addContinueArgs(cmd, *a);
  return {cmd, [a] {
            const auto s = setUp(a->map, true, continuationOverrides(*a));
            const ContinuationSettings c = s->continuation();
            const BifurcationTreeSettings t = bifurcationTreeSettings(s->scene().tool("bifurcation_tree"), c);
            const double start = s->spec().modelParameters[c.parameter];
            Output out(a->output);
            const ReturnMap map = s->map();
            std::vector<std::string> names{"level", "order", c.parameter};
            for (const auto& n : map.coordinateNames())
              names.push_back(n);
            names.push_back("type");
            std::fprintf(out.get(), "%s\n", header(names).c_str());
            Progress progress("bifurcation-tree");
            BifurcationTreeResult r;
            bool stopped = false;
            try {
              bifurcationTree(
                  s->spec().modelAt(c.parameter), s->integrators(), s->section(), start, s->guess(), t,
                  interruptibleControl(progress),
                  [&](const TreeBranch& b, const ContinuationPoint& p) {
                    std::vector<double> row{static_cast<double>(b.level), static_cast<double>(b.order),
                                            p.parameter};
                    for (double x : toVector(p.fixedPoint.point))
                      row.push_back(x);
                    printRow(out.get(), row, std::string(",") + toString(p.fixedPoint.type));
                  },
                  [&](const PeriodDoubling& d) {
                    if (!a->json)
                      fmt::print(a->output.empty() ? stderr : stdout,
                                 "period doubling of order {} at {} = {:.12g}\n", d.order, c.parameter,
                                 d.parameter);
                  },
                  &r);
            } catch (const Stopped&) {
              stopped = true;
            }
            out.commit();
            if (a->json) {
              nlohmann::json d = nlohmann::json::array();
              for (const auto& x : r.doublings)
                d.push_back({{"level", x.level}, {"order", x.order}, {"parameter", x.parameter}});
              fmt::print("{}\n", nlohmann::json{{"parameter", c.parameter},
                                                {"doublings", d},
                                                {"ratios", r.ratios()},
                                                {"end", r.end}}
                                     .dump());
            } else {
              for (double q : r.ratios())
                fmt::print(a->output.empty() ? stderr : stdout, "ratio: {:.10g}\n", q);
              if (!r.end.empty())
                fmt::print(a->output.empty() ? stderr : stdout, "the tree ends: {}\n", r.end);
            }
            return stopped ? 130 : 0;
          }};
}

Command addSeparatrixCommand(CLI::App* cmd) {
  auto a = std::make_shared<MapArgs>();
  auto branches = std::make_shared<std::string>(), output = std::make_shared<std::string>();
  addMapArgs(cmd, *a);
  cmd->add_option("--branch", *branches, "branches 1-4, comma-separated (default: separatrix.branch; 'all')");
  cmd->add_option("-o,--output", *output,
                  "CSV file: branch, coordinates, parameter (default: standard output)")
      ->check(writesOneOf({".csv"}));
  return {cmd, [a, branches, output] {
            const auto s = setUp(*a);
            const ReturnMap map = s->map();
            if (map.dimension() != 2) throw InputError("separatrix: separatrices are drawn for 2D maps only");
            const ParameterValues& sv = s->scene().tool("separatrix");
            std::vector<int> list;
            if (*branches == "all")
              list = {1, 2, 3, 4};
            else if (!branches->empty())
              for (double b : parseNumbers(*branches, "--branch")) {
                if (b != 1 && b != 2 && b != 3 && b != 4)
                  throw InputError("--branch: branches are 1, 2, 3, 4");
                list.push_back(static_cast<int>(b));
              }
            else
              list = {static_cast<int>(sv["branch"])};
            Progress progress("separatrix");
            const ToolControl control = interruptibleControl(progress);
            FixedPointResult fp;
            try {
              fp = findFixedPoint(map, s->guess(), s->search(), control);
            } catch (const Stopped&) {
              return 130;
            }
            Output out(*output);
            std::fprintf(out.get(), "branch,%s,parameter\n", header(map.coordinateNames()).c_str());
            for (int b : list) {
              SeparatrixSettings ss = separatrixSettings(sv, s->search());
              ss.branch = b;
              const SeparatrixResult r = growSeparatrix(map, fp, ss, control);
              for (std::size_t i = 0; i < r.points.size(); ++i) {
                std::vector<double> row{static_cast<double>(b)};
                for (double x : toVector(r.points[i]))
                  row.push_back(x);
                row.push_back(r.parameters[i]);
                printRow(out.get(), row);
              }
              fmt::print(stderr,
                         "branch {}: {} points, multiplier {:.12g} ({}), linear region {:g}, ended by {}\n",
                         b, r.points.size(), r.multiplier, r.unstable ? "outgoing" : "incoming",
                         r.linearRegion, r.stoppedBecause);
              if (r.stoppedBecause == "stopped") break;
            }
            out.commit();
            return interrupted() ? 130 : 0;
          }};
}

} // namespace rv
