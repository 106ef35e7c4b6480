// VtkXmlFiles.h -- results as VTK XML files for ParaView (and VTK's Python readers), written by VTK's own
// writers through a temporary name: tables of samples as polylines or point clouds (.vtp), grids as image
// data (.vti), the 3D view as a multiblock of its pieces in world coordinates (.vtm). The command line picks
// them by the output's extension.
#pragma once
#include <array>
#include <string>
#include <vector>

namespace rv {

class VisualScene;

/// Columns of samples of equal length, each named.
struct NamedColumns {
  std::vector<std::string> names;
  std::vector<std::vector<double>> values; ///< values[c][k]: column c at sample k
  /// Appends one row (one value per column). Inline: VTK-free code (the fuzzers' scenes) builds tables too.
  void addRow(const std::vector<double>& row) {
    if (values.size() < row.size()) values.resize(row.size());
    for (std::size_t c = 0; c < row.size(); ++c)
      values[c].push_back(row[c]);
  }
  long rows() const { return values.empty() ? 0 : static_cast<long>(values[0].size()); }
  /// Row k: each column's value at sample k.
  std::vector<double> row(long k) const {
    std::vector<double> r;
    r.reserve(values.size());
    for (const auto& column : values)
      r.push_back(column[static_cast<std::size_t>(k)]);
    return r;
  }
};

/// Writes the samples as poly data: every column a point-data array; the points' coordinates are the
/// columns `xyz` (an index of -1 gives 0); a polyline through them in order (`line`), else one vertex per
/// sample. InputError naming `what` when the path cannot be written, ComputationError when writing fails.
void writePolyDataVtp(const std::string& path, const NamedColumns& columns, std::array<int, 3> xyz, bool line,
                      const std::string& what = "-o");

/// A regular grid's values: size[0] x size[1] x size[2] nodes at origin + (i, j, k) * spacing, x fastest.
struct ImageGrid {
  std::array<int, 3> size{1, 1, 1};
  std::array<double, 3> origin{0, 0, 0}, spacing{1, 1, 1};
  std::vector<std::string> axisNames; ///< what x, y, z are (kept as field data "axes")
  NamedColumns arrays;                ///< point data, one value per node
};

/// Writes image data (.vti) with every array as point data.
void writeImageVti(const std::string& path, const ImageGrid& grid, const std::string& what = "-o");

/// Writes the scene's visible 3D pieces (bodies, plane, traces, axes' lines) as a multiblock (.vtm) named
/// after its objects, in world coordinates, each with its colour as field data. The pieces go into a folder
/// named after the file (ParaView's layout: view.vtm + view/*.vtp); the .vtm appears last.
void writeSceneVtm(const VisualScene& scene, const std::string& path, const std::string& what = "-o");

} // namespace rv
