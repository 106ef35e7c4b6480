// ModelFile.h -- models written as equations in JSON (docs/models.md): a model file, or the same object
// inline under a scene's "model", read into an EquationSystem (dynamics/models/EquationModel.h) and kept as
// a model entry for the life of the process. A scene's "problem" names a registered id or a model file (a
// path, relative to the scene); one function resolves both for every front end.
#pragma once
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/models/EquationModel.h"

#include <functional>
#include <memory>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

namespace rv {

/// The entry of a model file (loaded once per content: a file edited since is read again). Throws InputError
/// "FILE:json.path: what is wrong" for a malformed file or expression, or an id already registered.
const ModelEntry& modelFileEntry(const std::string& path);

/// The entry of a model given as a JSON object (a scene's inline "model", Python's Model(dict)); `source`
/// names it in messages.
const ModelEntry& modelEntryFromJson(const nlohmann::json& model, const std::string& source);

/// Whether a scene's "problem" names a file rather than a registered id (it ends with ".json" or holds a
/// '/').
bool namesModelFile(const std::string& problem);

/// The model a scene document uses: its inline "model", a model file named by "problem" (relative to the
/// folder of `source`), or a registered id. Throws InputError naming the field.
const ModelEntry& sceneModelEntry(const nlohmann::json& scene, const std::string& source);

/// The scene read from `source` as it must be written to `destination`: a model file its "problem" names
/// relative to the old folder is named relative to the new one (absolute when they share no root).
nlohmann::json sceneMovedTo(nlohmann::json scene, const std::string& source, const std::string& destination);

/// A registered model or a model file by path: what `rollviz describe` and Python take.
const ModelEntry& modelEntryByName(const std::string& idOrPath);

/// The model files loaded so far, oldest first (for lists).
std::vector<const ModelEntry*> loadedModelFiles();

/// The file a model-file entry came from ("" for a registered model or an inline one).
std::string modelFileOf(const ModelEntry& entry);

/// When a model file's field is compiled to native code (ModelCompiler.h): on its first instance, which waits
/// for the compiler up to ROLLVIZ_COMPILE_WAIT seconds and then runs interpreted while the compilation goes
/// on (the command line, Python); in the background, instances made before it is ready
/// running interpreted (the GUI, whose thread never waits); or never. ROLLVIZ_COMPILE_MODELS=0 means never.
enum class ModelCompilation { OnFirstUse, InBackground, Off };
void setModelCompilation(ModelCompilation when);

/// Where the notes of model compilation go (compiling, compiled in N s, why a model runs interpreted): stderr
/// unless set (the GUI shows them); an empty function puts stderr back. Called on the compiling thread.
void setModelCompilationNotes(std::function<void(const std::string&)> notes);

/// A model file's "initial" (as a scene's: {"state": {...}} or {"map": [...]}), the start of a scene that
/// gives none; null when it has none (or for a registered model).
nlohmann::json modelFileInitial(const ModelEntry& entry);

/// The checked system behind a model-file entry (null for a registered model).
std::shared_ptr<const EquationSystem> equationSystemOf(const ModelEntry& entry);

} // namespace rv
