// JsonFields.h -- parsing the project's JSON files (scenes, models, sessions, sweeps) and reading their
// fields, with every error naming "file:json.path: reason" (InputError).
#pragma once
#include "dynamics/core/ParameterTable.h"

#include <initializer_list>
#include <istream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rv {

/// The error context: "file:json.path".
struct Where {
  std::string file, path;
  Where operator/(const std::string& key) const { return {file, path.empty() ? key : path + "." + key}; }
  std::string str() const { return file + ":" + (path.empty() ? "$" : path); }
  [[noreturn]] void fail(const std::string& reason) const;
};

/// A value in a message (invalid UTF-8 replaced: dump() would throw on it).
std::string shown(const nlohmann::json& j);
const nlohmann::json& requireObject(const nlohmann::json& j, const Where& w);
double number(const nlohmann::json& j, const Where& w);
std::string text(const nlohmann::json& j, const Where& w);
bool boolean(const nlohmann::json& j, const Where& w);
/// An array of numbers ("expected an array of numbers"; an element that is not one names its index).
std::vector<double> numbers(const nlohmann::json& j, const Where& w);
/// Finite numbers separated by commas ("0.6,0.2": a command line's --guess, --x); InputError "expected
/// numbers separated by commas" for anything else (the caller names its flag).
std::vector<double> commaNumbers(const std::string& text);
/// Fails naming the first key of `j` that is not in `keys`.
void onlyKeys(const nlohmann::json& j, const Where& w, std::initializer_list<const char*> keys);
/// The whole text of one of the project's input files; InputError "PATH: is a folder, not a WHAT", "cannot
/// open the WHAT (no such file | not readable)" or "the WHAT is empty" (WHAT: "scene file", "model file").
std::string readInputFile(const std::string& path, const std::string& what);
/// Fills a parameter table's values from a JSON object, skipping the keys in `skip`; a choice takes its name
/// (or true/false for no/yes).
void readParameters(const nlohmann::json& j, const Where& w, ParameterValues& values,
                    const std::vector<std::string>& skip = {});

/// Parses a rollviz JSON file (a scene, model, session or sweep file); InputError "source:path: ..." when it
/// is malformed or writes a key twice in one object (JSON leaves that undefined).
nlohmann::json parseSceneJson(std::istream& in, const std::string& source);

} // namespace rv
