// Lowering.h -- a parsed expression given meaning: names resolved, shapes checked (scalars, vectors,
// matrices), and every vector and matrix operation written out in scalars on a Graph. The functions of
// the language are listed once here (functionNames) for help texts and "did you mean".
#pragma once
#include "dynamics/expr/Expression.h"
#include "dynamics/expr/Graph.h"

#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace rv::expr {

/// A value of the language: a rows x cols array of graph nodes, row-major (a scalar is 1 x 1, a vector n x
/// 1).
struct Value {
  int rows = 1, cols = 1;
  std::vector<int> n;
  bool scalar() const { return rows == 1 && cols == 1; }
  bool vector() const { return cols == 1 && rows > 1; }
  bool matrix() const { return cols > 1; }
  int at(int i, int j) const { return n[idx(i * cols + j)]; }
  /// An index as the containers take it (from int arithmetic that cannot be negative here).
  static constexpr std::size_t idx(int i) { return static_cast<std::size_t>(i); }
  static Value of(int node) { return {1, 1, {node}}; }
};

/// "a scalar", "a 3-vector", "a 3x3 matrix".
std::string shapeName(const Value& v);

/// The functions of the language, for messages and documentation.
const std::vector<std::string>& functionNames();

/// Turns expressions into graph nodes. `resolve` gives the value of a name (a state variable, a parameter,
/// a definition, ...) or nothing when the name is unknown; `known` lists the names for "did you mean".
class Lowering {
public:
  using Resolver = std::function<std::optional<Value>(const std::string& name, int column)>;
  Lowering(Graph& graph, Resolver resolve, std::vector<std::string> known)
      : g_(graph), resolve_(std::move(resolve)), known_(std::move(known)) {}
  /// The value of a parsed expression; throws ExprError at the column of what is wrong.
  Value lower(const Expression& e);

private:
  Value node(const Expression& e, int i);
  Value call(const Expression& e, const Node& n);
  Value elementwise(const Value& v, Op op);
  Value add(const Value& a, const Value& b, bool subtract, int column);
  Value multiply(const Value& a, const Value& b, int column);
  Value divide(const Value& a, const Value& b, int column);
  int constantIndex(const Value& v, int limit, int column, const char* what);
  Value inverse(const Value& m, int column);
  int determinant(const Value& m);

  Graph& g_;
  Resolver resolve_;
  std::vector<std::string> known_;
};

} // namespace rv::expr
