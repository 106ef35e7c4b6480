// Format.h -- printf-style formatting into a std::string, for messages (dynamics links Eigen only, so no
// fmt).
#pragma once
#include <cstdio>
#include <string>

namespace rv {

/// snprintf into a string: format("t = %g", t).
template <class... Args> std::string format(const char* pattern, Args... args) {
  const int size = std::snprintf(nullptr, 0, pattern, args...);
  std::string out(size > 0 ? size : 0, '\0');
  if (size > 0) std::snprintf(out.data(), out.size() + 1, pattern, args...);
  return out;
}

} // namespace rv
