#include "scenes/ModelFile.h"

#include "dynamics/core/Errors.h"
#include "dynamics/models/EquationModel.h"
#include "scenes/JsonFields.h"
#include "scenes/ModelCompiler.h"
#include "scenes/RollingModel.h"

#include <algorithm>
#include <atomic>
#include <cctype>
#include <cstdio>
#include <filesystem>
#include <functional>
#include <list>
#include <mutex>
#include <sstream>
#include <thread>

namespace rv {

using nlohmann::json;
using nlohmann::ordered_json;

namespace {

// The file's own order of keys (nlohmann::json sorts them): parameters and observables are listed as written.
class Reader {
public:
  Reader(const json& doc, const ordered_json* ordered, std::string source)
      : doc_(doc), ordered_(ordered), source_(std::move(source)) {}

  EquationModelSpec read() {
    const Where root{source_, ""};
    requireObject(doc_, root);
    onlyKeys(doc_, root,
             {"id", "title", "reference", "description", "kind", "parameters", "state", "vectors",
              "definitions", "equations", "observables", "integrals", "measure", "section", "complete", "map",
              "view", "initial"});
    EquationModelSpec s;
    s.source = source_;
    ModelInfo& info = s.info;
    if (!doc_.contains("id")) root.fail("missing \"id\" (the model's name in lists and scenes)");
    info.id = text(doc_["id"], root / "id");
    if (info.id.empty() || info.id.find_first_of(" \t\n/\\\"'") != std::string::npos)
      (root / "id").fail("an id is one word (letters, digits, '_' and '-')");
    if (const ModelEntry* taken = ModelRegistry::global().find(info.id))
      (root / "id")
          .fail("the id '" + info.id + "' is taken by " +
                (taken->origin.empty() ? "a built-in model" : "the module " + taken->origin) +
                ": a model file needs an id of its own");
    info.title = doc_.contains("title") ? text(doc_["title"], root / "title") : info.id;
    if (doc_.contains("reference")) info.reference = text(doc_["reference"], root / "reference");
    if (doc_.contains("kind")) {
      const std::string kind = text(doc_["kind"], root / "kind");
      if (kind != "flow" && kind != "map") (root / "kind").fail("expected \"flow\" or \"map\"");
      info.kind = kind == "map" ? ModelKind::Map : ModelKind::Flow;
    }
    readParameterTable(s, root / "parameters");
    if (!doc_.contains("state")) root.fail("missing \"state\" (the names of the state variables, in order)");
    const json& st = doc_["state"];
    if (!st.is_array() || st.empty()) (root / "state").fail("expected an array of names");
    for (std::size_t i = 0; i < st.size(); ++i)
      info.stateNames.push_back(text(st[i], root / "state" / std::to_string(i)));
    if (doc_.contains("vectors"))
      forEach({"vectors"}, root / "vectors", [&](const std::string& name, const json& v, const Where& w) {
        if (!v.is_array()) w.fail("expected an array of state variable names");
        std::vector<std::string> components;
        for (std::size_t i = 0; i < v.size(); ++i)
          components.push_back(text(v[i], w / std::to_string(i)));
        s.vectors.emplace_back(name, components);
      });
    if (doc_.contains("definitions")) s.definitions = texts({"definitions"}, root / "definitions");
    if (!doc_.contains("equations"))
      root.fail(std::string("missing \"equations\" (") +
                (info.kind == ModelKind::Map ? "the next value" : "d/dt") + " of each state variable)");
    s.equations = texts({"equations"}, root / "equations");
    readObservables(s, root);
    if (doc_.contains("measure")) s.measure = exprText(doc_["measure"], root / "measure");
    readSection(s, root / "section");
    if (doc_.contains("complete")) s.completion = texts({"complete"}, root / "complete");
    if (doc_.contains("map")) readMap(s, root / "map");
    if (doc_.contains("view")) readView(s, root / "view");
    return s;
  }

private:
  // calls f(key, value, where) for the members of the object at `keys` (from the root), in the file's order
  void forEach(const std::vector<std::string>& keys, const Where& w,
               const std::function<void(const std::string&, const json&, const Where&)>& f) {
    const json* j = &doc_;
    const ordered_json* o = ordered_;
    for (const auto& k : keys) {
      j = &j->at(k);
      o = o && o->is_object() && o->contains(k) ? &o->at(k) : nullptr;
    }
    requireObject(*j, w);
    std::vector<std::string> order;
    if (o && o->is_object())
      for (const auto& item : o->items())
        order.push_back(item.key());
    else
      for (const auto& item : j->items())
        order.push_back(item.key());
    for (const auto& k : order)
      if (j->contains(k)) f(k, j->at(k), w / k);
  }
  ExprText exprText(const json& j, const Where& w) const {
    if (j.is_number()) return {shown(j), w.path}; // a constant written as a number
    return {text(j, w), w.path};
  }
  std::vector<std::pair<std::string, ExprText>> texts(const std::vector<std::string>& keys, const Where& w) {
    std::vector<std::pair<std::string, ExprText>> out;
    forEach(keys, w, [&](const std::string& k, const json& v, const Where& at) {
      out.emplace_back(k, exprText(v, at));
    });
    return out;
  }

  void readParameterTable(EquationModelSpec& s, const Where& w) {
    std::vector<ParameterSpec> specs;
    if (doc_.contains("parameters"))
      forEach({"parameters"}, w, [&](const std::string& id, const json& v, const Where& at) {
        ParameterSpec p{.id = id, .label = id};
        if (v.is_number()) {
          p.defaultValue = v.get<double>();
        } else {
          requireObject(v, at);
          onlyKeys(v, at, {"default", "min", "max", "label", "description", "unit", "integer"});
          if (!v.contains("default")) at.fail("missing \"default\"");
          p.defaultValue = number(v["default"], at / "default");
          if (v.contains("min")) p.min = number(v["min"], at / "min");
          if (v.contains("max")) p.max = number(v["max"], at / "max");
          if (v.contains("label")) p.label = text(v["label"], at / "label");
          if (v.contains("description")) p.description = text(v["description"], at / "description");
          if (v.contains("unit")) p.unit = text(v["unit"], at / "unit");
          if (v.contains("integer")) p.integer = boolean(v["integer"], at / "integer");
        }
        if (!(p.min <= p.defaultValue && p.defaultValue <= p.max))
          at.fail("the default lies outside [min, max]");
        specs.push_back(std::move(p));
      });
    s.info.parameters = ParameterTable(std::move(specs));
  }

  void readObservables(EquationModelSpec& s, const Where& root) {
    if (doc_.contains("observables"))
      forEach({"observables"}, root / "observables",
              [&](const std::string& id, const json& v, const Where& at) {
                EquationModelSpec::ObservableText o{.id = id};
                if (v.is_object()) {
                  onlyKeys(v, at, {"value", "description", "angle", "integral"});
                  if (!v.contains("value")) at.fail("missing \"value\" (its expression)");
                  o.value = exprText(v["value"], at / "value");
                  if (v.contains("description")) o.description = text(v["description"], at / "description");
                  if (v.contains("angle")) o.angle = boolean(v["angle"], at / "angle");
                  if (v.contains("integral")) o.integral = boolean(v["integral"], at / "integral");
                } else {
                  o.value = exprText(v, at);
                }
                if (o.description.empty()) o.description = o.value.text.substr(0, 60);
                s.observables.push_back(std::move(o));
              });
    if (!doc_.contains("integrals")) return;
    const Where w = root / "integrals";
    const json& j = doc_["integrals"];
    if (!j.is_array()) w.fail("expected an array of observable ids");
    for (std::size_t i = 0; i < j.size(); ++i) {
      const std::string id = text(j[i], w / std::to_string(i));
      auto it =
          std::find_if(s.observables.begin(), s.observables.end(), [&](const auto& o) { return o.id == id; });
      if (it == s.observables.end())
        (w / std::to_string(i)).fail("'" + id + "' is not one of the \"observables\"");
      it->integral = true;
    }
  }

  void readSection(EquationModelSpec& s, const Where& w) {
    if (!doc_.contains("section")) return;
    const json& j = doc_["section"];
    if (j.is_string()) {
      s.info.section = j.get<std::string>();
      return;
    }
    requireObject(j, w);
    onlyKeys(j, w, {"observable", "time"});
    if (j.contains("observable") == j.contains("time"))
      w.fail("give \"observable\" (a level set) or \"time\" (the period of a stroboscopic section)");
    if (j.contains("observable"))
      s.info.section = text(j["observable"], w / "observable");
    else
      s.strobePeriod = exprText(j["time"], w / "time");
  }

  void readMap(EquationModelSpec& s, const Where& w) {
    const json& j = requireObject(doc_["map"], w);
    onlyKeys(j, w, {"coordinates", "symbols", "state", "solve"});
    EquationModelSpec::MapCompletion m;
    const auto names = [&](const char* key) {
      std::vector<std::string> out;
      const json& a = j[key];
      if (!a.is_array() || a.empty()) (w / key).fail("expected an array of names");
      for (std::size_t i = 0; i < a.size(); ++i)
        out.push_back(text(a[i], w / key / std::to_string(i)));
      return out;
    };
    if (!j.contains("coordinates")) w.fail("missing \"coordinates\" (the observables a map point gives)");
    s.info.mapCoordinates = names("coordinates");
    m.symbols = j.contains("symbols") ? names("symbols") : s.info.mapCoordinates;
    if (!j.contains("state")) w.fail("missing \"state\" (each state variable from the coordinates)");
    m.state = texts({"map", "state"}, w / "state");
    if (j.contains("solve")) {
      const Where ws = w / "solve";
      const json& v = requireObject(j["solve"], ws);
      onlyKeys(v, ws, {"unknown", "observable", "value", "from", "to", "step", "accuracy"});
      for (const char* k : {"unknown", "observable", "value", "from", "to", "step"})
        if (!v.contains(k)) ws.fail(std::string("missing \"") + k + "\"");
      m.unknown = text(v["unknown"], ws / "unknown");
      m.integral = text(v["observable"], ws / "observable");
      m.value = exprText(v["value"], ws / "value");
      m.from = exprText(v["from"], ws / "from");
      m.to = exprText(v["to"], ws / "to");
      m.step = exprText(v["step"], ws / "step");
      if (v.contains("accuracy")) m.accuracy = number(v["accuracy"], ws / "accuracy");
    }
    s.map = std::move(m);
  }

  /// A drawn shape: `key` names it ("none" and `extra` allowed besides), its sizes are the object's keys.
  EquationModelSpec::Shape readShape(const json& j, const Where& w, const char* key,
                                     const std::vector<std::pair<std::string, BodyShape>>& names) {
    EquationModelSpec::Shape shape;
    const std::string name = j.contains(key) ? text(j[key], w / key) : names.front().first;
    std::string expected;
    bool found = false;
    for (const auto& [n, kind] : names) {
      expected += (expected.empty() ? "\"" : ", \"") + n + "\"";
      if (n == name) shape.shape = kind, found = true;
    }
    if (!found) (w / key).fail("expected one of " + expected);
    const auto optional = [&](const char* k) -> std::optional<ExprText> {
      if (!j.contains(k)) return std::nullopt;
      return exprText(j[k], w / k);
    };
    shape.semiAxes = shape.shape == BodyShape::Ball ? optional("radius") : optional("semi_axes");
    shape.centre = optional("centre");
    shape.p = optional("p");
    shape.q = optional("q");
    shape.height = optional("height");
    return shape;
  }

  void readView(EquationModelSpec& s, const Where& w) {
    const json& j = requireObject(doc_["view"], w);
    onlyKeys(j, w,
             {"body", "radius", "semi_axes", "centre", "p", "q", "height", "mesh", "scale", "F", "size",
              "support", "rotation", "position", "contact", "normal"});
    EquationModelSpec::View v;
    v.body = readShape(j, w, "body",
                       {{"none", BodyShape::None},
                        {"ball", BodyShape::Ball},
                        {"ellipsoid", BodyShape::Ellipsoid},
                        {"paraboloid", BodyShape::Paraboloid},
                        {"mesh", BodyShape::None},
                        {"implicit", BodyShape::None}});
    const bool mesh = j.contains("body") && j["body"] == "mesh";
    if (mesh != j.contains("mesh"))
      (w / (mesh ? "body" : "mesh")).fail("a mesh body names its file in \"mesh\" (with \"body\": \"mesh\")");
    if (mesh) v.mesh = meshFile(j["mesh"], w / "mesh");
    if (j.contains("scale")) v.meshScale = exprText(j["scale"], w / "scale");
    const bool implicit = j.contains("body") && j["body"] == "implicit";
    if (implicit != j.contains("F"))
      (w / (implicit ? "body" : "F"))
          .fail("an implicit body gives its surface in \"F\": F(x, y, z) = 0, F < 0 inside (with \"body\": "
                "\"implicit\")");
    if (implicit) v.surface = exprText(j["F"], w / "F");
    if (j.contains("size")) v.surfaceSize = exprText(j["size"], w / "size");
    if (j.contains("support")) {
      const Where ws = w / "support";
      const json& support = requireObject(j["support"], ws);
      onlyKeys(support, ws, {"surface", "radius", "semi_axes", "centre", "p", "q", "height", "F", "size"});
      v.support = readShape(support, ws, "surface",
                            {{"plane", BodyShape::None},
                             {"sphere", BodyShape::Ball},
                             {"ellipsoid", BodyShape::Ellipsoid},
                             {"paraboloid", BodyShape::Paraboloid},
                             {"implicit", BodyShape::None}});
      const bool implicitSupport = support.contains("surface") && support["surface"] == "implicit";
      if (implicitSupport != support.contains("F"))
        (ws / (implicitSupport ? "surface" : "F"))
            .fail("an implicit support gives its surface in \"F\": F(x, y, z) = 0 in world axes, F < 0 in "
                  "the support (with \"surface\": \"implicit\")");
      if (implicitSupport) {
        v.supportSurface = exprText(support["F"], ws / "F");
        if (support.contains("size")) v.supportSurfaceSize = exprText(support["size"], ws / "size");
      } else if (support.contains("size")) {
        (ws / "size").fail("only an implicit support has a \"size\"");
      }
    }
    for (const char* key : {"rotation", "position", "contact"})
      if (!j.contains(key)) w.fail(std::string("missing \"") + key + "\" (an expression of the state)");
    v.rotation = exprText(j["rotation"], w / "rotation");
    v.position = exprText(j["position"], w / "position");
    v.contact = exprText(j["contact"], w / "contact");
    if (j.contains("normal")) v.normal = exprText(j["normal"], w / "normal");
    s.view = std::move(v);
  }

  /// A mesh file's absolute path: relative to the model file's folder (an inline model's: its scene's).
  std::string meshFile(const json& j, const Where& w) const {
    namespace fs = std::filesystem;
    fs::path file(text(j, w));
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return std::tolower(c); });
    if (ext != ".stl" && ext != ".obj")
      w.fail("a mesh is an STL or OBJ file (.stl, .obj), not '" + ext + "'");
    if (file.is_relative() && !source_.empty() && source_[0] != '<') {
      std::string model = source_;
      if (const auto colon = model.rfind(":model"); colon != std::string::npos && colon + 6 == model.size())
        model.resize(colon);
      file = fs::path(model).parent_path() / file;
    }
    std::error_code ec;
    if (!fs::is_regular_file(file, ec)) w.fail("no such mesh file: " + file.string());
    return fs::absolute(file, ec).lexically_normal().string();
  }

  const json& doc_;
  const ordered_json* ordered_;
  std::string source_;
};

struct Loaded {
  std::string key;  // the file and its content, or the inline object's text
  std::string file; // "" for an inline model
  std::shared_ptr<const EquationSystem> system;
  ModelEntry entry;
  json initial; // the file's default start, or null
};

std::mutex& loadedMutex() {
  static std::mutex m;
  return m;
}
std::list<Loaded>& modelFileList() { // a list: entries never move (scenes keep pointers to them)
  static std::list<Loaded> l;
  return l;
}

struct Compilation {
  std::once_flag once;
  std::mutex mutex;
  CompiledModelFactory factory; // set when the compiled library is loaded
};

std::mutex& notesMutex() {
  static std::mutex m;
  return m;
}

void noteOnStderr(const std::string& note) {
  std::fputs(("rollviz: " + note + "\n").c_str(), stderr);
}

std::function<void(const std::string&)>& compilationNotes() {
  static std::function<void(const std::string&)> notes = noteOnStderr;
  return notes;
}

std::atomic<ModelCompilation>& compilationPolicy() {
  static std::atomic<ModelCompilation> when{ModelCompilation::OnFirstUse};
  return when;
}

/// What was loaded for a model entry, or null (a registered model). Entries never move or change once loaded:
/// only the walk over the list needs the lock.
const Loaded* loadedOf(const ModelEntry& entry) {
  const std::lock_guard lock(loadedMutex());
  for (const Loaded& l : modelFileList())
    if (&l.entry == &entry) return &l;
  return nullptr;
}

const ModelEntry& entryOf(const std::string& key, const std::string& file, const json& doc,
                          const ordered_json* ordered, const std::string& source) {
  const std::lock_guard lock(loadedMutex());
  for (const Loaded& l : modelFileList())
    if (l.key == key) return l.entry;
  std::shared_ptr<const EquationSystem> system;
  if (isRollingModel(doc)) { // derived equations (RollingModel.h); errors named at the field the user wrote
    const RollingEquations rolling = rollingEquations(doc, ordered, source);
    const json derived = json::parse(rolling.model);
    const ordered_json order = ordered_json::parse(rolling.model);
    const auto atTheUsersField = [&](std::string what) {
      for (const auto& [generated, written] : rolling.origins)
        for (const std::string& form : {":" + generated + ":", ":" + generated + " "})
          if (const auto at = what.find(form); at != std::string::npos)
            what.replace(at + 1, generated.size(), written);
      return what;
    };
    try {
      EquationModelSpec spec = Reader(derived, &order, source).read();
      spec.definitionShapes = rolling.shapes;
      system = EquationSystem::build(std::move(spec));
    } catch (const InputError& e) {
      const std::string what = e.what();
      throw InputError(atTheUsersField(what.rfind(source + ":", 0) == 0 ? what : source + ":" + what));
    }
  } else {
    EquationModelSpec spec = Reader(doc, ordered, source).read();
    try {
      system = EquationSystem::build(std::move(spec));
    } catch (const InputError& e) {
      throw InputError(source + ":" + e.what());
    }
  }
  Loaded& l = modelFileList().emplace_back(Loaded{key, file, system, {}, doc.value("initial", json())});
  l.entry.info = &system->info();
  l.entry.origin = file.empty() ? source : file;
  // compiled on the first instance (ModelCompiler.h), interpreted when that is off, not ready or fails
  auto compilation = std::make_shared<Compilation>();
  l.entry.create = [system, compilation](const ParameterValues& p) -> std::unique_ptr<Model> {
    const ModelCompilation when =
        compileModelsByDefault() ? compilationPolicy().load() : ModelCompilation::Off;
    if (when != ModelCompilation::Off) {
      std::call_once(compilation->once, [&] {
        const auto compile = [system, compilation, when] {
          const auto note = [](const std::string& text) {
            const std::lock_guard lock(notesMutex());
            compilationNotes()(text);
          };
          // the command line and Python wait up to a budget, then stay interpreted: a run (a sweep) is all
          // one or all the other, whatever the compiler's speed
          auto factory = when == ModelCompilation::OnFirstUse
                             ? compiledModel(system, note, compileWaitSeconds())
                             : compiledModel(system, note);
          if (factory && when == ModelCompilation::InBackground)
            note("runs of '" + system->info().id + "' started from now use its native code");
          const std::lock_guard lock(compilation->mutex);
          compilation->factory = std::move(factory);
        };
        if (when == ModelCompilation::InBackground)
          std::thread(compile).detach(); // owns what it uses; an exit before it ends abandons it harmlessly
        else
          compile();
      });
      const std::lock_guard lock(compilation->mutex);
      if (compilation->factory) return compilation->factory(p);
    }
    return system->create(p);
  };
  return l.entry;
}

} // namespace

const ModelEntry& modelFileEntry(const std::string& path) {
  namespace fs = std::filesystem;
  const std::string content = readInputFile(path, "model file");
  std::istringstream strict(content);
  const json doc = parseSceneJson(strict, path); // syntax errors and keys written twice, with line numbers
  const ordered_json ordered = ordered_json::parse(content);
  std::error_code ec;
  const std::string canonical = fs::weakly_canonical(path, ec).string();
  return entryOf(canonical + "\n" + content, canonical, doc, &ordered, path);
}

const ModelEntry& modelEntryFromJson(const json& model, const std::string& source) {
  // the source is part of the key: a mesh file is found relative to it
  return entryOf("inline\n" + source + "\n" + model.dump(), "", model, nullptr, source);
}

bool namesModelFile(const std::string& problem) {
  const auto ends = [&](const std::string& suffix) {
    return problem.size() >= suffix.size() &&
           problem.compare(problem.size() - suffix.size(), suffix.size(), suffix) == 0;
  };
  return ends(".json") || problem.find('/') != std::string::npos;
}

const ModelEntry& sceneModelEntry(const json& scene, const std::string& source) {
  const Where root{source, ""};
  if (scene.contains("model")) {
    const ModelEntry& entry =
        modelEntryFromJson(requireObject(scene["model"], root / "model"), source + ":model");
    if (scene.contains("problem") && text(scene["problem"], root / "problem") != entry.info->id)
      (root / "problem")
          .fail("the scene holds the model '" + entry.info->id +
                "' inline: leave \"problem\" out or name it");
    return entry;
  }
  if (!scene.contains("problem"))
    root.fail("missing \"problem\" (a problem id, a model file, or \"model\" inline)");
  const std::string problem = text(scene["problem"], root / "problem");
  if (ModelRegistry::global().find(problem) || !namesModelFile(problem)) {
    try {
      return ModelRegistry::global().get(problem);
    } catch (const InputError& e) {
      (root / "problem").fail(e.what());
    }
  }
  namespace fs = std::filesystem;
  fs::path file(problem);
  if (file.is_relative() && !source.empty() && source[0] != '<') file = fs::path(source).parent_path() / file;
  try {
    return modelFileEntry(file.string());
  } catch (const InputError& e) {
    std::error_code ec; // a name too long for the system is no file either (not a filesystem_error)
    if (!fs::exists(file, ec)) (root / "problem").fail(e.what());
    throw;
  }
}

nlohmann::json sceneMovedTo(nlohmann::json scene, const std::string& source, const std::string& destination) {
  namespace fs = std::filesystem;
  if (!scene.contains("problem") || !scene["problem"].is_string() || source.empty() || source[0] == '<')
    return scene;
  const std::string problem = scene["problem"];
  const fs::path file(problem);
  if (!file.is_relative() || ModelRegistry::global().find(problem) || !namesModelFile(problem)) return scene;
  std::error_code ec;
  const fs::path model = fs::absolute(fs::path(source).parent_path() / file, ec).lexically_normal();
  const fs::path folder = fs::absolute(fs::path(destination), ec).parent_path();
  const fs::path relative = model.lexically_relative(folder);
  scene["problem"] = (relative.empty() ? model : relative).generic_string();
  return scene;
}

const ModelEntry& modelEntryByName(const std::string& idOrPath) {
  if (ModelRegistry::global().find(idOrPath) || !namesModelFile(idOrPath))
    return ModelRegistry::global().get(idOrPath);
  return modelFileEntry(idOrPath);
}

std::vector<const ModelEntry*> loadedModelFiles() {
  const std::lock_guard lock(loadedMutex());
  std::vector<const ModelEntry*> out;
  for (const Loaded& l : modelFileList())
    out.push_back(&l.entry);
  return out;
}

std::string modelFileOf(const ModelEntry& entry) {
  const Loaded* l = loadedOf(entry);
  return l ? l->file : std::string();
}

void setModelCompilationNotes(std::function<void(const std::string&)> notes) {
  const std::lock_guard lock(notesMutex());
  compilationNotes() = notes ? std::move(notes) : noteOnStderr;
}

void setModelCompilation(ModelCompilation when) {
  compilationPolicy() = when;
}

json modelFileInitial(const ModelEntry& entry) {
  const Loaded* l = loadedOf(entry);
  return l ? l->initial : json();
}

std::shared_ptr<const EquationSystem> equationSystemOf(const ModelEntry& entry) {
  const Loaded* l = loadedOf(entry);
  return l ? l->system : nullptr;
}

} // namespace rv
