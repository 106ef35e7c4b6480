#include "scenes/JsonFields.h"

#include "dynamics/core/Errors.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <set>
#include <sstream>

namespace rv {

using nlohmann::json;

std::string readInputFile(const std::string& path, const std::string& what) {
  namespace fs = std::filesystem;
  std::error_code ec;
  if (fs::is_directory(path, ec)) throw InputError(path + ": is a folder, not a " + what);
  std::ifstream in(path, std::ios::binary);
  if (!in)
    throw InputError(path + ": cannot open the " + what + " (" +
                     (fs::exists(path, ec) ? "not readable" : "no such file") + ")");
  std::stringstream buffer;
  buffer << in.rdbuf();
  std::string content = buffer.str();
  if (content.empty()) throw InputError(path + ": the " + what + " is empty");
  return content;
}

void Where::fail(const std::string& reason) const {
  throw InputError(str() + ": " + reason);
}

std::string shown(const json& j) {
  return j.dump(-1, ' ', false, json::error_handler_t::replace);
}

const json& requireObject(const json& j, const Where& w) {
  if (!j.is_object()) w.fail("expected an object");
  return j;
}

double number(const json& j, const Where& w) {
  if (!j.is_number()) w.fail("expected a number, got " + shown(j));
  return j.get<double>();
}

std::string text(const json& j, const Where& w) {
  if (!j.is_string()) w.fail("expected a string, got " + shown(j));
  return j.get<std::string>();
}

std::vector<double> commaNumbers(const std::string& text) {
  std::vector<double> v;
  std::stringstream in(text);
  for (std::string item; std::getline(in, item, ',');) {
    char* end = nullptr;
    const double x = std::strtod(item.c_str(), &end);
    if (item.empty() || *end != '\0' || !std::isfinite(x))
      throw InputError("expected numbers separated by commas");
    v.push_back(x);
  }
  return v;
}

std::vector<double> numbers(const nlohmann::json& j, const Where& w) {
  if (!j.is_array()) w.fail("expected an array of numbers");
  std::vector<double> v;
  v.reserve(j.size());
  for (std::size_t i = 0; i < j.size(); ++i)
    v.push_back(number(j[i], w / std::to_string(i)));
  return v;
}

bool boolean(const json& j, const Where& w) {
  if (!j.is_boolean()) w.fail("expected true or false, got " + shown(j));
  return j.get<bool>();
}

void onlyKeys(const json& j, const Where& w, std::initializer_list<const char*> keys) {
  for (const auto& [k, v] : j.items()) {
    bool ok = false;
    for (const char* known : keys)
      ok = ok || k == known;
    if (!ok) {
      std::string list;
      for (const char* known : keys)
        list += std::string(" ") + known;
      (w / k).fail("unknown key (known:" + list + ")");
    }
  }
}

void readParameters(const json& j, const Where& w, ParameterValues& values,
                    const std::vector<std::string>& skip) {
  for (const auto& [k, v] : j.items()) {
    if (std::find(skip.begin(), skip.end(), k) != skip.end()) continue;
    if (values.table().find(k) < 0) {
      std::string known;
      for (const auto& s : values.table().specs())
        known += " " + s.id;
      (w / k).fail("unknown parameter (known:" + known + ")");
    }
    try {
      const auto& choices = values.table().specs()[values.table().find(k)].choices;
      if (!choices.empty() && v.is_string())
        values.setChoice(k, v.get<std::string>(), (w / k).str());
      else if (choices.size() == 2 && choices[0] == "no" && v.is_boolean())
        values.set(k, v.get<bool>() ? 1 : 0);
      else
        values.set(k, number(v, w / k));
    } catch (const InputError& e) {
      const std::string msg = e.what();
      if (msg.rfind(w.file + ":", 0) == 0) throw;
      (w / k).fail(msg.substr(msg.find(": ") == std::string::npos ? 0 : msg.find(": ") + 2));
    }
  }
}

nlohmann::json parseSceneJson(std::istream& in, const std::string& source) {
  // the parser's events keep the path to the current value and each open object's keys: a key written twice
  // is bad input (JSON leaves it undefined; nlohmann would silently keep the last)
  struct Level {
    bool object;
    std::set<std::string> keys;
    std::string key; ///< the object's current key
    long index = 0;  ///< the array's current element
  };
  std::vector<Level> levels;
  std::string duplicate;
  const auto pathTo = [&](const std::string& last) {
    std::string path;
    for (std::size_t i = 0; i + 1 < levels.size(); ++i)
      path +=
          (path.empty() ? "" : ".") + (levels[i].object ? levels[i].key : std::to_string(levels[i].index));
    return path.empty() ? last : path + "." + last;
  };
  const auto ended = [&] { // a value is complete: the enclosing array moves to its next element
    if (!levels.empty() && !levels.back().object) ++levels.back().index;
  };
  const json::parser_callback_t callback = [&](int, json::parse_event_t event, json& parsed) {
    using E = json::parse_event_t;
    switch (event) {
    case E::object_start:
    case E::array_start:
      levels.push_back({event == E::object_start, {}, {}, 0});
      break;
    case E::key: {
      Level& level = levels.back();
      level.key = parsed.get<std::string>();
      if (!level.keys.insert(level.key).second && duplicate.empty()) duplicate = pathTo(level.key);
      break;
    }
    case E::object_end:
    case E::array_end:
      levels.pop_back();
      ended();
      break;
    case E::value:
      ended();
      break;
    }
    return true;
  };
  json doc;
  try {
    doc = json::parse(in, callback);
  } catch (const json::exception& e) {
    // parse errors, and numbers beyond a double (out_of_range 406, found by fuzzing)
    std::string reason = e.what();
    if (const auto p = reason.find("] "); p != std::string::npos) reason = reason.substr(p + 2);
    throw InputError(source + ":$: malformed JSON: " + reason);
  } catch (const std::ios_base::failure& e) {
    throw InputError(source + ": cannot read: " + e.what());
  }
  if (!duplicate.empty()) throw InputError(source + ":" + duplicate + ": key written twice");
  return doc;
}

} // namespace rv
