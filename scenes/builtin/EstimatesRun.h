// EstimatesRun.h -- what the tools of estimates against time (lyapunov, megno) share: their resumable run,
// and a number among a result's fields (their batch evaluations on lanes read one).
#pragma once
#include "scenes/ToolRunner.h"

#include <memory>
#include <optional>
#include <string>
#include <vector>

namespace rv {

// A run of estimates against time (dynamics/tools: MegnoRun, LyapunovRun): its fields are the last
// estimate's, its table the history of estimates (every output period), the table's columns named at the
// first estimate.
template <class Run, class Estimate> class EstimatesRun : public ToolRun {
public:
  template <class Settings>
  EstimatesRun(const Scene& scene, const Settings& settings)
      : model_(scene.model), spec_(scene.runSpec()),
        run_(
            *model_, [this] { return spec_.makeIntegrator(*model_); }, scene.initialState, settings) {}
  bool advance(const ToolControl& control) override {
    return run_.run(
        [this](const Estimate& e) {
          if (history_.rows() && history_.values[0].back() == e.time) return; // the last may come twice
          const std::vector<double> row = this->row(e);
          if (history_.names.empty()) name(row.size());
          history_.addRow(row);
        },
        control);
  }
  void save(Snapshot& state) const override {
    run_.save(state);
    state.put(static_cast<double>(history_.names.size()));
    putTable(state, history_);
  }
  void restore(Snapshot& state) override {
    run_.restore(state);
    const long width = state.getLong();
    history_ = {};
    if (width > 0) name(static_cast<std::size_t>(width));
    getTable(state, history_);
  }

protected:
  /// The history's row of an estimate: t first.
  virtual std::vector<double> row(const Estimate& e) const = 0;
  /// The names of a row of `width` numbers.
  virtual std::vector<std::string> columns(std::size_t width) const = 0;
  const Run& run() const { return run_; }
  const NamedColumns& history() const { return history_; }

private:
  void name(std::size_t width) {
    history_.names = columns(width);
    history_.values.resize(width);
  }
  std::shared_ptr<const Model> model_;
  RunSpec spec_;
  Run run_;
  NamedColumns history_;
};

/// A tool's output `name` from its fields, where it is a number.
inline std::optional<double> numberIn(const nlohmann::json& fields, const std::string& name) {
  const auto f = fields.find(name);
  if (f == fields.end() || !f->is_number()) return std::nullopt;
  return f->get<double>();
}

} // namespace rv
