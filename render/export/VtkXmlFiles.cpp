#include "render/export/VtkXmlFiles.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "render/view/VisualScene.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <filesystem>
#include <regex>
#include <unistd.h>
#include <vtkActor.h>
#include <vtkCellArray.h>
#include <vtkDoubleArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkInformation.h>
#include <vtkMapper.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkStringArray.h>
#include <vtkTransform.h>
#include <vtkTransformFilter.h>
#include <vtkXMLImageDataWriter.h>
#include <vtkXMLMultiBlockDataWriter.h>
#include <vtkXMLPolyDataWriter.h>

namespace fs = std::filesystem;

namespace rv {

namespace {

vtkSmartPointer<vtkDoubleArray> toArray(const std::string& name, const std::vector<double>& values) {
  auto a = vtkSmartPointer<vtkDoubleArray>::New();
  a->SetName(name.c_str());
  a->SetNumberOfValues(static_cast<vtkIdType>(values.size()));
  for (std::size_t k = 0; k < values.size(); ++k)
    a->SetValue(static_cast<vtkIdType>(k), values[k]);
  return a;
}

// writes through a temporary name: a failed write leaves nothing behind
template <class Writer>
void writeAtomically(Writer* writer, const std::string& path, const std::string& what) {
  AtomicFile file(path, what);
  writer->SetFileName(file.tempPath().c_str());
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1) throw ComputationError("cannot write " + path);
  file.commit();
}

} // namespace

void writePolyDataVtp(const std::string& path, const NamedColumns& columns, std::array<int, 3> xyz, bool line,
                      const std::string& what) {
  const vtkIdType n = columns.rows();
  auto points = vtkSmartPointer<vtkPoints>::New();
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(n);
  for (vtkIdType k = 0; k < n; ++k) {
    double p[3] = {0, 0, 0};
    for (int a = 0; a < 3; ++a)
      if (xyz[a] >= 0 && static_cast<std::size_t>(xyz[a]) < columns.values.size())
        p[a] = columns.values[xyz[a]][k];
    points->SetPoint(k, p);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  auto cells = vtkSmartPointer<vtkCellArray>::New();
  if (line) {
    if (n > 0) {
      cells->InsertNextCell(n);
      for (vtkIdType k = 0; k < n; ++k)
        cells->InsertCellPoint(k);
    }
    poly->SetLines(cells);
  } else {
    for (vtkIdType k = 0; k < n; ++k) {
      cells->InsertNextCell(1);
      cells->InsertCellPoint(k);
    }
    poly->SetVerts(cells);
  }
  for (std::size_t c = 0; c < columns.names.size(); ++c)
    poly->GetPointData()->AddArray(
        toArray(columns.names[c], c < columns.values.size() ? columns.values[c] : std::vector<double>{}));
  auto writer = vtkSmartPointer<vtkXMLPolyDataWriter>::New();
  writer->SetInputData(poly);
  writeAtomically(writer.Get(), path, what);
}

void writeImageVti(const std::string& path, const ImageGrid& grid, const std::string& what) {
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(grid.size[0], grid.size[1], grid.size[2]);
  image->SetOrigin(grid.origin[0], grid.origin[1], grid.origin[2]);
  image->SetSpacing(grid.spacing[0], grid.spacing[1], grid.spacing[2]);
  const std::size_t nodes = static_cast<std::size_t>(grid.size[0]) * grid.size[1] * grid.size[2];
  for (std::size_t c = 0; c < grid.arrays.names.size(); ++c) {
    const auto& v = grid.arrays.values.at(c);
    if (v.size() != nodes)
      throw ComputationError("writeImageVti: array " + grid.arrays.names[c] + " has the wrong size");
    image->GetPointData()->AddArray(toArray(grid.arrays.names[c], v));
  }
  if (!grid.axisNames.empty()) {
    auto axes = vtkSmartPointer<vtkStringArray>::New();
    axes->SetName("axes");
    for (const auto& a : grid.axisNames)
      axes->InsertNextValue(a);
    image->GetFieldData()->AddArray(axes);
  }
  auto writer = vtkSmartPointer<vtkXMLImageDataWriter>::New();
  writer->SetInputData(image);
  writeAtomically(writer.Get(), path, what);
}

void writeSceneVtm(const VisualScene& scene, const std::string& path, const std::string& what) {
  checkWritable(path, what);
  auto blocks = vtkSmartPointer<vtkMultiBlockDataSet>::New();
  unsigned block = 0;
  for (const auto& object : scene.objects()) {
    int piece = 0;
    for (vtkProp* prop : scene.props(object->name())) {
      auto* actor = vtkActor::SafeDownCast(prop);
      if (!actor || !actor->GetVisibility() || !actor->GetMapper()) continue;
      actor->GetMapper()->Update();
      vtkDataSet* data = actor->GetMapper()->GetInputAsDataSet();
      if (!data || data->GetNumberOfPoints() == 0) continue;
      // the actor's placement (body pose, scale) applied: ParaView shows the pieces where the view does
      auto transform = vtkSmartPointer<vtkTransform>::New();
      transform->SetMatrix(actor->GetMatrix());
      auto moved = vtkSmartPointer<vtkTransformFilter>::New();
      moved->SetTransform(transform);
      moved->SetInputData(data);
      moved->Update();
      vtkSmartPointer<vtkDataSet> out = vtkDataSet::SafeDownCast(moved->GetOutput());
      if (!out) continue;
      out = vtkSmartPointer<vtkDataSet>::Take(out->NewInstance());
      out->DeepCopy(moved->GetOutput());
      auto colour = vtkSmartPointer<vtkDoubleArray>::New();
      colour->SetName("color");
      colour->SetNumberOfComponents(3);
      colour->InsertNextTuple(actor->GetProperty()->GetColor());
      out->GetFieldData()->AddArray(colour);
      blocks->SetBlock(block, out);
      const std::string name = piece ? object->name() + "_" + std::to_string(piece) : object->name();
      blocks->GetMetaData(block)->Set(vtkCompositeDataSet::NAME(), name.c_str());
      ++block, ++piece;
    }
  }
  if (block == 0) throw ComputationError("the scene shows nothing to export");
  // the writer puts the pieces into a folder named after the file: write both in a temporary folder, then
  // move the pieces' folder and, last, the .vtm into place
  const fs::path target(path);
  const fs::path stem = target.stem();
  const fs::path dir = target.parent_path().empty() ? fs::path(".") : target.parent_path();
  // a folder of the same name is replaced only when it holds nothing but an earlier export's pieces
  // (the writer names them STEM_N[_M].vtX), and only once the new export is complete
  const fs::path pieces = dir / stem;
  const std::regex piece(std::regex_replace(stem.string(), std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)") +
                         R"(_\d+(_\d+)*\.vt[a-z]+)");
  if (fs::is_directory(pieces)) {
    bool any = false;
    for (const auto& e : fs::directory_iterator(pieces)) {
      any = true;
      if (!e.is_regular_file() || !std::regex_match(e.path().filename().string(), piece))
        throw InputError(what + " " + path + ": the folder " + pieces.string() +
                         " exists and is not an earlier export's: the pieces go there");
    }
    if (!any)
      throw InputError(what + " " + path + ": the empty folder " + pieces.string() +
                       " exists: the pieces go there (remove it)");
  } else if (fs::exists(pieces)) {
    throw InputError(what + " " + path + ": " + pieces.string() + " exists: the pieces' folder goes there");
  }
  static std::atomic<int> calls{0}; // one temporary folder per call: exports may run on several threads
  const fs::path temp = dir / (".rollviz-vtm-" + std::to_string(::getpid()) + "-" + std::to_string(calls++) +
                               "-" + stem.string());
  std::error_code ec;
  fs::remove_all(temp, ec);
  fs::create_directories(temp, ec);
  if (ec) throw InputError(what + " " + path + ": cannot write there (" + ec.message() + ")");
  struct Cleanup {
    fs::path dir;
    ~Cleanup() {
      std::error_code e;
      fs::remove_all(dir, e);
    }
  } cleanup{temp};
  auto writer = vtkSmartPointer<vtkXMLMultiBlockDataWriter>::New();
  writer->SetInputData(blocks);
  writer->SetFileName((temp / target.filename()).c_str());
  writer->SetDataModeToBinary();
  writer->SetCompressorTypeToZLib();
  if (writer->Write() != 1) throw ComputationError("cannot write " + path);
  // the earlier pieces step aside into the temporary folder (removed with it), the new ones and the .vtm come
  // in
  if (fs::exists(pieces)) fs::rename(pieces, temp / "earlier", ec);
  if (!ec) fs::rename(temp / stem, pieces, ec);
  if (!ec) fs::rename(temp / target.filename(), target, ec);
  if (ec) {
    std::error_code back;
    if (!fs::exists(pieces) && fs::exists(temp / "earlier")) fs::rename(temp / "earlier", pieces, back);
    throw ComputationError("cannot write " + path + ": " + ec.message());
  }
}

} // namespace rv
