#include "render/Textures.h"

#include "dynamics/core/Errors.h"
#include <algorithm>
#include <cmath>

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkTexture.h>
#include <vtkTransform.h>
#include <vtkUnsignedCharArray.h>

namespace rv {

namespace {
vtkSmartPointer<vtkTexture> textureFrom(int w, int h, const auto& pixel, bool repeat) {
  vtkNew<vtkImageData> img;
  img->SetDimensions(w, h, 1);
  img->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* p = static_cast<unsigned char*>(img->GetScalarPointer());
  for (int j = 0; j < h; ++j)
    for (int i = 0; i < w; ++i) {
      const Rgb c = pixel(i, j);
      for (int k = 0; k < 3; ++k)
        *p++ = static_cast<unsigned char>(std::lround(std::clamp(c[k], 0.0, 1.0) * 255));
    }
  auto tex = vtkSmartPointer<vtkTexture>::New();
  tex->SetInputData(img);
  tex->InterpolateOn();
  // no mipmaps: trilinear filtering costs ~40 ms a 720p frame on llvmpipe (tests/bench), for a little moire
  // far off
  tex->MipmapOff();
  tex->SetRepeat(repeat);
  return tex;
}

Rgb mix(const Rgb& a, const Rgb& b, double s) {
  return {a[0] + (b[0] - a[0]) * s, a[1] + (b[1] - a[1]) * s, a[2] + (b[2] - a[2]) * s};
}
} // namespace

vtkSmartPointer<vtkTexture> makeBallTexture(const Rgb& colour) {
  const int w = 1024, h = 512;
  const Rgb light = mix(colour, {1, 1, 1}, 0.75), dark = {0.08, 0.08, 0.1};
  return textureFrom(
      w, h,
      [&](int i, int j) {
        const double lon = 360.0 * (i + 0.5) / w, lat = 180.0 * (j + 0.5) / h - 90;
        const bool sector = static_cast<int>(lon / 45) % 2 == 0, north = lat > 0;
        Rgb c = (sector != north) ? colour : light;
        // thin dark meridians and parallels every 30 degrees (about 1.5 texels wide)
        const double dl = std::abs(std::remainder(lon, 30.0)) * w / 360,
                     dp = std::abs(std::remainder(lat, 30.0)) * h / 180;
        const double line = std::max(std::clamp(1.6 - dl, 0.0, 1.0), std::clamp(1.6 - dp, 0.0, 1.0));
        return mix(c, dark, 0.8 * line);
      },
      true);
}

vtkSmartPointer<vtkTexture> textureFor(const ObjectOptions& o,
                                       const std::function<vtkSmartPointer<vtkTexture>()>& own) {
  if (o.texture == "none") return nullptr;
  vtkSmartPointer<vtkTexture> tex;
  if (o.texture.empty()) {
    tex = own();
  } else {
    vtkNew<vtkPNGReader> png;
    png->SetFileName(o.texture.c_str());
    png->Update();
    if (png->GetErrorCode() != 0) throw ComputationError("cannot read the texture " + o.texture);
    tex = vtkSmartPointer<vtkTexture>::New();
    tex->SetInputData(png->GetOutput());
    tex->InterpolateOn();
    tex->SetRepeat(true);
  }
  if (o.gridDensity != 1) {
    vtkNew<vtkTransform> scale;
    scale->Scale(o.gridDensity, o.gridDensity, 1);
    tex->SetTransform(scale);
  }
  return tex;
}

vtkSmartPointer<vtkTexture> makeCheckerTexture(const Rgb& light, const Rgb& dark, const Rgb& line) {
  const int n = 256; // two cells of 128 texels per side
  return textureFrom(
      n, n,
      [&](int i, int j) {
        Rgb c = ((i / 128) + (j / 128)) % 2 ? dark : light;
        const int di = std::min(i % 128, 127 - i % 128), dj = std::min(j % 128, 127 - j % 128);
        return std::min(di, dj) < 2 ? mix(c, line, 0.6) : c;
      },
      true);
}

} // namespace rv
