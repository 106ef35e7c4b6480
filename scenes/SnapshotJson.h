// SnapshotJson.h -- a Snapshot in JSON files (checkpoints, the GUI's saved jobs): each double as its 64-bit
// pattern, so every value comes back exactly, NaN and infinities included.
#pragma once
#include "dynamics/core/Errors.h"
#include "dynamics/core/Snapshot.h"

#include <bit>
#include <cstdint>
#include <nlohmann/json.hpp>
#include <string>

namespace rv {

inline nlohmann::json snapshotToJson(const Snapshot& s) {
  nlohmann::json bits = nlohmann::json::array();
  for (double v : s.values)
    bits.push_back(std::bit_cast<std::uint64_t>(v));
  return bits;
}

/// InputError naming `what` when `j` is not what snapshotToJson wrote.
inline Snapshot snapshotFromJson(const nlohmann::json& j, const std::string& what) {
  if (!j.is_array()) throw InputError(what + ": damaged saved state");
  Snapshot s;
  s.values.reserve(j.size());
  for (const auto& v : j) {
    if (!v.is_number_unsigned()) throw InputError(what + ": damaged saved state");
    s.values.push_back(std::bit_cast<double>(v.get<std::uint64_t>()));
  }
  return s;
}

} // namespace rv
