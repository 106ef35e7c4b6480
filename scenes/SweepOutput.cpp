// SweepOutput.cpp -- what a sweep writes and reads back (scenes/Sweep.h): its CSV (header, rows, a finished
// file read back) and the chart's description of it.
#include "dynamics/core/Errors.h"
#include "dynamics/core/NaN.h"
#include "scenes/SweepGrid.h"

#include <cmath>
#include <fmt/core.h>
#include <fstream>
#include <limits>
#include <map>
#include <sstream>

namespace rv {

namespace {

std::string csvField(const std::string& s) {
  if (s.find_first_of(",\"\n") == std::string::npos) return s;
  std::string q = "\"";
  for (char c : s)
    q += c == '"' ? std::string("\"\"") : std::string(1, c == '\n' ? ' ' : c);
  return q + "\"";
}

} // namespace

std::vector<std::string> sweepCsvHeader(const SweepSpec& spec, bool timing) {
  std::vector<std::string> h;
  for (const auto& a : spec.axes)
    h.push_back(a.id);
  h.insert(h.end(), spec.columns.begin(), spec.columns.end());
  if (timing) h.emplace_back("seconds");
  h.emplace_back("status");
  return h;
}

SweepChartData sweepChartData(const SweepSpec& spec) {
  SweepChartData d;
  d.title = spec.title;
  for (std::size_t k = 0; k < spec.axes.size(); ++k) {
    const SweepAxis& a = spec.axes[k];
    d.axes.push_back(spec.axisLabel(k));
    d.counts.push_back(a.count);
    d.mins.push_back(a.min);
    d.maxs.push_back(a.max);
  }
  d.columns = spec.columns;
  d.orbit = spec.quantity->cloud;
  return d;
}
std::string sweepCsvRow(const SweepSpec& spec, long index, const SweepRecord& r, bool timing) {
  std::string row;
  for (double v : spec.axisValues(index))
    row += fmt::format("{:.17g},", v);
  for (double v : r.values)
    row += fmt::format("{:.17g},", v);
  if (timing) row += fmt::format("{:.6g},", r.seconds);
  row += r.ok ? "ok" : csvField("failed: " + r.reason);
  return row;
}

std::vector<double> readSweepCsv(const SweepSpec& spec, const std::string& path, const std::string& what) {
  std::ifstream in(path);
  if (!in) throw InputError(what + " " + path + ": cannot open");
  std::string line, expected, timed;
  for (const auto& h : sweepCsvHeader(spec))
    expected += (expected.empty() ? "" : ",") + h;
  for (const auto& h : sweepCsvHeader(spec, true))
    timed += (timed.empty() ? "" : ",") + h;
  if (!std::getline(in, line) || (line != expected && line != timed))
    throw InputError(what + " " + path + ": not the CSV of this sweep (expected the header " + expected +
                     ")");
  const std::size_t first = spec.axes.size(), n = spec.columns.size();
  std::vector<double> values;
  values.reserve(static_cast<std::size_t>(spec.points()) * n);
  std::map<long, SweepRecord> computed; // a refined sweep's rows: its computed points, found by their axes
  long row = 0;
  for (; std::getline(in, line); ++row) {
    std::stringstream fields(line);
    std::string field;
    std::vector<long> k;
    SweepRecord record;
    for (std::size_t c = 0; c < first + n; ++c) {
      if (!std::getline(fields, field, ','))
        throw InputError(fmt::format("{} {}:{}: too few columns", what, path, row + 2));
      double v = kNaN;
      try {
        v = field == "nan" ? kNaN : std::stod(field);
      } catch (const std::exception&) {
        throw InputError(fmt::format("{} {}:{}: not a number '{}'", what, path, row + 2, field));
      }
      if (c >= first) {
        (spec.refine ? record.values : values).push_back(v);
        continue;
      }
      const SweepAxis& axis = spec.axes[c];
      const double at = axis.count > 1 ? (v - axis.min) / (axis.max - axis.min) * (axis.count - 1) : 0.0;
      if (!(at > -0.5 && at < axis.count - 0.5))
        throw InputError(
            fmt::format("{} {}:{}: {} = {} is off the sweep's grid", what, path, row + 2, axis.id, v));
      k.push_back(std::lround(at));
    }
    if (spec.refine) computed[sweepGridIndex(spec, k)] = std::move(record);
  }
  if (spec.refine)
    return sweepGridValues(
        spec, [&](long i) { return computed.count(i) > 0; }, [&](long i) { return computed.at(i); });
  if (row != spec.points())
    throw InputError(fmt::format("{} {}: {} rows, the sweep has {} points", what, path, row, spec.points()));
  return values;
}

} // namespace rv
