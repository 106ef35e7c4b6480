#include "dynamics/expr/Lowering.h"

#include "dynamics/expr/Derivative.h"

#include <algorithm>
#include <cmath>
#include <map>
#include <numbers>

namespace rv::expr {
namespace {

constexpr std::size_t idx(int i) {
  return Value::idx(i);
}

const std::map<std::string, Op>& scalarFunctions() {
  static const std::map<std::string, Op> f{
      {"sin", Op::Sin},   {"cos", Op::Cos},   {"tan", Op::Tan},   {"asin", Op::Asin}, {"acos", Op::Acos},
      {"atan", Op::Atan}, {"sinh", Op::Sinh}, {"cosh", Op::Cosh}, {"tanh", Op::Tanh}, {"exp", Op::Exp},
      {"log", Op::Log},   {"sqrt", Op::Sqrt}, {"abs", Op::Abs},   {"sign", Op::Sign}};
  return f;
}

} // namespace

std::string shapeName(const Value& v) {
  if (v.scalar()) return "a scalar";
  if (v.vector()) return "a " + std::to_string(v.rows) + "-vector";
  return "a " + std::to_string(v.rows) + "x" + std::to_string(v.cols) + " matrix";
}

const std::vector<std::string>& functionNames() {
  static const std::vector<std::string> names = [] {
    std::vector<std::string> v;
    for (const auto& [name, op] : scalarFunctions())
      v.push_back(name);
    for (const char* n :
         {"atan2",    "pow", "min",   "max",        "vec",       "rows",    "cols",      "diag",
          "identity", "dot", "cross", "norm",       "normalize", "outer",   "transpose", "inverse",
          "solve",    "det", "trace", "derivative", "gradient",  "jacobian"})
      v.emplace_back(n);
    return v;
  }();
  return names;
}

Value Lowering::lower(const Expression& e) {
  return node(e, e.root);
}

Value Lowering::elementwise(const Value& v, Op op) {
  Value r = v;
  for (int& x : r.n)
    x = g_.make(op, x);
  return r;
}

Value Lowering::add(const Value& a, const Value& b, bool subtract, int column) {
  if (a.rows != b.rows || a.cols != b.cols)
    throw ExprError(column, std::string("cannot ") + (subtract ? "subtract " : "add ") + shapeName(b) +
                                (subtract ? " from " : " to ") + shapeName(a));
  Value r = a;
  for (std::size_t i = 0; i < r.n.size(); ++i)
    r.n[i] = g_.make(subtract ? Op::Sub : Op::Add, a.n[i], b.n[i]);
  return r;
}

Value Lowering::multiply(const Value& a, const Value& b, int column) {
  if (a.scalar() || b.scalar()) {
    const Value& s = a.scalar() ? a : b;
    Value r = a.scalar() ? b : a;
    for (int& x : r.n)
      x = g_.make(Op::Mul, s.n[0], x);
    return r;
  }
  if (a.cols == 1 && b.cols == 1)
    throw ExprError(column, "'*' of two vectors is ambiguous: write dot(u, v) or cross(u, v)");
  if (a.cols != b.rows)
    throw ExprError(column, "cannot multiply " + shapeName(a) + " by " + shapeName(b) + " (sizes disagree)");
  Value r{a.rows, b.cols, {}};
  for (int i = 0; i < a.rows; ++i)
    for (int j = 0; j < b.cols; ++j) {
      int sum = g_.constant(0);
      for (int k = 0; k < a.cols; ++k)
        sum = g_.make(Op::Add, sum, g_.make(Op::Mul, a.at(i, k), b.at(k, j)));
      r.n.push_back(sum);
    }
  return r;
}

Value Lowering::divide(const Value& a, const Value& b, int column) {
  if (!b.scalar()) throw ExprError(column, "cannot divide by " + shapeName(b) + " (only by a scalar)");
  Value r = a;
  for (int& x : r.n)
    x = g_.make(Op::Div, x, b.n[0]);
  return r;
}

int Lowering::constantIndex(const Value& v, int limit, int column, const char* what) {
  if (!v.scalar() || !g_.isConstant(v.n[0]))
    throw ExprError(column, std::string("the ") + what + " index must be a constant number");
  const double x = g_.at(v.n[0]).c;
  if (x != std::floor(x) || x < 1 || x > limit)
    throw ExprError(column, std::string("the ") + what + " index must be a whole number from 1 to " +
                                std::to_string(limit));
  return static_cast<int>(x) - 1;
}

int Lowering::determinant(const Value& m) {
  const auto mul = [&](int a, int b) { return g_.make(Op::Mul, a, b); };
  const auto sub = [&](int a, int b) { return g_.make(Op::Sub, a, b); };
  if (m.rows == 1) return m.n[0];
  if (m.rows == 2) return sub(mul(m.at(0, 0), m.at(1, 1)), mul(m.at(0, 1), m.at(1, 0)));
  int det = g_.constant(0);
  for (int j = 0; j < 3; ++j) { // expansion along the first row
    const int minor =
        sub(mul(m.at(1, (j + 1) % 3), m.at(2, (j + 2) % 3)), mul(m.at(1, (j + 2) % 3), m.at(2, (j + 1) % 3)));
    det = g_.make(Op::Add, det, mul(m.at(0, j), minor));
  }
  return det;
}

Value Lowering::inverse(const Value& m, int column) {
  if (m.rows != m.cols || m.rows > 3)
    throw ExprError(column, "inverse and solve take a square matrix of size up to 3, got " + shapeName(m));
  const int det = determinant(m);
  const auto mul = [&](int a, int b) { return g_.make(Op::Mul, a, b); };
  const auto sub = [&](int a, int b) { return g_.make(Op::Sub, a, b); };
  Value r{m.rows, m.cols, std::vector<int>(m.n.size())};
  const auto set = [&](int i, int j, int v) { r.n[idx(i * r.cols + j)] = g_.make(Op::Div, v, det); };
  if (m.rows == 1) {
    set(0, 0, g_.constant(1));
  } else if (m.rows == 2) {
    set(0, 0, m.at(1, 1));
    set(0, 1, g_.make(Op::Neg, m.at(0, 1)));
    set(1, 0, g_.make(Op::Neg, m.at(1, 0)));
    set(1, 1, m.at(0, 0));
  } else {
    for (int i = 0; i < 3; ++i) // the adjugate: cofactor (j, i) at (i, j)
      for (int j = 0; j < 3; ++j) {
        const int a = (j + 1) % 3, b = (j + 2) % 3, c = (i + 1) % 3, d = (i + 2) % 3;
        set(i, j, sub(mul(m.at(a, c), m.at(b, d)), mul(m.at(a, d), m.at(b, c))));
      }
  }
  return r;
}

Value Lowering::call(const Expression& e, const Node& n) {
  std::vector<Value> args;
  args.reserve(n.children.size());
  for (int c : n.children)
    args.push_back(node(e, c));
  const auto argc = [&](std::size_t count) {
    if (args.size() != count)
      throw ExprError(n.column, "'" + n.name + "' takes " + std::to_string(count) + " argument" +
                                    (count == 1 ? "" : "s") + ", got " + std::to_string(args.size()));
  };
  const auto need = [&](std::size_t i, bool ok, const char* what) {
    if (!ok)
      throw ExprError(e.at(n.children[i]).column, "argument " + std::to_string(i + 1) + " of '" + n.name +
                                                      "' must be " + what + ", got " + shapeName(args[i]));
  };
  const auto isVector = [](const Value& v) { return v.cols == 1; };
  const auto dot = [&](const Value& a, const Value& b) {
    int s = g_.constant(0);
    for (std::size_t i = 0; i < a.n.size(); ++i)
      s = g_.make(Op::Add, s, g_.make(Op::Mul, a.n[i], b.n[i]));
    return s;
  };
  const auto sameVectors = [&]() {
    argc(2);
    need(0, isVector(args[0]), "a vector");
    need(1, isVector(args[1]) && args[1].rows == args[0].rows, "a vector of the first one's size");
  };
  if (const auto f = scalarFunctions().find(n.name); f != scalarFunctions().end()) {
    argc(1);
    need(0, args[0].scalar(), "a scalar");
    return elementwise(args[0], f->second);
  }
  if (n.name == "atan2" || n.name == "pow") {
    argc(2);
    need(0, args[0].scalar(), "a scalar");
    need(1, args[1].scalar(), "a scalar");
    return Value::of(g_.make(n.name == "pow" ? Op::Pow : Op::Atan2, args[0].n[0], args[1].n[0]));
  }
  if (n.name == "min" || n.name == "max") {
    if (args.size() < 2) throw ExprError(n.column, "'" + n.name + "' takes two or more arguments");
    int r = -1;
    for (std::size_t i = 0; i < args.size(); ++i) {
      need(i, args[i].scalar(), "a scalar");
      r = i == 0 ? args[i].n[0] : g_.make(n.name == "min" ? Op::Min : Op::Max, r, args[i].n[0]);
    }
    return Value::of(r);
  }
  if (n.name == "vec") {
    if (args.empty()) throw ExprError(n.column, "'vec' takes its components");
    Value r{static_cast<int>(args.size()), 1, {}};
    for (std::size_t i = 0; i < args.size(); ++i) {
      need(i, args[i].scalar(), "a scalar");
      r.n.push_back(args[i].n[0]);
    }
    return r;
  }
  if (n.name == "rows" || n.name == "cols") {
    if (args.size() < 2) throw ExprError(n.column, "'" + n.name + "' takes two or more vectors");
    const int size = args[0].rows;
    for (std::size_t i = 0; i < args.size(); ++i)
      need(i, isVector(args[i]) && args[i].rows == size && size > 1, "a vector of the first one's size");
    const int count = static_cast<int>(args.size());
    Value r{n.name == "rows" ? count : size, n.name == "rows" ? size : count, {}};
    for (int i = 0; i < r.rows; ++i)
      for (int j = 0; j < r.cols; ++j)
        r.n.push_back(n.name == "rows" ? args[static_cast<std::size_t>(i)].n[static_cast<std::size_t>(j)]
                                       : args[static_cast<std::size_t>(j)].n[static_cast<std::size_t>(i)]);
    return r;
  }
  if (n.name == "diag") {
    std::vector<int> d;
    if (args.size() == 1) {
      need(0, args[0].vector(), "a vector (or give the diagonal's entries)");
      d = args[0].n;
    } else {
      for (std::size_t i = 0; i < args.size(); ++i) {
        need(i, args[i].scalar(), "a scalar");
        d.push_back(args[i].n[0]);
      }
    }
    if (d.size() < 2) throw ExprError(n.column, "'diag' takes a vector or two or more scalars");
    const int size = static_cast<int>(d.size());
    Value r{size, size, std::vector<int>(d.size() * d.size(), g_.constant(0))};
    for (int i = 0; i < size; ++i)
      r.n[idx(i * size + i)] = d[idx(i)];
    return r;
  }
  if (n.name == "identity") {
    int size = 3;
    if (args.size() == 1)
      size = constantIndex(args[0], 64, e.at(n.children[0]).column, "size") + 1;
    else if (!args.empty())
      argc(1);
    if (size < 2) throw ExprError(n.column, "identity(n) needs n >= 2");
    Value r{size, size, std::vector<int>(static_cast<std::size_t>(size * size), g_.constant(0))};
    for (int i = 0; i < size; ++i)
      r.n[idx(i * size + i)] = g_.constant(1);
    return r;
  }
  if (n.name == "dot") {
    sameVectors();
    return Value::of(dot(args[0], args[1]));
  }
  if (n.name == "cross") {
    argc(2);
    need(0, isVector(args[0]) && args[0].rows == 3, "a 3-vector");
    need(1, isVector(args[1]) && args[1].rows == 3, "a 3-vector");
    const auto& a = args[0].n;
    const auto& b = args[1].n;
    Value r{3, 1, {}};
    for (int i = 0; i < 3; ++i) {
      const auto j = static_cast<std::size_t>((i + 1) % 3), k = static_cast<std::size_t>((i + 2) % 3);
      r.n.push_back(g_.make(Op::Sub, g_.make(Op::Mul, a[j], b[k]), g_.make(Op::Mul, a[k], b[j])));
    }
    return r;
  }
  if (n.name == "norm" || n.name == "normalize") {
    argc(1);
    need(0, isVector(args[0]), "a vector");
    const int norm = g_.make(Op::Sqrt, dot(args[0], args[0]));
    if (n.name == "norm") return Value::of(norm);
    return divide(args[0], Value::of(norm), n.column);
  }
  if (n.name == "outer") {
    sameVectors();
    Value r{args[0].rows, args[0].rows, {}};
    for (int a : args[0].n)
      for (int b : args[1].n)
        r.n.push_back(g_.make(Op::Mul, a, b));
    return r;
  }
  if (n.name == "transpose") {
    argc(1);
    const Value& m = args[0];
    Value r{m.cols, m.rows, {}};
    for (int i = 0; i < r.rows; ++i)
      for (int j = 0; j < r.cols; ++j)
        r.n.push_back(m.at(j, i));
    return r;
  }
  if (n.name == "inverse") {
    argc(1);
    return inverse(args[0], e.at(n.children[0]).column);
  }
  if (n.name == "solve") { // A x = b by the adjugate: exact derivatives through the same operations
    argc(2);
    need(1, isVector(args[1]) && args[1].rows == args[0].rows, "a vector of the matrix's size");
    return multiply(inverse(args[0], e.at(n.children[0]).column), args[1], n.column);
  }
  if (n.name == "det" || n.name == "trace") {
    argc(1);
    need(0, args[0].matrix() && args[0].rows == args[0].cols && args[0].rows <= 3,
         "a square matrix of size up to 3");
    if (n.name == "det") return Value::of(determinant(args[0]));
    int s = g_.constant(0);
    for (int i = 0; i < args[0].rows; ++i)
      s = g_.make(Op::Add, s, args[0].at(i, i));
    return Value::of(s);
  }
  if (n.name == "derivative" || n.name == "gradient" || n.name == "jacobian") {
    // exact derivatives through the graph (Derivative.h): derivative(f, x, v) is f's rate when x moves at
    // the rate v; gradient(f, x) and jacobian(f, x) take x's components one by one
    const bool along = n.name == "derivative";
    const auto derive = [&](const std::vector<int>& outputs, const std::vector<std::pair<int, int>>& seeds) {
      try {
        return directionalDerivative(g_, outputs, seeds);
      } catch (const ExprError&) {
        throw;
      } catch (const InputError& e) {
        throw ExprError(n.column, e.what());
      }
    };
    argc(along ? 3 : 2);
    const Value& x = args[1];
    for (std::size_t i = 0; i < x.n.size(); ++i)
      need(1, !g_.isConstant(x.n[i]) && std::count(x.n.begin(), x.n.end(), x.n[i]) == 1,
           "variables (state components or expressions of them, each once), not constants");
    if (along) {
      need(2, args[2].rows == x.rows && args[2].cols == x.cols, "the shape of argument 2");
      std::vector<std::pair<int, int>> seeds;
      for (std::size_t i = 0; i < x.n.size(); ++i)
        seeds.emplace_back(x.n[i], args[2].n[i]);
      Value r = args[0];
      r.n = derive(args[0].n, seeds);
      return r;
    }
    const bool gradient = n.name == "gradient";
    need(0, gradient ? args[0].scalar() : isVector(args[0]), gradient ? "a scalar" : "a vector");
    need(1, isVector(x), "a vector");
    const int rows = gradient ? x.rows : args[0].rows, cols = gradient ? 1 : x.rows;
    Value r{rows, cols, std::vector<int>(idx(rows * cols))};
    for (int j = 0; j < x.rows; ++j) {
      const std::vector<int> d = derive(args[0].n, {{x.n[idx(j)], g_.constant(1)}});
      if (gradient)
        r.n[idx(j)] = d[0];
      else
        for (int i = 0; i < rows; ++i)
          r.n[idx(i * cols + j)] = d[idx(i)];
    }
    return r;
  }
  const std::string near = nearestName(n.name, functionNames());
  throw ExprError(n.column, "unknown function '" + n.name + "'" +
                                (near.empty() ? "" : " (did you mean '" + near + "'?)"));
}

Value Lowering::node(const Expression& e, int i) {
  const Node& n = e.at(i);
  switch (n.kind) {
  case Node::Kind::Number:
    return Value::of(g_.constant(n.number));
  case Node::Kind::Name: {
    if (auto v = resolve_(n.name, n.column)) return *v;
    if (n.name == "pi") return Value::of(g_.constant(std::numbers::pi));
    std::vector<std::string> known = known_;
    known.emplace_back("pi");
    const std::string near = nearestName(n.name, known);
    const bool function =
        std::find(functionNames().begin(), functionNames().end(), n.name) != functionNames().end();
    throw ExprError(n.column, "unknown name '" + n.name + "'" +
                                  (function       ? " (it is a function: write " + n.name + "(...))"
                                   : near.empty() ? ""
                                                  : " (did you mean '" + near + "'?)"));
  }
  case Node::Kind::Call:
    return call(e, n);
  case Node::Kind::Negate:
    return elementwise(node(e, n.children[0]), Op::Neg);
  case Node::Kind::Sum: {
    Value r = node(e, n.children[0]);
    if (n.inverted[0]) r = elementwise(r, Op::Neg);
    for (std::size_t k = 1; k < n.children.size(); ++k)
      r = add(r, node(e, n.children[k]), n.inverted[k], e.at(n.children[k]).column);
    return r;
  }
  case Node::Kind::Product: {
    Value r = node(e, n.children[0]);
    for (std::size_t k = 1; k < n.children.size(); ++k) {
      const Value b = node(e, n.children[k]);
      const int column = e.at(n.children[k]).column;
      r = n.inverted[k] ? divide(r, b, column) : multiply(r, b, column);
    }
    return r;
  }
  case Node::Kind::Power: {
    const Value a = node(e, n.children[0]), b = node(e, n.children[1]);
    if (!a.scalar()) throw ExprError(n.column, "'^' takes a scalar base, got " + shapeName(a));
    if (!b.scalar())
      throw ExprError(e.at(n.children[1]).column, "'^' takes a scalar exponent, got " + shapeName(b));
    return Value::of(g_.make(Op::Pow, a.n[0], b.n[0]));
  }
  case Node::Kind::Index: {
    const Value v = node(e, n.children[0]);
    if (v.scalar()) throw ExprError(n.column, "a scalar has no components");
    const int row = constantIndex(node(e, n.children[1]), v.rows, e.at(n.children[1]).column, "row");
    if (n.children.size() == 2) {
      if (v.cols == 1) return Value::of(v.n[static_cast<std::size_t>(row)]);
      Value r{v.cols, 1, {}};
      for (int j = 0; j < v.cols; ++j)
        r.n.push_back(v.at(row, j));
      return r;
    }
    if (v.cols == 1) throw ExprError(n.column, "a vector takes one index");
    const int col = constantIndex(node(e, n.children[2]), v.cols, e.at(n.children[2]).column, "column");
    return Value::of(v.at(row, col));
  }
  case Node::Kind::List: {
    std::vector<Value> items;
    for (int c : n.children)
      items.push_back(node(e, c));
    if (items[0].scalar()) {
      Value r{static_cast<int>(items.size()), 1, {}};
      for (std::size_t k = 0; k < items.size(); ++k) {
        if (!items[k].scalar())
          throw ExprError(e.at(n.children[k]).column, "a list of scalars cannot hold " + shapeName(items[k]));
        r.n.push_back(items[k].n[0]);
      }
      if (r.rows < 2) throw ExprError(n.column, "a vector has two or more components");
      return r;
    }
    const int width = items[0].rows;
    Value r{static_cast<int>(items.size()), width, {}};
    for (std::size_t k = 0; k < items.size(); ++k) {
      if (!(items[k].cols == 1 && items[k].rows == width))
        throw ExprError(e.at(n.children[k]).column,
                        "the rows of a matrix must be vectors of one size, got " + shapeName(items[k]));
      r.n.insert(r.n.end(), items[k].n.begin(), items[k].n.end());
    }
    if (r.rows < 2) throw ExprError(n.column, "a matrix has two or more rows");
    return r;
  }
  }
  throw ExprError(n.column, "unknown expression");
}

} // namespace rv::expr
