// PyCommon.h -- what the Python module's files share: Python values as scene overrides, NumPy arrays that own
// their C++ buffers (no copy), parameter tables as Python lists.
#pragma once
#include "dynamics/core/ParameterTable.h"
#include "scenes/SceneLoader.h"

#include <complex>
#include <pybind11/complex.h>
#include <pybind11/numpy.h>
#include <pybind11/pybind11.h>
#include <pybind11/stl.h>
#include <string>
#include <vector>

namespace rv::py {

namespace pyb = pybind11;

/// A Python value (bool, int, float, str, list, tuple, dict, None) as JSON; ValueError naming `what` else.
nlohmann::json toJson(const pyb::handle& value, const std::string& what);

/// `key=value` as a `--set` override (the value as JSON text, so that strings stay strings).
SceneOverride toOverride(const std::string& key, const pyb::handle& value);

/// The scene again with more overrides (InputError, i.e. ValueError, for bad ones).
Scene withOverrides(const Scene& scene, const std::vector<SceneOverride>& overrides);

/// A NumPy array of `shape` viewing `data`, which it keeps alive (moved, never copied).
template <class T> pyb::array_t<T> toArray(std::vector<T>&& data, std::vector<pyb::ssize_t> shape) {
  auto* owned = new std::vector<T>(std::move(data));
  pyb::capsule owner(owned, [](void* p) { delete static_cast<std::vector<T>*>(p); });
  return pyb::array_t<T>(std::move(shape), owned->data(), owner);
}
template <class T> pyb::array_t<T> toArray(std::vector<T>&& data) {
  const auto n = static_cast<pyb::ssize_t>(data.size());
  return toArray(std::move(data), {n});
}

/// A parameter table as a list of dicts: id, default, min, max, unit, description (+ choices).
pyb::list describeTable(const ParameterTable& table);

/// Registers the tool runners: Scene._run(tool, progress, kwargs), _tools(), sweep().
void bindTools(pyb::module_& m, pyb::class_<Scene>& scene);

} // namespace rv::py
