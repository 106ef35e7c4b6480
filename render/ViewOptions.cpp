#include "render/ViewOptions.h"

#include <cstdlib>

namespace rv {

std::optional<Rgb> parseColour(const std::string& text) {
  if (text.size() != 7 || text[0] != '#') return std::nullopt;
  Rgb c{};
  for (int i = 0; i < 3; ++i) {
    const std::string hex = text.substr(1 + 2 * i, 2);
    char* end = nullptr;
    const long v = std::strtol(hex.c_str(), &end, 16);
    if (end != hex.c_str() + 2) return std::nullopt;
    c[i] = v / 255.0;
  }
  return c;
}

const ObjectOptions& ViewOptions::object(const std::string& name) const {
  static const ObjectOptions defaults;
  const auto it = objects.find(name);
  return it == objects.end() ? defaults : it->second;
}

} // namespace rv
