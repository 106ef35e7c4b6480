#include "tests/render/ImageCompare.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <set>
#include <sstream>
#include <stdexcept>

namespace rv::test {

bool isVaried(const Image& image) {
  const std::size_t n = image.rgb.size();
  if (n == 0) return false;
  double sum = 0, sum2 = 0;
  std::set<unsigned> colours;
  for (std::size_t i = 0; i < n; ++i)
    sum += image.rgb[i], sum2 += double(image.rgb[i]) * image.rgb[i];
  for (std::size_t i = 0; i + 2 < n && colours.size() <= 50; i += 3)
    colours.insert(image.rgb[i] << 16 | image.rgb[i + 1] << 8 | image.rgb[i + 2]);
  const double mean = sum / n, sd = std::sqrt(std::max(0.0, sum2 / n - mean * mean));
  return sd > 5 && colours.size() > 50;
}

ImageDifference compareImages(const Image& a, const Image& b) {
  if (a.width != b.width || a.height != b.height)
    throw std::runtime_error("sizes differ: " + std::to_string(a.width) + "x" + std::to_string(a.height) +
                             " vs " + std::to_string(b.width) + "x" + std::to_string(b.height));
  ImageDifference d;
  d.diff = a;
  double total = 0;
  long over = 0;
  for (std::size_t p = 0; p < a.rgb.size(); p += 3) {
    int worst = 0;
    for (int c = 0; c < 3; ++c) {
      const int e = std::abs(int(a.rgb[p + c]) - int(b.rgb[p + c]));
      total += e, worst = std::max(worst, e);
      d.diff.rgb[p + c] = static_cast<unsigned char>(std::min(255, 4 * e));
    }
    over += worst > 48;
  }
  d.meanAbs = total / a.rgb.size();
  d.fractionOver = static_cast<double>(over) / (a.rgb.size() / 3);
  return d;
}

std::string matchesBaseline(const Image& actual, const std::string& name, double maxMeanAbs,
                            double maxFractionOver) {
  const char* src = std::getenv("ROLLVIZ_SOURCE_DIR");
  const std::filesystem::path baseline =
      std::filesystem::path(src ? src : ".") / "assets/baselines" / (name + ".png");
  if (const char* u = std::getenv("ROLLVIZ_UPDATE_BASELINES"); u && std::string(u) == "1") {
    writePng(actual, baseline.string());
    return "";
  }
  const char* out = std::getenv("ROLLVIZ_TEST_OUTPUT");
  const std::filesystem::path dir = out ? out : ".";
  std::filesystem::create_directories(dir);
  const auto keep = [&](const Image& img, const std::string& suffix) {
    writePng(img, (dir / (name + suffix)).string());
  };
  if (!std::filesystem::exists(baseline)) {
    keep(actual, ".actual.png");
    return "no baseline " + baseline.string() + " (ROLLVIZ_UPDATE_BASELINES=1 writes it)";
  }
  const Image expected = readPng(baseline.string());
  try {
    const ImageDifference d = compareImages(actual, expected);
    if (d.meanAbs <= maxMeanAbs && d.fractionOver <= maxFractionOver) return "";
    keep(actual, ".actual.png");
    keep(d.diff, ".diff.png");
    std::ostringstream os;
    os << name << ": mean |difference| " << d.meanAbs << " (max " << maxMeanAbs
       << "), pixels off by > 48: " << 100 * d.fractionOver << "% (max " << 100 * maxFractionOver
       << "%); see " << dir.string();
    return os.str();
  } catch (const std::runtime_error& e) {
    keep(actual, ".actual.png");
    return name + ": " + e.what();
  }
}

} // namespace rv::test
