#include "render/export/WebPage.h"

#include "dynamics/core/Errors.h"
#include "dynamics/io/AtomicFile.h"
#include "render/export/WebAssets.h"
#include "render/view/VisualScene.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <nlohmann/json.hpp>
#include <vtkActor.h>
#include <vtkActorCollection.h>
#include <vtkAlgorithm.h>
#include <vtkBase64Utilities.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCellArrayIterator.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkMatrix4x4.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

namespace rv {

namespace {

using json = nlohmann::json;

template <class T> std::string base64(const std::vector<T>& values) {
  const auto bytes = values.size() * sizeof(T);
  std::string out(bytes / 3 * 4 + 8, '\0');
  const auto n = vtkBase64Utilities::Encode(reinterpret_cast<const unsigned char*>(values.data()), bytes,
                                            reinterpret_cast<unsigned char*>(out.data()), 0);
  out.resize(n);
  return out;
}

json colourOf(const double* c) {
  return json::array({c[0], c[1], c[2]});
}

/// One primitive set of an actor as drawn: its vertices with what they carry, and its cells by kind.
struct Geometry {
  std::vector<float> positions, normals, uvs;
  std::vector<std::uint8_t> colours; ///< RGBA per vertex (a mapper's scalars), or empty
  std::vector<std::uint32_t> triangles, segments, points;
  bool strip = false, dots = false; ///< a growing line: every vertex in order, as a line or as dots
  long like = -1; ///< >= 0: all but the positions are those of that geometry (a moving set of lines)

  bool sameButPositions(const Geometry& o) const {
    return normals == o.normals && uvs == o.uvs && colours == o.colours && triangles == o.triangles &&
           segments == o.segments && points == o.points && strip == o.strip && dots == o.dots;
  }

  json toJson() const {
    json g;
    g["positions"] = base64(positions);
    if (like >= 0) {
      g["like"] = like;
      return g;
    }
    if (!normals.empty()) g["normals"] = base64(normals);
    if (!uvs.empty()) g["uvs"] = base64(uvs);
    if (!colours.empty()) g["colours"] = base64(colours);
    if (!triangles.empty()) g["triangles"] = base64(triangles);
    if (!segments.empty()) g["segments"] = base64(segments);
    if (!points.empty()) g["points"] = base64(points);
    if (strip) g["strip"] = true;
    if (dots) g["dots"] = true;
    return g;
  }
};

std::vector<float> pointsOf(vtkPolyData* data) {
  const vtkIdType n = data->GetNumberOfPoints();
  std::vector<float> p(static_cast<std::size_t>(3 * n));
  double q[3];
  for (vtkIdType i = 0; i < n; ++i) {
    data->GetPoint(i, q);
    for (int k = 0; k < 3; ++k)
      p[static_cast<std::size_t>(3 * i + k)] = static_cast<float>(q[k]);
  }
  return p;
}

std::vector<float> tuplesOf(vtkDataArray* a, int components) {
  std::vector<float> v;
  if (!a || a->GetNumberOfComponents() < components) return v;
  v.reserve(static_cast<std::size_t>(components * a->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < a->GetNumberOfTuples(); ++i)
    for (int k = 0; k < components; ++k)
      v.push_back(static_cast<float>(a->GetComponent(i, k)));
  return v;
}

/// Calls `cell(n, ids)` for every cell of `cells`.
template <class F> void forEachCell(vtkCellArray* cells, F&& cell) {
  if (!cells || cells->GetNumberOfCells() == 0) return;
  auto it = vtk::TakeSmartPointer(cells->NewIterator());
  vtkIdType n;
  const vtkIdType* ids;
  for (it->GoToFirstCell(); !it->IsDoneWithTraversal(); it->GoToNextCell()) {
    it->GetCurrentCell(n, ids);
    cell(n, ids);
  }
}

/// The actor's polygonal data as a Geometry: polygons as fans, strips as triangles, polylines as segments.
Geometry snapshot(vtkActor* actor, vtkPolyDataMapper* mapper, vtkPolyData* data) {
  Geometry g;
  g.positions = pointsOf(data);
  const vtkIdType n = data->GetNumberOfPoints();
  g.normals = tuplesOf(data->GetPointData()->GetNormals(), 3);
  if (actor->GetTexture()) g.uvs = tuplesOf(data->GetPointData()->GetTCoords(), 2);
  if (mapper->GetScalarVisibility() && data->GetPointData()->GetScalars() &&
      mapper->GetScalarMode() != VTK_SCALAR_MODE_USE_CELL_DATA &&
      mapper->GetScalarMode() != VTK_SCALAR_MODE_USE_CELL_FIELD_DATA)
    if (vtkUnsignedCharArray* c = mapper->MapScalars(1.0);
        c && c->GetNumberOfTuples() == n && c->GetNumberOfComponents() == 4)
      g.colours.assign(c->GetPointer(0), c->GetPointer(0) + 4 * n);
  const auto id = [](vtkIdType i) { return static_cast<std::uint32_t>(i); };
  forEachCell(data->GetPolys(), [&](vtkIdType m, const vtkIdType* ids) {
    for (vtkIdType k = 1; k + 1 < m; ++k)
      g.triangles.insert(g.triangles.end(), {id(ids[0]), id(ids[k]), id(ids[k + 1])});
  });
  forEachCell(data->GetStrips(), [&](vtkIdType m, const vtkIdType* ids) {
    for (vtkIdType k = 0; k + 2 < m; ++k)
      if (k % 2 == 0)
        g.triangles.insert(g.triangles.end(), {id(ids[k]), id(ids[k + 1]), id(ids[k + 2])});
      else
        g.triangles.insert(g.triangles.end(), {id(ids[k + 1]), id(ids[k]), id(ids[k + 2])});
  });
  forEachCell(data->GetLines(), [&](vtkIdType m, const vtkIdType* ids) {
    for (vtkIdType k = 0; k + 1 < m; ++k)
      g.segments.insert(g.segments.end(), {id(ids[k]), id(ids[k + 1])});
  });
  forEachCell(data->GetVerts(), [&](vtkIdType m, const vtkIdType* ids) {
    for (vtkIdType k = 0; k < m; ++k)
      g.points.push_back(id(ids[k]));
  });
  return g;
}

/// A texture's image as a PNG data URI.
std::string textureUri(vtkTexture* texture) {
  if (auto* source = texture->GetInputAlgorithm()) source->Update();
  auto* image = vtkImageData::SafeDownCast(texture->GetInput());
  if (!image) return {};
  vtkNew<vtkPNGWriter> png;
  png->WriteToMemoryOn();
  png->SetInputData(image);
  png->Write();
  auto* bytes = png->GetResult();
  if (!bytes || bytes->GetNumberOfTuples() == 0) return {};
  const auto* p = bytes->GetPointer(0);
  return "data:image/png;base64," + base64(std::vector<std::uint8_t>(p, p + bytes->GetNumberOfTuples()));
}

/// The appearance of an actor as the page's materials take it.
json materialOf(vtkActor* actor, int texture) {
  auto* p = actor->GetProperty();
  json m{{"colour", colourOf(p->GetColor())},
         {"opacity", p->GetOpacity()},
         {"specular", p->GetSpecular()},
         {"shininess", p->GetSpecularPower()},
         {"lit", p->GetLighting() && p->GetAmbient() < 1},
         {"wireframe", p->GetRepresentation() == VTK_WIREFRAME},
         {"lineWidth", p->GetLineWidth()},
         {"pointSize", p->GetPointSize()}};
  if (texture >= 0) {
    m["texture"] = texture;
    m["repeat"] = actor->GetTexture()->GetRepeat() != 0;
  }
  return m;
}

/// What one actor shows over the frames. A version is a stretch of frames with one geometry: static (a
/// mesh placed by its matrix), or growing (a trace: the vertices it has at the stretch's end, of which the
/// first counts[k] are shown at frame k, the last of them replaced by ends[k], the line's moving end).
struct Track {
  struct Version {
    long from = 0;
    std::size_t geometry = 0;
    bool growing = false;
    std::vector<std::uint32_t> counts;
    std::vector<float> ends;
  };
  std::string name;
  vtkActor* actor = nullptr;
  int texture = -1;
  std::vector<Version> versions;
  std::vector<float> matrices; ///< 16 per frame, column-major (three.js's order)
  std::vector<std::uint8_t> visible;
  vtkPolyData* data = nullptr;
  vtkMTimeType seen = 0;
  std::vector<float> last; ///< the vertices at the previous frame
};

class Recorder {
public:
  explicit Recorder(const VisualScene& scene) : scene_(scene) {
    for (const auto& object : scene.objects())
      for (vtkProp* prop : scene.props(object->name())) {
        auto* actor = vtkActor::SafeDownCast(prop);
        if (!actor || !vtkPolyDataMapper::SafeDownCast(actor->GetMapper())) continue;
        Track t;
        const auto count = std::count_if(tracks_.begin(), tracks_.end(), [&](const Track& u) {
          return u.name.rfind(object->name(), 0) == 0;
        });
        t.name = count == 0 ? object->name() : object->name() + "#" + std::to_string(count);
        t.actor = actor;
        tracks_.push_back(std::move(t));
      }
  }

  void record(long frame, double t, const Eigen::VectorXd& x) {
    times_.push_back(t);
    states_.insert(states_.end(), x.data(), x.data() + x.size());
    energy_.push_back(scene_.energyError().value_or(std::nan("")));
    auto* camera = scene_.renderer()->GetActiveCamera();
    for (const double* v : {camera->GetPosition(), camera->GetFocalPoint(), camera->GetViewUp()})
      for (int k = 0; k < 3; ++k)
        camera_.push_back(static_cast<float>(v[k]));
    if (frame == 0) viewAngle_ = camera->GetViewAngle();
    for (auto& track : tracks_)
      observe(track, frame);
  }

  json finish() {
    json actors = json::array();
    for (auto& track : tracks_) {
      if (!track.versions.empty() && track.versions.back().growing) finishGrowing(track);
      json a{{"name", track.name}, {"material", materialOf(track.actor, track.texture)}};
      json versions = json::array();
      for (const auto& v : track.versions) {
        json j{{"from", v.from}, {"geometry", v.geometry}};
        if (v.growing) j["counts"] = base64(v.counts), j["ends"] = base64(v.ends);
        versions.push_back(std::move(j));
      }
      a["versions"] = std::move(versions);
      a["matrices"] = base64(constantOrAll(track.matrices, 16));
      a["visible"] = base64(constantOrAll(track.visible, 1));
      actors.push_back(std::move(a));
    }
    json geometries = json::array();
    for (const auto& g : geometries_)
      geometries.push_back(g.toJson());
    auto* r = scene_.renderer();
    json d{{"frames", times_.size()},
           {"t", base64(times_)},
           {"x", base64(states_)},
           {"energyError", base64(energy_)},
           {"camera", {{"angle", viewAngle_}, {"frames", base64(camera_)}}},
           {"background", colourOf(r->GetBackground())},
           {"textures", textures_},
           {"geometries", std::move(geometries)},
           {"actors", std::move(actors)}};
    if (r->GetGradientBackground()) d["background2"] = colourOf(r->GetBackground2());
    return d;
  }

private:
  /// The same value at every frame is written once.
  template <class T> static std::vector<T> constantOrAll(const std::vector<T>& v, std::size_t width) {
    for (std::size_t i = width; i < v.size(); ++i)
      if (v[i] != v[i % width]) return v;
    return {v.begin(), v.begin() + static_cast<std::ptrdiff_t>(std::min(width, v.size()))};
  }

  void observe(Track& track, long frame) {
    auto* actor = track.actor;
    double m[16];
    vtkMatrix4x4::DeepCopy(m, actor->GetMatrix());
    for (int c = 0; c < 4; ++c)
      for (int r = 0; r < 4; ++r)
        track.matrices.push_back(static_cast<float>(m[4 * r + c]));
    track.visible.push_back(actor->GetVisibility() ? 1 : 0);
    auto* mapper = vtkPolyDataMapper::SafeDownCast(actor->GetMapper());
    if (auto* source = mapper->GetInputAlgorithm()) source->Update();
    vtkPolyData* data = mapper->GetInput();
    if (!data) data = empty_;
    if (track.texture < 0 && actor->GetTexture()) track.texture = textureIndex(actor->GetTexture());
    if (data != track.data || data->GetMTime() != track.seen) {
      std::vector<float> now = pointsOf(data);
      if (track.versions.empty() || data != track.data) {
        open(track, frame, data);
      } else if (now != track.last) {
        auto& v = track.versions.back();
        const std::size_t before = track.last.size();
        // a trace grows: the vertices it had stay, but for the moving end
        const bool prefix = now.size() >= before && before >= 3 &&
                            std::equal(track.last.begin(), track.last.end() - 3, now.begin());
        if (prefix && (v.growing || now.size() > before))
          v.growing = true;
        else {
          if (v.growing) finishGrowing(track);
          open(track, frame, data);
        }
      }
      track.last = std::move(now);
      track.data = data;
      track.seen = data->GetMTime();
    }
    auto& v = track.versions.back();
    const auto n = track.last.size() / 3;
    v.counts.push_back(static_cast<std::uint32_t>(n));
    for (int k = 0; k < 3; ++k)
      v.ends.push_back(n > 0 ? track.last[3 * (n - 1) + static_cast<std::size_t>(k)] : 0.0F);
  }

  void open(Track& track, long frame, vtkPolyData* data) {
    auto* mapper = vtkPolyDataMapper::SafeDownCast(track.actor->GetMapper());
    Geometry g = snapshot(track.actor, mapper, data);
    if (!track.versions.empty()) { // the same lines moved: only the positions are new
      const auto previous = track.versions.back().geometry;
      const auto base =
          geometries_[previous].like >= 0 ? static_cast<std::size_t>(geometries_[previous].like) : previous;
      if (g.sameButPositions(geometries_[base]))
        g = {.positions = std::move(g.positions), .like = long(base)};
    }
    geometries_.push_back(std::move(g));
    track.versions.push_back({.from = frame, .geometry = geometries_.size() - 1});
  }

  /// A growing version's geometry becomes the vertices it reached, in order.
  void finishGrowing(Track& track) {
    auto& g = geometries_[track.versions.back().geometry];
    const Geometry& cells = g.like >= 0 ? geometries_[static_cast<std::size_t>(g.like)] : g;
    g.dots = cells.segments.empty() && !cells.points.empty();
    g.strip = !g.dots;
    g.like = -1;
    g.positions = track.last;
    g.normals.clear(), g.uvs.clear(), g.colours.clear();
    g.triangles.clear(), g.segments.clear(), g.points.clear();
  }

  int textureIndex(vtkTexture* texture) {
    for (std::size_t i = 0; i < textureSources_.size(); ++i)
      if (textureSources_[i] == texture) return static_cast<int>(i);
    textureSources_.push_back(texture);
    textures_.push_back(textureUri(texture));
    return static_cast<int>(textures_.size() - 1);
  }

  const VisualScene& scene_;
  std::vector<Track> tracks_;
  std::vector<Geometry> geometries_;
  std::vector<vtkTexture*> textureSources_;
  json textures_ = json::array();
  std::vector<double> times_, states_, energy_;
  std::vector<float> camera_;
  double viewAngle_ = 30;
  vtkNew<vtkPolyData> empty_;
};

json mapJson(const PageMap& map) {
  json series = json::array();
  for (const auto& s : map.series) {
    const char* kind = s.kind == PageMapSeries::Kind::Curve     ? "curve"
                       : s.kind == PageMapSeries::Kind::Markers ? "markers"
                                                                : "points";
    series.push_back({{"kind", kind},
                      {"colour", json::array({s.colour[0], s.colour[1], s.colour[2]})},
                      {"x", base64(s.x)},
                      {"y", base64(s.y)}});
  }
  return {{"x", map.xName}, {"y", map.yName}, {"series", std::move(series)}};
}

std::string htmlEscaped(const std::string& s) {
  std::string out;
  for (const char c : s)
    switch (c) {
    case '&':
      out += "&amp;";
      break;
    case '<':
      out += "&lt;";
      break;
    case '>':
      out += "&gt;";
      break;
    case '"':
      out += "&quot;";
      break;
    default:
      out += c;
    }
  return out;
}

/// `</` inside a script element would end it: JSON may write it `<\/`.
std::string scriptSafe(std::string s) {
  for (std::size_t i = 0; (i = s.find("</", i)) != std::string::npos; i += 3)
    s.replace(i, 2, "<\\/");
  return s;
}

} // namespace

long writeWebPage(VisualScene& scene, Integrator& integrator, const PageSpec& spec,
                  const std::function<bool(long, long)>& progress) {
  if (!(spec.fps >= 1 && std::isfinite(spec.duration) && spec.duration > 0 && std::isfinite(spec.speed) &&
        spec.speed > 0))
    throw InputError("page: needs fps >= 1, a positive duration and a positive speed");
  AtomicFile file(spec.path, "-o");
  const long total = std::lround(spec.duration * spec.fps) + 1;
  Recorder recorder(scene);
  const double t0 = integrator.time();
  Eigen::VectorXd x(integrator.state().size());
  for (long k = 0; k < total; ++k) {
    if (progress && !progress(k, total)) return 0;
    const double t = t0 + integrator.direction() * spec.speed * static_cast<double>(k) / spec.fps;
    playTo(scene, integrator, t, x);
    recorder.record(k, t, x);
  }
  json data = recorder.finish();
  data["fps"] = spec.fps;
  data["speed"] = spec.speed;
  data["title"] = spec.title;
  data["description"] = spec.description;
  data["variables"] = spec.variables;
  data["parameters"] = json::array();
  for (const auto& [name, value] : spec.parameters)
    data["parameters"].push_back({name, value});
  if (spec.map) data["map"] = mapJson(*spec.map);

  std::string page(webAsset(WebAsset::PageHtml));
  const auto put = [&](const std::string& marker, const std::string& text) {
    const auto at = page.find(marker);
    if (at == std::string::npos) throw ComputationError("page: the template lacks " + marker);
    page.replace(at, marker.size(), text);
  };
  put("@TITLE@", htmlEscaped(spec.title.empty() ? "rollviz" : spec.title));
  put("@SCRIPTS@", "<script>" + std::string(webAsset(WebAsset::ThreeJs)) + "</script>\n<script>" +
                       std::string(webAsset(WebAsset::OrbitControls)) +
                       "</script>\n<script type=\"application/json\" id=\"rollviz-data\">" +
                       scriptSafe(data.dump()) + "</script>\n<script>" +
                       std::string(webAsset(WebAsset::PageJs)) + "</script>");
  {
    std::ofstream out(file.tempPath(), std::ios::binary);
    out << page;
    if (!out.flush()) throw ComputationError("page: cannot write " + spec.path);
  }
  file.commit();
  return total;
}

} // namespace rv
