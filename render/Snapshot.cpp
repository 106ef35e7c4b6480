#include "render/Snapshot.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <vector>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGReader.h>
#include <vtkPNGWriter.h>
#include <vtkRenderLargeImage.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkSmartPointer.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

namespace rv {

namespace {
// VTK's rows are bottom-up, Image's top-down: rows of RGB are copied whole, in reverse order
void flipRgbRows(const unsigned char* bottomUp, int width, int height, Image& out) {
  out.width = width, out.height = height;
  const std::size_t row = std::size_t(width) * 3;
  out.rgb.resize(row * height);
  for (int y = 0; y < height; ++y)
    std::memcpy(out.rgb.data() + std::size_t(height - 1 - y) * row, bottomUp + std::size_t(y) * row, row);
}

Image fromVtk(vtkImageData* img) {
  Image out;
  int dims[3];
  img->GetDimensions(dims);
  const int nc = img->GetNumberOfScalarComponents();
  const auto* src = static_cast<const unsigned char*>(img->GetScalarPointer());
  if (nc == 3) {
    flipRgbRows(src, dims[0], dims[1], out);
    return out;
  }
  out.width = dims[0], out.height = dims[1];
  out.rgb.resize(std::size_t(out.width) * out.height * 3);
  for (int y = 0; y < out.height; ++y)
    for (int x = 0; x < out.width; ++x)
      for (int c = 0; c < 3; ++c)
        out.rgb[(std::size_t(out.height - 1 - y) * out.width + x) * 3 + c] =
            src[(std::size_t(y) * out.width + x) * nc + std::min(c, nc - 1)];
  return out;
}
} // namespace

Image capture(vtkRenderWindow* window) {
  Image img;
  captureInto(window, img);
  return img;
}

void captureInto(vtkRenderWindow* window, Image& into) {
  window->Render();
  // read once from the buffer just rendered (front = 0: VTK's render framebuffer, also with no blit), into a
  // buffer this thread keeps
  thread_local vtkSmartPointer<vtkUnsignedCharArray> pixels = vtkSmartPointer<vtkUnsignedCharArray>::New();
  const int* size = window->GetSize();
  const int w = size[0], h = size[1];
  if (window->GetPixelData(0, 0, w - 1, h - 1, 0, pixels, 0) == VTK_ERROR)
    throw ComputationError("cannot read the rendered picture back");
  flipRgbRows(pixels->GetPointer(0), w, h, into);
}

void writePng(vtkRenderWindow* window, const std::string& path, const std::string& what,
              const SnapshotOptions& options) {
  if (options.scale < 1 || options.scale > 16) throw InputError("--scale: must lie in [1, 16]");
  if (options.transparent && options.scale > 1)
    throw InputError("--transparent: only at scale 1 (the tiled large picture has no alpha)");
  AtomicFile file(path, what);
  // a transparent picture: every renderer's background drawn with alpha 0, for this picture only
  struct Saved {
    vtkRenderer* renderer;
    bool gradient;
    double alpha;
  };
  std::vector<Saved> saved;
  if (options.transparent) {
    auto* renderers = window->GetRenderers();
    renderers->InitTraversal();
    while (vtkRenderer* r = renderers->GetNextItem()) {
      saved.push_back({r, static_cast<bool>(r->GetGradientBackground()), r->GetBackgroundAlpha()});
      r->GradientBackgroundOff();
      r->SetBackgroundAlpha(0.0);
    }
    window->SetAlphaBitPlanes(1);
  }
  vtkNew<vtkPNGWriter> png;
  vtkNew<vtkWindowToImageFilter> grab;
  vtkNew<vtkRenderLargeImage> large;
  if (options.scale > 1) {
    large->SetInput(window->GetRenderers()->GetFirstRenderer());
    large->SetMagnification(options.scale);
    png->SetInputConnection(large->GetOutputPort());
  } else {
    window->Render();
    grab->SetInput(window);
    grab->ShouldRerenderOff();
    grab->ReadFrontBufferOff();
    if (options.transparent)
      grab->SetInputBufferTypeToRGBA();
    else
      grab->SetInputBufferTypeToRGB();
    png->SetInputConnection(grab->GetOutputPort());
  }
  png->SetFileName(file.tempPath().c_str());
  png->Write();
  for (const auto& s : saved) {
    s.renderer->SetGradientBackground(s.gradient);
    s.renderer->SetBackgroundAlpha(s.alpha);
  }
  if (png->GetErrorCode() != 0 || !std::filesystem::exists(file.tempPath()))
    throw ComputationError("cannot write the PNG " + path);
  file.commit();
}

void writePng(const Image& image, const std::string& path) {
  vtkNew<vtkImageData> img;
  img->SetDimensions(image.width, image.height, 1);
  img->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* dst = static_cast<unsigned char*>(img->GetScalarPointer());
  for (int y = 0; y < image.height; ++y)
    std::memcpy(dst + std::size_t(y) * image.width * 3,
                image.rgb.data() + std::size_t(image.height - 1 - y) * image.width * 3,
                std::size_t(image.width) * 3);
  vtkNew<vtkPNGWriter> png;
  png->SetInputData(img);
  png->SetFileName(path.c_str());
  png->Write();
  if (png->GetErrorCode() != 0) throw ComputationError("cannot write the PNG " + path);
}

Image readPng(const std::string& path) {
  if (!std::filesystem::exists(path)) throw ComputationError("no such picture: " + path);
  vtkNew<vtkPNGReader> png;
  png->SetFileName(path.c_str());
  png->Update();
  if (png->GetErrorCode() != 0) throw ComputationError("cannot read the PNG " + path);
  return fromVtk(png->GetOutput());
}

} // namespace rv
