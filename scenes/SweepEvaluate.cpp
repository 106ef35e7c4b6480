// SweepEvaluate.cpp -- a sweep's grid points evaluated (scenes/Sweep.h): one at a time, or several at once on
// SIMD lanes where the quantity can (its tool's batch evaluation), each point's record as alone.
#include "dynamics/core/Errors.h"
#include "dynamics/core/Lanes.h"
#include "dynamics/core/NaN.h"
#include "dynamics/tools/ReturnMap.h"
#include "scenes/Sweep.h"

#include <chrono>
#include <limits>
#include <map>
#include <mutex>

namespace rv {

namespace {

// grid point `index`'s scene as the quantity computes on it (narrowed to what it needs)
Scene evaluatedScene(const SweepSpec& spec, long index) {
  Scene scene = sweepPointScene(spec, index);
  if (spec.quantity->narrow) spec.quantity->narrow(scene);
  return scene;
}

} // namespace

SweepRecord evaluateSweepPoint(const SweepSpec& spec, long index, const ToolControl& control) {
  const auto start = std::chrono::steady_clock::now();
  SweepRecord r;
  try {
    const Scene scene = evaluatedScene(spec, index);
    r.values = spec.quantity->evaluate(spec, scene, control);
    r.values.resize(spec.columns.size(), kNaN);
  } catch (const Stopped&) {
    r.ok = false;
    r.reason = "stopped";
  } catch (const std::exception& e) { // InputError (no scene at these values) or ComputationError
    r.ok = false;
    r.reason = e.what();
    if (r.reason.rfind(spec.source + ":", 0) == 0) r.reason.erase(0, spec.source.size() + 1); // said once
  }
  if (!r.ok) r.values.assign(spec.columns.size(), kNaN);
  r.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return r;
}

int sweepBatch(const SweepSpec& spec) {
  if (!spec.quantity->evaluateLanes) return 1;
  return spec.lanes == 0 ? laneWidth() : spec.lanes;
}

std::optional<PointsOnLanes> pointsOnLanes(const std::vector<Scene>& scenes) {
  const auto common = [](const Scene& s) {
    nlohmann::json doc = s.document;
    doc.erase("initial");
    doc.erase("parameters");
    return doc;
  };
  if (scenes.empty()) return std::nullopt;
  const nlohmann::json first = common(scenes.front());
  PointsOnLanes p{.run = scenes.front().runSpec()};
  for (const Scene& s : scenes) {
    if (common(s) != first) return std::nullopt;
    p.models.push_back(s.model.get());
    p.starts.push_back(s.initialState);
  }
  return p;
}

namespace {
// the points `indices`, whose scenes are `scenes`, together on lanes; each record to the sink
void evaluateOnLanes(const SweepSpec& spec, const std::vector<long>& indices,
                     const std::vector<Scene>& scenes, std::chrono::steady_clock::time_point start,
                     const ToolControl& control, const RecordSink& sink) {
  if (indices.size() < 2) { // alone, as a point of a sweep that does not batch
    for (const long index : indices)
      sink(index, evaluateSweepPoint(spec, index, control));
    return;
  }
  std::optional<std::vector<LaneValues>> lanes;
  try {
    lanes = spec.quantity->evaluateLanes(spec, scenes, control);
  } catch (const Stopped&) {
    for (const long index : indices)
      sink(index, {std::vector<double>(spec.columns.size(), kNaN), 0, false, "stopped"});
    return;
  } catch (const std::exception&) { // bad settings: each point says so, as alone
    lanes.reset();
  }
  if (!lanes) {
    for (const long index : indices)
      sink(index, evaluateSweepPoint(spec, index, control));
    return;
  }
  const double share = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
                       static_cast<double>(indices.size());
  for (std::size_t j = 0; j < indices.size(); ++j) {
    SweepRecord r;
    const LaneValues& lane = (*lanes)[j];
    if (lane.failure) { // the reason as evaluateSweepPoint words it
      try {
        std::rethrow_exception(lane.failure);
      } catch (const std::exception& e) {
        r.ok = false;
        r.reason = e.what();
        if (r.reason.rfind(spec.source + ":", 0) == 0) r.reason.erase(0, spec.source.size() + 1);
      }
      r.values.assign(spec.columns.size(), kNaN);
    } else {
      r.values = lane.values;
      r.values.resize(spec.columns.size(), kNaN);
    }
    r.seconds = share;
    sink(indices[j], r);
  }
}
} // namespace

void evaluateSweepPoints(const SweepSpec& spec, const std::vector<long>& indices, const ToolControl& control,
                         const RecordSink& sink) {
  const std::size_t width = static_cast<std::size_t>(sweepBatch(spec));
  std::vector<Scene> scenes;
  std::vector<long> batched;
  auto start = std::chrono::steady_clock::now();
  for (const long index : indices) {
    if (control.stopRequested()) return;
    if (width == 1) {
      sink(index, evaluateSweepPoint(spec, index, control));
      continue;
    }
    try {
      scenes.push_back(evaluatedScene(spec, index));
      batched.push_back(index);
    } catch (const std::exception&) {
      // no scene at its values: its failure, said alone; its lane is the next point's
      sink(index, evaluateSweepPoint(spec, index, control));
      continue;
    }
    if (batched.size() == width) {
      evaluateOnLanes(spec, batched, scenes, start, control, sink);
      scenes.clear();
      batched.clear();
      start = std::chrono::steady_clock::now();
    }
  }
  if (!batched.empty() && !control.stopRequested())
    evaluateOnLanes(spec, batched, scenes, start, control, sink);
}

std::vector<SweepRecord> evaluateSweepPoints(const SweepSpec& spec, const std::vector<long>& indices,
                                             const ToolControl& control) {
  std::map<long, SweepRecord> computed;
  evaluateSweepPoints(spec, indices, control,
                      [&](long index, const SweepRecord& record) { computed[index] = record; });
  std::vector<SweepRecord> records;
  records.reserve(indices.size());
  for (const long index : indices) {
    const auto found = computed.find(index);
    records.push_back(found != computed.end()
                          ? found->second
                          : SweepRecord{std::vector<double>(spec.columns.size(), kNaN), 0, false, "stopped"});
  }
  return records;
}

namespace {
struct LanesEvaluators {
  std::mutex mutex;
  std::map<std::string, LanesEvaluator> byTool;
};
LanesEvaluators& lanesEvaluators() {
  static LanesEvaluators all;
  return all;
}
} // namespace

void addLanesEvaluator(const std::string& id, LanesEvaluator evaluate) {
  auto& all = lanesEvaluators();
  const std::lock_guard lock(all.mutex);
  if (!all.byTool.emplace(id, std::move(evaluate)).second)
    throw InputError("tool " + id + " has a batch evaluation on lanes already");
}

const LanesEvaluator* findLanesEvaluator(const std::string& id) {
  auto& all = lanesEvaluators();
  const std::lock_guard lock(all.mutex);
  const auto it = all.byTool.find(id);
  return it == all.byTool.end() ? nullptr : &it->second; // (entries are never removed: the pointer stays)
}

} // namespace rv
