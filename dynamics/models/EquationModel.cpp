#include "dynamics/models/EquationModel.h"

#include "dynamics/core/TaylorTape.h"
#include "dynamics/expr/Lowering.h"
#include "dynamics/kinematics/RootFinding.h"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <functional>
#include <map>
#include <numbers>
#include <set>
#include <sstream>

namespace rv {
namespace {

using expr::Expression;
using expr::Graph;
using expr::Value;

constexpr const char* kTime = "time";

/// An index as the containers take it (from int arithmetic that cannot be negative here).
constexpr std::size_t idx(int i) {
  return static_cast<std::size_t>(i);
} // the state component of a non-autonomous flow's autonomous extension

bool identifier(const std::string& s) {
  if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) != 0 || s[0] == '_')) return false;
  return std::all_of(s.begin(), s.end(),
                     [](char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; });
}

/// Rethrows a parse or type error of one expression with the expression's place in front.
template <class F> auto at(const std::string& where, F&& f) -> decltype(f()) {
  try {
    return f();
  } catch (const expr::ExprError& e) {
    throw InputError(where + ": " + e.what());
  }
}

// Names resolved in one context: base values (state, time, parameters, map symbols) and the definitions,
// lowered once each on first use (a definition that reaches itself again is a circle).
class Scope {
public:
  Scope(const EquationSystem& system, Graph& graph, std::map<std::string, Value> base)
      : system_(system), graph_(graph), base_(std::move(base)) {
    for (const auto& [name, v] : base_)
      known_.push_back(name);
    for (const auto& [name, text] : system_.spec().definitions)
      known_.push_back(name);
  }

  Value lower(const ExprText& text) {
    origins_.push_back(text.where);
    graph_.setOrigin(text.where);
    const Expression& e = system_.parsed(text.where);
    expr::Lowering lowering(
        graph_, [this](const std::string& name, int column) { return resolve(name, column); }, known_);
    Value v = at(text.where, [&] { return lowering.lower(e); });
    origins_.pop_back(); // the nodes made next belong to the expression that used this one
    if (!origins_.empty()) graph_.setOrigin(origins_.back());
    return v;
  }
  /// lower() that requires a shape: rows x cols (cols 1: a vector; rows = cols = 1: a scalar).
  Value lower(const ExprText& text, int rows, int cols, const std::string& what) {
    Value v = lower(text);
    if (v.rows != rows || v.cols != cols)
      throw InputError(text.where + ": " + what + " must be " + expr::shapeName(Value{rows, cols, {}}) +
                       ", not " + expr::shapeName(v));
    return v;
  }

private:
  std::optional<Value> resolve(const std::string& name, int column) {
    if (const auto it = base_.find(name); it != base_.end()) return it->second;
    if (const auto it = done_.find(name); it != done_.end()) return it->second;
    const auto& defs = system_.spec().definitions;
    const auto def = std::find_if(defs.begin(), defs.end(), [&](const auto& d) { return d.first == name; });
    if (def == defs.end()) return std::nullopt;
    if (const auto open = std::find(stack_.begin(), stack_.end(), name); open != stack_.end()) {
      std::string circle;
      for (auto it = open; it != stack_.end(); ++it)
        circle += *it + " -> ";
      throw expr::ExprError(column, "the definitions refer to each other in a circle: " + circle + name);
    }
    stack_.push_back(name);
    const Value v = lower(def->second);
    if (const auto shape = system_.spec().definitionShapes.find(name);
        shape != system_.spec().definitionShapes.end() &&
        (v.rows != shape->second.rows || v.cols != shape->second.cols))
      throw InputError(def->second.where + ": " + shape->second.what + " must be " +
                       expr::shapeName(Value{shape->second.rows, shape->second.cols, {}}) + ", not " +
                       expr::shapeName(v));
    stack_.pop_back();
    done_.emplace(name, v);
    return v;
  }

  const EquationSystem& system_;
  Graph& graph_;
  std::map<std::string, Value> base_;
  std::map<std::string, Value> done_;
  std::vector<std::string> stack_;   // definitions being lowered (a circle returns to one of them)
  std::vector<std::string> origins_; // the expressions being lowered, innermost last
  std::vector<std::string> known_;
};

/// The base names of the model's own state: each component an input slot, the vectors, `t`, the parameters
/// as constants (folded into the programs).
std::map<std::string, Value> stateNames(const EquationSystem& system, Graph& g, const ParameterValues* p,
                                        const std::vector<int>& stateNodes, int timeNode) {
  std::map<std::string, Value> base;
  const auto& names = system.info().stateNames;
  for (std::size_t i = 0; i < names.size(); ++i)
    base[names[i]] = Value::of(stateNodes[i]);
  for (const auto& [name, components] : system.spec().vectors) {
    Value v{static_cast<int>(components.size()), 1, {}};
    for (const auto& c : components)
      v.n.push_back(base.at(c).n[0]);
    base[name] = v;
  }
  base["t"] = Value::of(timeNode);
  // the parameters' values folded in, or (p null) input slots after the state and the time, for the
  // generated code that takes them at run time
  const auto& specs = system.info().parameters.specs();
  const int first = static_cast<int>(names.size()) + 1;
  for (std::size_t i = 0; i < specs.size(); ++i)
    base[specs[i].id] = Value::of(p ? g.constant(p->values()[i]) : g.input(first + static_cast<int>(i)));
  return base;
}

/// Input slots 0..n-1: the state.
std::vector<int> stateInputs(Graph& g, int n) {
  std::vector<int> state;
  state.reserve(idx(n));
  for (int i = 0; i < n; ++i)
    state.push_back(g.input(i));
  return state;
}

/// The right-hand side's nodes, one per state component, in a scope of the state's names.
std::vector<int> fieldNodes(const EquationSystem& sys, Graph& g, Scope& scope) {
  const auto& spec = sys.spec();
  const auto& names = sys.info().stateNames;
  std::vector<int> field(names.size(), -1);
  const auto index = [&](const std::string& name) {
    return static_cast<std::size_t>(std::find(names.begin(), names.end(), name) - names.begin());
  };
  for (const auto& equation : spec.equations) { // no structured binding: the lambda below captures the key
    const std::string& key = equation.first;
    const ExprText& text = equation.second;
    const auto vec =
        std::find_if(spec.vectors.begin(), spec.vectors.end(), [&](const auto& v) { return v.first == key; });
    if (vec == spec.vectors.end()) {
      field[index(key)] = scope.lower(text, 1, 1, "the equation of a scalar").n[0];
      continue;
    }
    const Value v = scope.lower(text, static_cast<int>(vec->second.size()), 1, "the equation of a vector");
    for (std::size_t c = 0; c < vec->second.size(); ++c)
      field[index(vec->second[c])] = v.n[c];
  }
  if (sys.nonAutonomous()) field.back() = g.constant(1);
  return field;
}

} // namespace

// ---------------------------------------------------------------------------------------------------------
// EquationSystem

namespace {
void requireIdentifier(const std::string& name, const std::string& where, std::set<std::string>& taken) {
  if (!identifier(name))
    throw InputError(where + ": '" + name +
                     "' is not a name (letters, digits and '_', not starting with a digit)");
  static const std::set<std::string> reserved{"t", "pi", "section"};
  const auto& functions = expr::functionNames();
  if (reserved.count(name) || std::find(functions.begin(), functions.end(), name) != functions.end())
    throw InputError(where + ": '" + name + "' is reserved (the language's own name)");
  if (!taken.insert(name).second) throw InputError(where + ": the name '" + name + "' is defined twice");
}
} // namespace

EquationSystem::EquationSystem(EquationModelSpec spec) : spec_(std::move(spec)), info_(spec_.info) {
  const bool flow = info_.kind == ModelKind::Flow;
  // every name once
  std::set<std::string> taken;
  for (const auto& p : info_.parameters.specs())
    requireIdentifier(p.id, "parameters." + p.id, taken);
  if (info_.stateNames.empty()) throw InputError("state: a model needs at least one state variable");
  for (const auto& s : info_.stateNames)
    requireIdentifier(s, "state." + s, taken);
  for (const auto& [name, components] : spec_.vectors) {
    requireIdentifier(name, "vectors." + name, taken);
    if (components.size() < 2) throw InputError("vectors." + name + ": a vector has two or more components");
    for (const auto& c : components)
      if (std::find(info_.stateNames.begin(), info_.stateNames.end(), c) == info_.stateNames.end())
        throw InputError("vectors." + name + ": '" + c + "' is not a state variable");
  }
  for (const auto& [name, text] : spec_.definitions)
    requireIdentifier(name, text.where, taken);

  // parse every text once
  const auto parse = [&](const ExprText& t) {
    parsed_.emplace_back(t.where, at(t.where, [&] { return expr::parse(t.text); }));
  };
  for (const auto& d : spec_.definitions)
    parse(d.second);
  for (const auto& e : spec_.equations)
    parse(e.second);
  for (const auto& o : spec_.observables)
    parse(o.value);
  if (spec_.measure) parse(*spec_.measure);
  for (const auto& c : spec_.completion)
    parse(c.second);
  if (spec_.strobePeriod) parse(*spec_.strobePeriod);
  if (spec_.map) {
    for (const auto& s : spec_.map->state)
      parse(s.second);
    if (!spec_.map->unknown.empty())
      for (const ExprText* t : {&spec_.map->from, &spec_.map->to, &spec_.map->step, &spec_.map->value})
        parse(*t);
  }
  if (spec_.view) {
    const auto& v = *spec_.view;
    for (const EquationModelSpec::Shape* shape : {&v.body, &v.support})
      for (const auto* t : {&shape->semiAxes, &shape->centre, &shape->p, &shape->q, &shape->height})
        if (*t) parse(**t);
    for (const auto* t :
         {&v.meshScale, &v.normal, &v.surface, &v.surfaceSize, &v.supportSurface, &v.supportSurfaceSize})
      if (*t) parse(**t);
    for (const ExprText* t : {&v.rotation, &v.position, &v.contact})
      parse(*t);
  }

  // one equation per state variable
  std::map<std::string, std::string> equationOf;
  for (const auto& equation : spec_.equations) { // no structured binding: the lambdas below capture the key
    const std::string& key = equation.first;
    const ExprText& text = equation.second;
    std::vector<std::string> targets;
    const auto vec = std::find_if(spec_.vectors.begin(), spec_.vectors.end(),
                                  [&](const auto& v) { return v.first == key; });
    if (vec != spec_.vectors.end())
      targets = vec->second;
    else if (std::find(info_.stateNames.begin(), info_.stateNames.end(), key) != info_.stateNames.end())
      targets = {key};
    else
      throw InputError(text.where + ": '" + key + "' is not a state variable or vector" + [&] {
        const std::string near = expr::nearestName(key, info_.stateNames);
        return near.empty() ? std::string() : " (did you mean '" + near + "'?)";
      }());
    for (const auto& t : targets)
      if (!equationOf.emplace(t, text.where).second)
        throw InputError(text.where + ": '" + t + "' already has an equation (" + equationOf[t] + ")");
  }
  for (const auto& s : info_.stateNames)
    if (!equationOf.count(s))
      throw InputError("equations: the state variable '" + s + "' has no equation (" +
                       (flow ? "d" + s + "/dt" : "its next value") + ")");

  // which state variables each equation reads (through definitions and vectors): time dependence and the
  // core (the leading variables whose equations read only each other)
  std::map<std::string, std::set<std::string>> reads;
  std::set<std::string> visiting;
  std::function<const std::set<std::string>&(const std::string&)> readsOf =
      [&](const std::string& where) -> const std::set<std::string>& {
    if (const auto it = reads.find(where); it != reads.end()) return it->second;
    std::set<std::string> out;
    if (visiting.insert(where).second) { // circles are reported by the lowering, with the column
      for (const auto& name : expr::namesUsed(parsed(where))) {
        if (name == "t") out.insert(kTime);
        if (std::find(info_.stateNames.begin(), info_.stateNames.end(), name) != info_.stateNames.end())
          out.insert(name);
        for (const auto& [v, components] : spec_.vectors)
          if (v == name) out.insert(components.begin(), components.end());
        for (const auto& [d, text] : spec_.definitions)
          if (d == name) {
            const auto& inner = readsOf(text.where);
            out.insert(inner.begin(), inner.end());
          }
      }
      visiting.erase(where);
    }
    return reads[where] = std::move(out);
  };
  std::map<std::string, std::set<std::string>> equationReads;
  for (const auto& [key, where] : equationOf)
    equationReads[key] = readsOf(where);
  for (const auto& [key, r] : equationReads)
    if (r.count(kTime)) {
      if (!flow)
        throw InputError(equationOf[key] + ": a map has no time 't' (its equations give the next state)");
      nonAutonomous_ = true;
    }
  if (nonAutonomous_) {
    if (std::find(info_.stateNames.begin(), info_.stateNames.end(), kTime) != info_.stateNames.end())
      throw InputError(std::string("state.") + kTime + ": a flow that reads t names its time component '" +
                       kTime + "' itself; rename the state variable");
    info_.stateNames.push_back(kTime);
  }
  const auto& names = info_.stateNames;
  info_.coreDimension = static_cast<int>(names.size());
  for (int m = 1; m < static_cast<int>(names.size()); ++m) {
    const std::set<std::string> prefix(names.begin(), names.begin() + m);
    bool closed = true;
    for (int i = 0; i < m && closed; ++i) {
      const auto r = equationReads.find(names[static_cast<std::size_t>(i)]);
      const std::set<std::string> none;
      for (const auto& v : r == equationReads.end() ? none : r->second)
        if (!prefix.count(v)) closed = false;
    }
    if (closed) {
      info_.coreDimension = m;
      break;
    }
  }

  // observables, integrals, measure, section, map coordinates
  std::set<std::string> observableIds(names.begin(), names.end());
  observableIds.insert("t");
  for (const auto& o : spec_.observables) {
    if (o.id.empty() || !observableIds.insert(o.id).second)
      throw InputError(o.value.where + ": the observable '" + o.id +
                       "' is defined twice (state variables and "
                       "t are observables already)");
    if (o.integral) info_.integralNames.push_back(o.id);
  }
  if (spec_.strobePeriod) {
    if (!flow) throw InputError(spec_.strobePeriod->where + ": a map has no time section");
    if (!observableIds.insert("strobe").second)
      throw InputError(spec_.strobePeriod->where + ": the observable 'strobe' is taken");
    info_.section = "strobe";
  }
  info_.hasMeasure = spec_.measure.has_value();
  // a flow that names no section is cut where its first state variable crosses the scene's value (every
  // map needs one: the GUI opens a model with its Poincare map)
  if (flow && info_.section.empty()) info_.section = info_.stateNames.front();
  if (!info_.section.empty() && !observableIds.count(info_.section))
    throw InputError("section: '" + info_.section + "' is not an observable of the model");
  for (const auto& c : info_.mapCoordinates)
    if (!observableIds.count(c))
      throw InputError("map.coordinates: '" + c + "' is not an observable of the model");
  if (spec_.map) {
    if (spec_.map->symbols.size() != info_.mapCoordinates.size())
      throw InputError("map.symbols: one name for each map coordinate");
    std::set<std::string> mapNames; // the map's own names: they may repeat the state's (y for y)
    for (const auto& p : info_.parameters.specs())
      mapNames.insert(p.id);
    for (const auto& s : spec_.map->symbols)
      requireIdentifier(s, "map.symbols." + s, mapNames);
    if (!spec_.map->unknown.empty()) {
      requireIdentifier(spec_.map->unknown, "map.unknown.name", mapNames);
      if (std::find(info_.integralNames.begin(), info_.integralNames.end(), spec_.map->integral) ==
              info_.integralNames.end() &&
          std::none_of(spec_.observables.begin(), spec_.observables.end(),
                       [&](const auto& o) { return o.id == spec_.map->integral; }))
        throw InputError("map.solve.observable: '" + spec_.map->integral +
                         "' is not an observable of the model");
    }
  }
}

const expr::Expression& EquationSystem::parsed(const std::string& where) const {
  for (const auto& [w, e] : parsed_)
    if (w == where) return e;
  throw std::logic_error("no parsed expression at " + where);
}

std::unique_ptr<Model> EquationSystem::create(const ParameterValues& params) const {
  return std::make_unique<EquationModel>(shared_from_this(), params);
}

expr::Program EquationSystem::parametricField() const {
  Graph g;
  const int n = static_cast<int>(info_.stateNames.size());
  const std::vector<int> state = stateInputs(g, n);
  const int time = nonAutonomous_ ? state.back() : g.input(n);
  Scope scope(*this, g, stateNames(*this, g, nullptr, state, time));
  return {g, fieldNodes(*this, g, scope)};
}

std::shared_ptr<const EquationSystem> EquationSystem::build(EquationModelSpec spec) {
  std::shared_ptr<const EquationSystem> system(new EquationSystem(std::move(spec)));
  (void)system->create(ParameterValues(system->info().parameters)); // every expression lowered and checked
  return system;
}

// ---------------------------------------------------------------------------------------------------------
// EquationModel

EquationModel::EquationModel(std::shared_ptr<const EquationSystem> system, const ParameterValues& params)
    : Model(system->info(), params), system_(std::move(system)) {
  const EquationSystem& sys = *system_;
  const EquationModelSpec& spec = sys.spec();
  const auto& names = info_->stateNames;
  const int n = dimension();
  const std::vector<int> state = stateInputs(graph_, n);
  const int timeNode = sys.nonAutonomous() ? state.back() : graph_.input(n);
  Scope scope(sys, graph_, stateNames(sys, graph_, &params, state, timeNode));

  // the field
  field_ = expr::Program(graph_, fieldNodes(sys, graph_, scope));
  if (field_.inputsUsed() > n) throw std::logic_error(info_->id + ": the field reads the time slot");
  const auto index = [&](const std::string& name) {
    return static_cast<int>(std::find(names.begin(), names.end(), name) - names.begin());
  };

  // observables (t and the state first, as every model has them)
  addObservable("t", "time", [](double t, const double*) { return t; });
  for (std::size_t i = 0; i < names.size(); ++i)
    addObservable(names[i],
                  names[i] == kTime && sys.nonAutonomous() ? "time (the autonomous extension)"
                                                           : "state component",
                  [i](double, const double* x) { return x[i]; });
  std::vector<int> integralNodes;
  std::map<std::string, int> observableNodes;
  for (const auto& o : spec.observables) {
    const int node = scope.lower(o.value, 1, 1, "an observable").n[0];
    observableNodes[o.id] = node;
    if (o.integral) integralNodes.push_back(node);
    auto program = std::make_shared<expr::Program>(graph_, std::vector<int>{node});
    const int inputs = n + 1;
    addObservable(o.id, o.description, [program, inputs](double t, const double* x) {
      thread_local std::vector<double> in;
      in.assign(x, x + inputs - 1);
      in.push_back(t);
      double v = 0;
      program->evaluate(in.data(), &v);
      return v;
    });
    observables_.back().angle = o.angle;
    if (spec.map && o.id == spec.map->unknown) unknownObservable_ = static_cast<int>(observables_.size()) - 1;
  }
  integrals_ = expr::Program(graph_, integralNodes);
  if (spec.measure)
    measure_ = expr::Program(graph_, {scope.lower(*spec.measure, 1, 1, "the measure density").n[0]});
  if (spec.strobePeriod) {
    const Value period = scope.lower(*spec.strobePeriod, 1, 1, "the period of the time section");
    if (!graph_.isConstant(period.n[0]) || !(graph_.at(period.n[0]).c > 0))
      throw InputError(spec.strobePeriod->where +
                       ": the period must be a positive constant (of the parameters)");
    const double T = graph_.at(period.n[0]).c;
    const std::size_t time =
        names.size() - 1; // the autonomous extension's time (t when the flow is autonomous)
    const bool clock = sys.nonAutonomous();
    addObservable("strobe", "2 pi t / T: the phase of the forcing (its section is the stroboscopic map)",
                  [T, time, clock](double t, const double* x) {
                    return 2 * std::numbers::pi * (clock ? x[time] : t) / T;
                  });
    observables_.back().angle = true;
  }

  // completion of the state variables a scene leaves out
  for (const auto& [name, text] : spec.completion) {
    const int i = index(name);
    if (i >= n) throw InputError(text.where + ": '" + name + "' is not a state variable");
    completion_.emplace_back(
        i, expr::Program(graph_, {scope.lower(text, 1, 1, "a completed state variable").n[0]}));
  }

  // map points: the state from the symbols, the unknown and the section's value
  if (spec.map) {
    const auto& m = *spec.map;
    const int k = static_cast<int>(m.symbols.size());
    std::map<std::string, Value> base;
    const auto& ps = params.table().specs();
    for (std::size_t i = 0; i < ps.size(); ++i)
      base[ps[i].id] = Value::of(graph_.constant(params.values()[i]));
    for (int i = 0; i < k; ++i)
      base[m.symbols[static_cast<std::size_t>(i)]] = Value::of(graph_.input(i));
    if (!m.unknown.empty()) base[m.unknown] = Value::of(graph_.input(k));
    base["section"] = Value::of(graph_.input(k + 1));
    Scope mapScope(sys, graph_, base);
    std::vector<int> st(static_cast<std::size_t>(n), -1);
    for (const auto& [name, text] : m.state) {
      const int i = index(name);
      if (i >= n) throw InputError(text.where + ": '" + name + "' is not a state variable");
      st[static_cast<std::size_t>(i)] = mapScope.lower(text, 1, 1, "a state variable").n[0];
    }
    for (int i = 0; i < n; ++i)
      if (st[static_cast<std::size_t>(i)] < 0) {
        if (names[static_cast<std::size_t>(i)] != kTime)
          throw InputError("map.state: the state variable '" + names[static_cast<std::size_t>(i)] +
                           "' is not given");
        st[static_cast<std::size_t>(i)] = graph_.constant(0);
      }
    std::vector<int> outputs = st;
    if (!m.unknown.empty()) {
      // the observable evaluated on the completed state, minus the value it must have
      Scope onState(
          sys, graph_,
          stateNames(sys, graph_, &params, st, sys.nonAutonomous() ? st.back() : graph_.constant(0)));
      const auto obs = std::find_if(spec.observables.begin(), spec.observables.end(),
                                    [&](const auto& o) { return o.id == m.integral; });
      const int value = onState.lower(obs->value).n[0];
      const int target = mapScope.lower(m.value, 1, 1, "the value").n[0];
      outputs.push_back(graph_.make(expr::Op::Sub, value, target));
      for (const ExprText* t : {&m.from, &m.to, &m.step}) {
        const Value v = mapScope.lower(*t, 1, 1, "a bound");
        outputs.push_back(v.n[0]);
      }
    }
    map_ = expr::Program(graph_, outputs);
  }

  // the body
  if (spec.view) {
    const auto& v = *spec.view;
    std::vector<int> pose;
    const Value R = scope.lower(v.rotation, 3, 3, "the rotation");
    const Value c = scope.lower(v.position, 3, 1, "the position");
    const Value p = scope.lower(v.contact, 3, 1, "the contact point");
    pose.insert(pose.end(), R.n.begin(), R.n.end());
    pose.insert(pose.end(), c.n.begin(), c.n.end());
    pose.insert(pose.end(), p.n.begin(), p.n.end());
    if (v.normal) {
      const Value n = scope.lower(*v.normal, 3, 1, "the normal");
      pose.insert(pose.end(), n.n.begin(), n.n.end());
      poseHasNormal_ = true;
    }
    pose_ = expr::Program(graph_, pose);
    const auto constant = [&](const std::optional<ExprText>& t, int rows, const char* what, double fallback) {
      std::vector<double> out(static_cast<std::size_t>(rows), fallback);
      if (!t) return out;
      const Value val = scope.lower(*t, rows, 1, what);
      for (int i = 0; i < rows; ++i) {
        const int node = val.n[static_cast<std::size_t>(i)];
        if (!graph_.isConstant(node))
          throw InputError(t->where + ": " + what + " must not depend on the state (only on the parameters)");
        out[static_cast<std::size_t>(i)] = graph_.at(node).c;
      }
      return out;
    };
    const auto geometryOf = [&](const EquationModelSpec::Shape& shape) {
      BodyGeometry g{.shape = shape.shape};
      if (shape.shape == BodyShape::Ball) {
        g.semiAxes = Eigen::Vector3d::Constant(constant(shape.semiAxes, 1, "the radius", 1)[0]);
      } else if (shape.shape == BodyShape::Ellipsoid) {
        const auto a = constant(shape.semiAxes, 3, "the semi-axes", 1);
        g.semiAxes = {a[0], a[1], a[2]};
      } else if (shape.shape == BodyShape::Paraboloid) {
        g.p = constant(shape.p, 1, "p", 1)[0];
        g.q = constant(shape.q, 1, "q", 1)[0];
        g.height = constant(shape.height, 1, "the height", 1)[0];
      }
      const auto centre = constant(shape.centre, 3, "the centre", 0);
      g.centre = {centre[0], centre[1], centre[2]};
      return g;
    };
    geometry_ = geometryOf(v.body);
    if (v.support.shape != BodyShape::None) support_ = geometryOf(v.support);
    if (support_ && support_->shape != BodyShape::Paraboloid && v.support.height) // a bowl: the lower part
      supportCap_ = constant(v.support.height, 1, "the height", 1)[0];
    if (!v.mesh.empty()) mesh_ = BodyMeshFile{v.mesh, constant(v.meshScale, 1, "the mesh's scale", 1)[0]};
    // F of the point (x, y, z) alone, the parameters folded in: a scope of its own
    const auto implicitSurface = [&](const ExprText& F, const char* what) {
      std::map<std::string, Value> point;
      for (int i = 0; i < 3; ++i)
        point[std::string(1, "xyz"[i])] = Value::of(graph_.input(i));
      const auto& specs = info_->parameters.specs();
      for (std::size_t i = 0; i < specs.size(); ++i)
        point[specs[i].id] = Value::of(graph_.constant(params.values()[i]));
      Scope local(sys, graph_, std::move(point));
      return expr::Program(graph_, local.lower(F, 1, 1, what).n);
    };
    if (v.surface) {
      surface_ = implicitSurface(*v.surface, "the surface F");
      surfaceSize_ = constant(v.surfaceSize, 1, "the surface's size", 1)[0];
    }
    if (v.supportSurface) {
      supportSurface_ = implicitSurface(*v.supportSurface, "the support's surface F");
      supportSurfaceSize_ = constant(v.supportSurfaceSize, 1, "the support's size", 1)[0];
    }
  }
}

std::optional<ImplicitSurface> EquationModel::bodySurface() const {
  if (!surface_) return std::nullopt;
  const Eigen::Vector3d centre = geometry_ ? geometry_->centre : Eigen::Vector3d::Zero();
  return ImplicitSurface{[program = *surface_, centre](const Eigen::Vector3d& p) {
                           const Eigen::Vector3d q = p - centre;
                           double F = 0;
                           program.evaluate(q.data(), &F);
                           return F;
                         },
                         surfaceSize_ + centre.norm()};
}

std::optional<ImplicitSurface> EquationModel::supportSurface() const {
  if (!supportSurface_) return std::nullopt;
  return ImplicitSurface{[program = *supportSurface_](const Eigen::Vector3d& p) {
                           double F = 0;
                           program.evaluate(p.data(), &F);
                           return F;
                         },
                         supportSurfaceSize_};
}

namespace {
/// x and t as the programs' inputs.
const double* withTime(const double* x, int n, double t) {
  thread_local std::vector<double> in;
  in.assign(x, x + n);
  in.push_back(t);
  return in.data();
}
} // namespace

namespace {
/// The inputs of this thread's last right-hand side that was not finite at a finite state (a stage inside a
/// step, say), for nonFiniteCause when the step's start is finite.
thread_local std::vector<double> lastNonFinite;
} // namespace

void EquationModel::rhs(const double* x, double* dx) const {
  const int n = dimension();
  field_.evaluate(x, dx); // the field reads the state only (a non-autonomous flow's t is its last component)
  double sum = 0, inputs = 0;
  for (int i = 0; i < n; ++i)
    sum += dx[i], inputs += x[i];
  if (!std::isfinite(sum) && std::isfinite(inputs)) { // where it began
    lastNonFinite.assign(x, x + n);
    lastNonFinite.push_back(0);
  }
}

void EquationModel::jacobian(const double* x, double* jac) const {
  const int n = dimension();
  thread_local std::vector<double> seed, value;
  seed.assign(idx(n * n), 0.0);
  for (int i = 0; i < n; ++i)
    seed[idx(i * n + i)] = 1;
  value.resize(static_cast<std::size_t>(n));
  field_.derivatives(x, seed.data(), n, n, value.data(), jac);
}

void EquationModel::coreJacobian(const double* x, double* jac) const {
  const int n = dimension(), m = info_->coreDimension;
  thread_local std::vector<double> seed, value, full;
  seed.assign(idx(m * m), 0.0);
  for (int i = 0; i < m; ++i)
    seed[idx(i * m + i)] = 1;
  value.resize(static_cast<std::size_t>(n));
  full.resize(idx(n * m));
  field_.derivatives(x, seed.data(), m, m, value.data(), full.data());
  std::copy_n(full.data(), m * m, jac); // the first m outputs' rows
}

void EquationModel::tangentRhs(const double* x, const double* V, int k, double* dx, double* dV) const {
  const int n = dimension(), m = info_->coreDimension;
  thread_local std::vector<double> seed, der;
  seed.resize(idx(m * k));
  for (int c = 0; c < k; ++c) // V holds k columns of m; the seeds are per input slot
    for (int i = 0; i < m; ++i)
      seed[idx(i * k + c)] = V[c * m + i];
  der.resize(idx(n * k));
  field_.derivatives(x, seed.data(), m, k, dx, der.data());
  for (int c = 0; c < k; ++c)
    for (int i = 0; i < m; ++i)
      dV[c * m + i] = der[idx(i * k + c)];
}

void EquationModel::recordField(taylor::Tape& tape, const double* x) const {
  const int n = dimension();
  taylor::Recording recording(tape, n);
  std::vector<taylor::Var> in, reg(field_.registers());
  for (int i = 0; i < n; ++i)
    in.push_back(tape.input(i, x[i]));
  in.emplace_back(0.0); // the time slot of an autonomous flow (unused by its field)
  field_.run<taylor::Var>(in.data(), reg.data());
  for (int i = 0; i < n; ++i)
    tape.setOutput(i, reg[static_cast<std::size_t>(field_.outputs()[static_cast<std::size_t>(i)])]);
}

Eigen::VectorXd EquationModel::integrals(const double* x) const {
  Eigen::VectorXd v(static_cast<Eigen::Index>(integrals_.outputs().size()));
  if (v.size() > 0) integrals_.evaluate(withTime(x, dimension(), 0), v.data());
  return v;
}

double EquationModel::measureDensity(const double* x) const {
  if (measure_.outputs().empty()) return 1.0;
  double v = 1;
  measure_.evaluate(withTime(x, dimension(), 0), &v);
  return v;
}

std::optional<BodyPose> EquationModel::pose(const double* x) const {
  if (pose_.outputs().empty()) return std::nullopt;
  double out[18];
  pose_.evaluate(withTime(x, dimension(), 0), out);
  BodyPose p;
  for (int i = 0; i < 3; ++i)
    for (int j = 0; j < 3; ++j)
      p.rotation(i, j) = out[i * 3 + j];
  p.centre = {out[9], out[10], out[11]};
  p.contact = {out[12], out[13], out[14]};
  if (poseHasNormal_)
    p.supportNormal = Eigen::Vector3d(out[15], out[16], out[17]).normalized();
  else if (support_) { // the surface's normal at the contact, on the body's side
    p.supportNormal = shapeNormal(*support_, p.contact);
    if (p.supportNormal.dot(p.centre - p.contact) < 0) p.supportNormal = -p.supportNormal;
  }
  return p;
}

std::optional<SupportSurface> EquationModel::support() const {
  if (!support_) return std::nullopt;
  // a sphere or ellipsoid with a height is drawn from its lowest point up to that height (a bowl a body
  // inside it is seen in)
  const double pi = std::numbers::pi,
               top = supportCap_ ? std::asin(std::clamp(*supportCap_ / support_->semiAxes[2] - 1, -1.0, 1.0))
                                 : pi / 2,
               upTo = (top + pi / 2) / pi;
  return SupportSurface{[g = *support_, upTo](double u, double v) { return shapePoint(g, u, v * upTo); }};
}

Eigen::VectorXd EquationModel::stateFromNamed(const std::map<std::string, double>& named,
                                              const std::string& context) const {
  const int n = dimension();
  Eigen::VectorXd x = Eigen::VectorXd::Zero(n);
  assignNamed(named, context, x);
  std::vector<bool> given(static_cast<std::size_t>(n), false);
  for (int i = 0; i < n; ++i)
    given[static_cast<std::size_t>(i)] = named.count(info_->stateNames[static_cast<std::size_t>(i)]) > 0;
  for (const auto& [i, program] : completion_) {
    if (given[static_cast<std::size_t>(i)]) continue;
    program.evaluate(withTime(x.data(), n, 0), &x[i]);
    given[static_cast<std::size_t>(i)] = true;
  }
  for (int i = 0; i < n; ++i) {
    const auto& name = info_->stateNames[static_cast<std::size_t>(i)];
    if (!given[static_cast<std::size_t>(i)] && !(name == kTime && system_->nonAutonomous()))
      throw InputError(context + ": missing state component '" + name + "'");
  }
  if (!std::isfinite(x.sum())) throw InputError(context + ": the completed state is not finite");
  return x;
}

std::vector<double> EquationModel::completionRoots(const std::vector<double>& point, double section,
                                                   Eigen::VectorXd* state, int root) const {
  const int n = dimension(), k = static_cast<int>(point.size());
  std::vector<double> in(point);
  in.push_back(0); // the unknown
  in.push_back(section);
  std::vector<double> out(map_.outputs().size());
  if (system_->spec().map->unknown.empty()) {
    map_.evaluate(in.data(), out.data());
    if (state) *state = Eigen::Map<const Eigen::VectorXd>(out.data(), n);
    return {};
  }
  map_.evaluate(in.data(), out.data());
  const double from = out[idx(n + 1)], to = out[idx(n + 2)], step = out[idx(n + 3)];
  const auto residual = [&](double u) {
    in[static_cast<std::size_t>(k)] = u;
    map_.evaluate(in.data(), out.data());
    return out[static_cast<std::size_t>(n)];
  };
  std::vector<double> roots;
  if (std::isfinite(from) && std::isfinite(to) && step > 0)
    roots = findRoots(residual, from, to, step, system_->spec().map->accuracy);
  if (state && root >= 1 && root <= static_cast<int>(roots.size())) {
    residual(roots[static_cast<std::size_t>(root - 1)]);
    *state = Eigen::Map<const Eigen::VectorXd>(out.data(), n);
  }
  return roots;
}

Eigen::VectorXd EquationModel::stateFromMap(const std::vector<double>& point, const MapPointSpec& spec,
                                            const std::string& context) const {
  if (!system_->spec().map) return Model::stateFromMap(point, spec, context);
  const auto& coords = info_->mapCoordinates;
  if (point.size() != coords.size()) {
    std::string list;
    for (const auto& c : coords)
      list += (list.empty() ? "" : ", ") + c;
    throw InputError(context + ": " + info_->id + " map points are (" + list + ")");
  }
  Eigen::VectorXd x;
  const auto roots = completionRoots(point, spec.sectionValue, &x, spec.root);
  if (x.size() == 0 || !std::isfinite(x.sum())) {
    std::ostringstream os;
    os << context << ": no state at (";
    for (std::size_t i = 0; i < point.size(); ++i)
      os << (i ? ", " : "") << point[i];
    os << ")";
    if (roots.empty())
      os << " (the point lies outside the region of allowed motion)";
    else
      os << " with root " << spec.root << " (there are " << roots.size() << ")";
    throw InputError(os.str());
  }
  return x;
}

int EquationModel::sheetOf(const Eigen::VectorXd& x, const MapPointSpec& spec) const {
  if (unknownObservable_ < 0) return 1;
  std::vector<double> point;
  for (const auto& c : info_->mapCoordinates)
    point.push_back(observables_[static_cast<std::size_t>(findObservable(c))].value(0, x.data()));
  const double u = observables_[static_cast<std::size_t>(unknownObservable_)].value(0, x.data());
  const auto roots = completionRoots(point, spec.sectionValue, nullptr, 0);
  int best = 1;
  for (std::size_t i = 1; i < roots.size(); ++i)
    if (std::abs(roots[i] - u) < std::abs(roots[static_cast<std::size_t>(best - 1)] - u))
      best = static_cast<int>(i) + 1;
  return best;
}

std::string EquationModel::nonFiniteCause(const double* x) const {
  std::string cause = field_.firstNonFinite(withTime(x, dimension(), 0), graph_.origins());
  if (cause.empty() && lastNonFinite.size() == static_cast<std::size_t>(dimension()) + 1)
    cause = field_.firstNonFinite(lastNonFinite.data(), graph_.origins());
  lastNonFinite.clear();
  return cause.empty() ? cause : info_->id + ": " + cause;
}

} // namespace rv
