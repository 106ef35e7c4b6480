// FileNames.h -- what a file's name says: its extension picks the format of an output (and of a mesh read),
// in every layer, so it sits at the bottom.
#pragma once
#include <algorithm>
#include <cctype>
#include <string>

namespace rv {

/// Whether `path` ends with `extension` (".vtp"), ignoring case.
inline bool hasExtension(const std::string& path, const std::string& extension) {
  if (path.size() < extension.size()) return false;
  return std::equal(extension.rbegin(), extension.rend(), path.rbegin(), [](char a, char b) {
    return std::tolower(static_cast<unsigned char>(a)) == std::tolower(static_cast<unsigned char>(b));
  });
}

} // namespace rv
