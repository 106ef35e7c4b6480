#include "dynamics/expr/Expression.h"

#include <algorithm>
#include <cctype>
#include <cerrno>
#include <cmath>
#include <cstdlib>

namespace rv::expr {
namespace {

bool nameStart(char c) {
  return std::isalpha(static_cast<unsigned char>(c)) != 0 || c == '_';
}
bool nameChar(char c) {
  return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_';
}

std::string shown(char c) {
  if (std::isprint(static_cast<unsigned char>(c)) != 0) return std::string("'") + c + "'";
  return "a character of code " + std::to_string(static_cast<unsigned char>(c));
}

// Recursive descent over the grammar in the header; `depth_` bounds the recursion.
class Parser {
public:
  explicit Parser(const std::string& text) : s_(text) { e_.text = text; }

  Expression run() {
    if (s_.size() > kMaxExpressionLength)
      throw ExprError(1, "the expression is " + std::to_string(s_.size()) + " characters long (at most " +
                             std::to_string(kMaxExpressionLength) + ")");
    skip();
    if (p_ == s_.size()) throw ExprError(1, "empty expression");
    e_.root = expr();
    skip();
    if (p_ != s_.size()) {
      if (s_[p_] == ')') throw ExprError(col(), "unbalanced ')': no '(' before it");
      throw ExprError(col(), "unexpected " + shown(s_[p_]) + " after a complete expression");
    }
    return std::move(e_);
  }

private:
  int col() const { return static_cast<int>(p_) + 1; }
  void skip() {
    while (p_ < s_.size() && std::isspace(static_cast<unsigned char>(s_[p_])) != 0)
      ++p_;
  }
  bool take(char c) {
    skip();
    if (p_ < s_.size() && s_[p_] == c) {
      ++p_;
      return true;
    }
    return false;
  }
  int add(Node n) {
    e_.nodes.push_back(std::move(n));
    return static_cast<int>(e_.nodes.size()) - 1;
  }
  struct Deeper { // one level of nesting
    Deeper(Parser& p, int column) : p_(p) {
      if (++p_.depth_ > kMaxNesting)
        throw ExprError(column, "nested more than " + std::to_string(kMaxNesting) + " levels deep");
    }
    ~Deeper() { --p_.depth_; }
    Deeper(const Deeper&) = delete;
    Deeper& operator=(const Deeper&) = delete;
    Parser& p_;
  };

  int expr() {
    skip();
    const int c = col();
    int first = term();
    Node sum{.kind = Node::Kind::Sum, .column = c};
    sum.children.push_back(first);
    sum.inverted.push_back(false);
    for (;;) {
      skip();
      if (p_ < s_.size() && (s_[p_] == '+' || s_[p_] == '-')) {
        const bool minus = s_[p_++] == '-';
        sum.children.push_back(term());
        sum.inverted.push_back(minus);
      } else {
        break;
      }
    }
    return sum.children.size() == 1 ? first : add(std::move(sum));
  }

  int term() {
    skip();
    const int c = col();
    int first = unary();
    Node product{.kind = Node::Kind::Product, .column = c};
    product.children.push_back(first);
    product.inverted.push_back(false);
    for (;;) {
      skip();
      if (p_ < s_.size() && (s_[p_] == '*' || s_[p_] == '/')) {
        const bool divide = s_[p_++] == '/';
        product.children.push_back(unary());
        product.inverted.push_back(divide);
      } else {
        break;
      }
    }
    return product.children.size() == 1 ? first : add(std::move(product));
  }

  int unary() {
    skip();
    const int c = col();
    if (take('-')) {
      Deeper d(*this, c);
      const int operand = unary();
      return add({.kind = Node::Kind::Negate, .column = c, .children = {operand}});
    }
    if (take('+')) {
      Deeper d(*this, c);
      return unary();
    }
    return power();
  }

  int power() {
    skip();
    const int c = col();
    const int base = postfix();
    if (!take('^')) return base;
    Deeper d(*this, c);
    const int exponent = unary();
    return add({.kind = Node::Kind::Power, .column = c, .children = {base, exponent}});
  }

  int postfix() {
    int value = primary();
    for (;;) {
      skip();
      const int c = col();
      if (!take('[')) return value;
      Deeper d(*this, c);
      Node index{.kind = Node::Kind::Index, .column = c, .children = {value, expr()}};
      if (take(',')) index.children.push_back(expr());
      if (!take(']')) throw ExprError(col(), "expected ']' closing the '[' at column " + std::to_string(c));
      value = add(std::move(index));
    }
  }

  int primary() {
    skip();
    const int c = col();
    if (p_ == s_.size()) throw ExprError(c, "the expression ends where a value is expected");
    const char ch = s_[p_];
    if (std::isdigit(static_cast<unsigned char>(ch)) != 0 || ch == '.') return number();
    if (nameStart(ch)) {
      const std::size_t b = p_;
      while (p_ < s_.size() && nameChar(s_[p_]))
        ++p_;
      std::string name = s_.substr(b, p_ - b);
      skip();
      if (p_ < s_.size() && s_[p_] == '(') {
        ++p_;
        Deeper d(*this, c);
        Node call{.kind = Node::Kind::Call, .column = c, .name = std::move(name)};
        if (!take(')')) {
          do
            call.children.push_back(expr());
          while (take(','));
          if (!take(')'))
            throw ExprError(col(), "expected ',' or ')' in the arguments of '" + call.name + "' (column " +
                                       std::to_string(c) + ")");
        }
        return add(std::move(call));
      }
      return add({.kind = Node::Kind::Name, .column = c, .name = std::move(name)});
    }
    if (ch == '(') {
      ++p_;
      Deeper d(*this, c);
      const int inner = expr();
      if (!take(')')) throw ExprError(col(), "expected ')' closing the '(' at column " + std::to_string(c));
      return inner;
    }
    if (ch == '[') {
      ++p_;
      Deeper d(*this, c);
      Node list{.kind = Node::Kind::List, .column = c};
      do
        list.children.push_back(expr());
      while (take(','));
      if (!take(']'))
        throw ExprError(col(), "expected ',' or ']' in the list opened at column " + std::to_string(c));
      return add(std::move(list));
    }
    if (ch == ')') throw ExprError(c, "unexpected ')': a value is missing before it");
    throw ExprError(c, "unexpected " + shown(ch) + " where a value is expected");
  }

  int number() {
    const int c = col();
    const std::size_t b = p_;
    while (p_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p_])) != 0)
      ++p_;
    if (p_ < s_.size() && s_[p_] == '.') {
      ++p_;
      while (p_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p_])) != 0)
        ++p_;
    }
    if (p_ - b == 1 && s_[b] == '.') throw ExprError(c, "a lone '.' is not a number");
    if (p_ < s_.size() && (s_[p_] == 'e' || s_[p_] == 'E')) {
      std::size_t q = p_ + 1;
      if (q < s_.size() && (s_[q] == '+' || s_[q] == '-')) ++q;
      if (q == s_.size() || std::isdigit(static_cast<unsigned char>(s_[q])) == 0)
        throw ExprError(c, "the exponent of '" + s_.substr(b, q - b) + "' has no digits");
      p_ = q;
      while (p_ < s_.size() && std::isdigit(static_cast<unsigned char>(s_[p_])) != 0)
        ++p_;
    }
    const std::string digits = s_.substr(b, p_ - b);
    if (p_ < s_.size() && nameStart(s_[p_]))
      throw ExprError(col(), "a name cannot follow the number '" + digits + "' (write '*' for a product)");
    errno = 0;
    const double v = std::strtod(digits.c_str(), nullptr);
    if (!std::isfinite(v) || errno == ERANGE) {
      if (std::isfinite(v) && v == 0) return add({.kind = Node::Kind::Number, .column = c, .number = 0});
      if (std::isfinite(v)) return add({.kind = Node::Kind::Number, .column = c, .number = v}); // subnormal
      throw ExprError(c, "the number " + digits + " is out of the range of double precision");
    }
    return add({.kind = Node::Kind::Number, .column = c, .number = v});
  }

  const std::string& s_;
  std::size_t p_ = 0;
  int depth_ = 0;
  Expression e_;
};

std::size_t editDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j)
    row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diag = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t up = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diag + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diag = up;
    }
  }
  return row[b.size()];
}

} // namespace

Expression parse(const std::string& text) {
  return Parser(text).run();
}

std::vector<std::string> namesUsed(const Expression& e) {
  std::vector<std::string> names;
  for (const Node& n : e.nodes)
    if (n.kind == Node::Kind::Name && std::find(names.begin(), names.end(), n.name) == names.end())
      names.push_back(n.name);
  return names;
}

std::string renamed(const Expression& e, const std::map<std::string, std::string>& replace) {
  std::vector<std::pair<std::size_t, const Node*>> at; // where each name to replace starts, last first
  for (const Node& n : e.nodes)
    if (n.kind == Node::Kind::Name && replace.count(n.name))
      at.emplace_back(static_cast<std::size_t>(n.column - 1), &n);
  std::sort(at.begin(), at.end(), [](const auto& a, const auto& b) { return a.first > b.first; });
  std::string text = e.text;
  for (const auto& [start, n] : at)
    text.replace(start, n->name.size(), "(" + replace.at(n->name) + ")");
  return text;
}

std::string nearestName(const std::string& name, const std::vector<std::string>& known) {
  std::string best;
  std::size_t bestDistance = std::max<std::size_t>(2, name.size() / 3) + 1;
  for (const auto& k : known) {
    const std::size_t d = editDistance(name, k);
    if (d < bestDistance) {
      bestDistance = d;
      best = k;
    }
  }
  return best;
}

} // namespace rv::expr
