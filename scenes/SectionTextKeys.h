// SectionTextKeys.h -- the settings of a tool's scene section that are no numbers of its parameter table
// (scenes/SceneLoader.cpp reads and checks them): a generic tool command offers some as flags beside the
// table's; Python's signatures list them all.
#pragma once
#include <string>
#include <vector>

namespace rv {

struct SectionTextKey {
  std::string key;         ///< e.g. "second_parameter"
  std::string description; ///< one line, for `--help`
  std::string type;        ///< "text", "number" or "numbers" (an array)
  bool parameter = false;  ///< a text that names one of the problem's parameters (the GUI offers them)
};

/// The text keys of scene section `section` (none for most); with flagsOnly, those a generic tool command
/// offers as flags.
std::vector<SectionTextKey> sectionTextKeys(const std::string& section, bool flagsOnly = true);

} // namespace rv
