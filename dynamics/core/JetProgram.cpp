#include "dynamics/core/JetProgram.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace rv {

using jet_recording::Constant;
using jet_recording::Var;

void JetProgram::begin(int inputs, int coefficients) {
  inputs_ = inputs, coefficients_ = coefficients, slots_ = 0;
  constants_.clear();
  numbers_.clear();
  nodes_.assign(static_cast<std::size_t>(inputs), Node{Op::ConstJet, -1, -1}); // the inputs: no operation
  outputs_.clear();
  inputSlots_.clear();
  outputSlots_.clear();
  code_.clear();
  for (int i = 0; i < coefficients; ++i)
    constants_.push_back({ConstantOp::Coefficient, i, -1, 0});
}

Constant JetProgram::coefficient(int i) {
  if (i < 0 || i >= coefficients_) throw std::logic_error("JetProgram: no coefficient " + std::to_string(i));
  return Constant(i, nullptr);
}

Constant JetProgram::number(double value) {
  const auto [it, fresh] = numbers_.emplace(std::bit_cast<std::uint64_t>(value), constantCount());
  if (fresh) constants_.push_back({ConstantOp::Number, -1, -1, value});
  return Constant(it->second, nullptr);
}

Constant JetProgram::constant(ConstantOp op, int a, int b) {
  constants_.push_back({op, a, b, 0});
  return Constant(constantCount() - 1, nullptr);
}

Var JetProgram::jet(Op op, int a, int b) {
  nodes_.push_back({op, a, b});
  return Var(static_cast<int>(nodes_.size()) - 1, nullptr);
}

void JetProgram::setOutput(int i, const Var& v) {
  if (static_cast<std::size_t>(i) >= outputs_.size()) outputs_.resize(static_cast<std::size_t>(i) + 1, -1);
  outputs_[static_cast<std::size_t>(i)] = v.id;
}

namespace {
// whether operand b of op is a node (else a constant, or none)
bool nodeOperandB(JetProgram::Op op) {
  using Op = JetProgram::Op;
  return op == Op::Add || op == Op::Sub || op == Op::Mul || op == Op::Div;
}
bool nodeOperandA(JetProgram::Op op) {
  return op != JetProgram::Op::ConstJet;
}
} // namespace

void JetProgram::finish() {
  const int count = static_cast<int>(nodes_.size());
  for (std::size_t i = 0; i < outputs_.size(); ++i)
    if (outputs_[i] < 0 || outputs_[i] >= count)
      throw std::logic_error("JetProgram: the field did not write output " + std::to_string(i));
  // the nodes some output needs (operands come before their node)
  std::vector<char> used(static_cast<std::size_t>(count), 0);
  for (const int o : outputs_)
    used[static_cast<std::size_t>(o)] = 1;
  for (int n = count - 1; n >= inputs_; --n) {
    if (!used[static_cast<std::size_t>(n)]) continue;
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    if (nodeOperandA(node.op)) used[static_cast<std::size_t>(node.a)] = 1;
    if (nodeOperandB(node.op)) used[static_cast<std::size_t>(node.b)] = 1;
  }
  // the last reader of each node (outputs live to the end)
  constexpr int kEnd = std::numeric_limits<int>::max();
  std::vector<int> lastUse(static_cast<std::size_t>(count), -1);
  for (int n = inputs_; n < count; ++n) {
    if (!used[static_cast<std::size_t>(n)]) continue;
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    if (nodeOperandA(node.op)) lastUse[static_cast<std::size_t>(node.a)] = n;
    if (nodeOperandB(node.op)) lastUse[static_cast<std::size_t>(node.b)] = n;
  }
  for (const int o : outputs_)
    lastUse[static_cast<std::size_t>(o)] = kEnd;
  // slots: a freed one first; an instruction's operands are freed after its result has its slot, so that
  // no instruction writes where it reads
  std::vector<int> slotOf(static_cast<std::size_t>(count), -1), free;
  const auto allocate = [&](int n) {
    int s;
    if (free.empty()) {
      s = slots_++;
    } else {
      s = free.back();
      free.pop_back();
    }
    slotOf[static_cast<std::size_t>(n)] = s;
  };
  const auto release = [&](int operand, int reader) {
    if (lastUse[static_cast<std::size_t>(operand)] == reader)
      free.push_back(slotOf[static_cast<std::size_t>(operand)]);
  };
  inputSlots_.assign(static_cast<std::size_t>(inputs_), -1);
  for (int i = 0; i < inputs_; ++i)
    if (used[static_cast<std::size_t>(i)]) {
      allocate(i);
      inputSlots_[static_cast<std::size_t>(i)] = slotOf[static_cast<std::size_t>(i)];
    }
  for (int n = inputs_; n < count; ++n) {
    if (!used[static_cast<std::size_t>(n)]) continue;
    const Node& node = nodes_[static_cast<std::size_t>(n)];
    allocate(n);
    Instr in{node.op, slotOf[static_cast<std::size_t>(n)], node.a, node.b};
    if (nodeOperandA(node.op)) in.a = slotOf[static_cast<std::size_t>(node.a)];
    if (nodeOperandB(node.op)) in.b = slotOf[static_cast<std::size_t>(node.b)];
    code_.push_back(in);
    if (nodeOperandA(node.op)) release(node.a, n);
    if (nodeOperandB(node.op) && node.b != node.a) release(node.b, n);
  }
  for (const int o : outputs_)
    outputSlots_.push_back(slotOf[static_cast<std::size_t>(o)]);
  nodes_.clear();
  nodes_.shrink_to_fit();
  numbers_.clear();
}

std::vector<double> JetProgram::bindConstants(const std::vector<const double*>& coefficientsOfLane) const {
  const std::size_t width = coefficientsOfLane.size(), count = constants_.size();
  std::vector<double> values(count * width);
  // each lane computes as the field's LaneVector arithmetic does, one IEEE operation (or C library call) at
  // a time
  for (std::size_t l = 0; l < width; ++l) {
    const auto at = [&](int c) { return values[static_cast<std::size_t>(c) * width + l]; };
    for (std::size_t c = 0; c < count; ++c) {
      const ConstantNode& k = constants_[c];
      double v = 0;
      switch (k.op) {
      case ConstantOp::Number:
        v = k.number;
        break;
      case ConstantOp::Coefficient:
        v = coefficientsOfLane[l][k.a];
        break;
      case ConstantOp::Add:
        v = at(k.a) + at(k.b);
        break;
      case ConstantOp::Sub:
        v = at(k.a) - at(k.b);
        break;
      case ConstantOp::Mul:
        v = at(k.a) * at(k.b);
        break;
      case ConstantOp::Div:
        v = at(k.a) / at(k.b);
        break;
      case ConstantOp::Neg:
        v = -at(k.a);
        break;
      case ConstantOp::Sqrt:
        v = std::sqrt(at(k.a));
        break;
      case ConstantOp::Sin:
        v = std::sin(at(k.a));
        break;
      case ConstantOp::Cos:
        v = std::cos(at(k.a));
        break;
      }
      values[c * width + l] = v;
    }
  }
  return values;
}

} // namespace rv
