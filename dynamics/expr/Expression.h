// Expression.h -- the expression language of model files: the text of one expression parsed into a tree.
// Grammar (precedence from low to high; sums and products are n-ary nodes, so a long generated equation
// makes a wide tree, not a deep one):
//   expr    := term (('+' | '-') term)*
//   term    := unary (('*' | '/') unary)*
//   unary   := '-' unary | '+' unary | power
//   power   := postfix ('^' unary)?               right-associative: a^b^c = a^(b^c); -x^2 = -(x^2)
//   postfix := primary ('[' expr (',' expr)? ']')*  components, 1-based: v[1], A[2,3]
//   primary := NUMBER | NAME | NAME '(' args ')' | '(' expr ')' | '[' expr (',' expr)* ']'
// Nothing here knows what a name means: Lowering.h resolves names and types.
#pragma once
#include "dynamics/core/Errors.h"

#include <map>
#include <string>
#include <vector>

namespace rv::expr {

/// A parse or type error at a column (1-based) of an expression's text.
struct ExprError : InputError {
  ExprError(int column, const std::string& message)
      : InputError("column " + std::to_string(column) + ": " + message), column(column) {}
  int column;
};

/// One node of a parsed expression. Children are indices into Expression::nodes.
struct Node {
  enum class Kind { Number, Name, Call, Negate, Sum, Product, Power, Index, List };
  Kind kind;
  int column = 1;             ///< where it starts in the text (1-based)
  double number = 0;          ///< Number
  std::string name;           ///< Name, Call
  std::vector<int> children;  ///< Call: arguments; Sum/Product: operands; Power: base, exponent; Index:
                              ///< value then one or two indices; List: elements; Negate: operand
  std::vector<bool> inverted; ///< Sum: operand subtracted; Product: operand divided
};

/// A parsed expression: its nodes, the root last.
struct Expression {
  std::string text;
  std::vector<Node> nodes;
  int root = -1;
  const Node& at(int i) const { return nodes[static_cast<std::size_t>(i)]; }
};

/// Longest expression text accepted, and deepest nesting of parentheses, calls and brackets.
constexpr std::size_t kMaxExpressionLength = 1 << 20;
constexpr int kMaxNesting = 200;

/// Parses one expression; throws ExprError naming the column and what is wrong.
Expression parse(const std::string& text);

/// Names used by an expression (variables, not called functions), in order of first use.
std::vector<std::string> namesUsed(const Expression& e);

/// The expression's text with each name in `replace` (a variable, not a called function) written as its
/// replacement in parentheses: an expression of x, y, z evaluated at a point p is renamed(F, {{"x", "p[1]"},
/// ...}) (a rolling body's implicit surface, scenes/RollingModel.h).
std::string renamed(const Expression& e, const std::map<std::string, std::string>& replace);

/// The known name nearest to `name` by edit distance (for "did you mean"), or "" when none is close.
std::string nearestName(const std::string& name, const std::vector<std::string>& known);

} // namespace rv::expr
