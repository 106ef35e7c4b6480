#include "render/export/Figure.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "dynamics/io/FileNames.h"

#include <filesystem>
#include <mutex>
#include <vtkGL2PSExporter.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>

// The factories of VTK's GL2PS modules (their classes are abstract without them). Registered by hand, once,
// rather than by listing the modules in VTK's autoinit: that would change every target's flags.
void vtkRenderingGL2PSOpenGL2_AutoInit_Construct();
void vtkIOExportGL2PS_AutoInit_Construct();

namespace rv {

const std::vector<std::string>& figureExtensions() {
  static const std::vector<std::string> extensions{".png", ".svg", ".pdf"};
  return extensions;
}

FigureFormat figureFormat(const std::string& path, const std::string& what) {
  if (hasExtension(path, ".png")) return FigureFormat::Png;
  if (hasExtension(path, ".svg")) return FigureFormat::Svg;
  if (hasExtension(path, ".pdf")) return FigureFormat::Pdf;
  throw InputError(what + " " + path + ": unsupported format '" +
                   std::filesystem::path(path).extension().string() +
                   "' (the extension names it; supported: .png, .svg, .pdf)");
}

void writeFigure(vtkRenderWindow* window, const std::string& path, const std::string& what,
                 const SnapshotOptions& options) {
  const FigureFormat format = figureFormat(path, what);
  if (format == FigureFormat::Png) {
    writePng(window, path, what, options);
    return;
  }
  if (options.scale != 1 || options.transparent)
    throw InputError(what + " " + path +
                     ": a scale and a transparent background are for PNG (a vector figure has no pixels)");
  static std::once_flag factories;
  std::call_once(factories, [] {
    vtkRenderingGL2PSOpenGL2_AutoInit_Construct();
    vtkIOExportGL2PS_AutoInit_Construct();
  });
  AtomicFile file(path, what);
  window->Render(); // lays the chart out at the window's size
  vtkSmartPointer<vtkGL2PSExporter> exporter =
      vtkSmartPointer<vtkGL2PSExporter>::Take(vtkGL2PSExporter::New());
  if (!exporter) throw ComputationError("cannot write " + path + ": VTK's GL2PS exporter is not available");
  exporter->SetRenderWindow(window);
  exporter->SetFilePrefix(file.tempPath().c_str()); // it appends the format's extension
  if (format == FigureFormat::Svg)
    exporter->SetFileFormatToSVG();
  else
    exporter->SetFileFormatToPDF();
  exporter->SetCompress(format == FigureFormat::Pdf); // a compressed SVG would be .svgz
  exporter->SetSortToOff();                           // a 2D chart: drawn in order
  exporter->TextAsPathOff();                          // text stays text
  exporter->DrawBackgroundOn(); // (the OpenGL2 backend always draws it, as a picture: most of a PDF's bytes)
  exporter->SilentOn();
  exporter->SetTitle(std::filesystem::path(path).stem().string().c_str());
  exporter->Write();
  const std::string written = file.tempPath() + (format == FigureFormat::Svg ? ".svg" : ".pdf");
  std::error_code ec;
  if (!std::filesystem::exists(written, ec) || std::filesystem::file_size(written, ec) == 0) {
    std::filesystem::remove(written, ec);
    throw ComputationError("cannot write " + path + " (VTK's GL2PS exporter wrote nothing)");
  }
  std::filesystem::rename(written, file.tempPath(), ec);
  if (ec) throw ComputationError("cannot write " + path + ": " + ec.message());
  file.commit();
}

} // namespace rv
