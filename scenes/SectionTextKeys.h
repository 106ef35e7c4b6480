// SectionTextKeys.h -- the text settings of a tool's scene section that are no numbers of its parameter table
// (scenes/SceneLoader.cpp reads and checks them): a generic tool command offers them as flags beside the
// table's.
#pragma once
#include <string>
#include <vector>

namespace rv {

struct SectionTextKey {
  std::string key;         ///< e.g. "second_parameter"
  std::string description; ///< one line, for `--help`
};

/// The described text keys of scene section `section` (none for most).
std::vector<SectionTextKey> sectionTextKeys(const std::string& section);

} // namespace rv
