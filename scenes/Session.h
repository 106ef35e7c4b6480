// Session.h -- a GUI session in one JSON file: the scene, every trajectory of the map (where it starts, the
// values it runs with, its colour, its points and the whole state to go on from, bit for bit), the fixed
// points and families its tools drew (as drawn, with their multipliers), the Results
// log and what the window keeps of its layout. The GUI writes and opens it (File > Save session / Open
// session, Edit > Undo keeps the same record of the map); every command line command takes it where it
// takes a scene (its scene), and `rollviz chart SESSION --view poincare` draws the saved map
// (sessionMapChart, scenes/SceneCharts.h: this file needs no VTK).
#pragma once
#include "render/ViewOptions.h"
#include "scenes/JsonFields.h"

#include <complex>
#include <map>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <vector>

namespace rv {

/// A map trajectory as saved: enough to draw it and to go on with it.
struct SavedTrajectory {
  std::vector<double> start;                ///< the full initial state
  std::map<std::string, double> parameters; ///< the problem's parameters it runs with
  std::map<std::string, double> integrator; ///< the method's settings
  Rgb colour{0, 0, 1};
  std::vector<double> x, y, z; ///< its map points (z: a 3D map's third coordinate)
  std::vector<double> state;   ///< PoincareTask::save's values (in the file bit for bit: snapshotToJson)
  bool running = false;        ///< it ran when saved: it goes on when opened
  long first = 1, last = 0;    ///< the range of points shown (Set range)
  std::string origin;          ///< where a click started it, in map coordinates ("" for none)
  int id = 0;                  ///< its number in the tool manager, kept when it is put back (0: none known)
};

/// What a fixed-point tool of the map drew (a search, a family, a separatrix branch, a bifurcation tree):
/// kept as drawn, with the fixed points' multipliers; a session opens it as a finished record (not computed
/// again: a family can take minutes).
struct SavedToolOutput {
  /// How its job ended (one that ran when saved is kept as stopped: a record computes nothing more).
  enum class Outcome { Finished, Stopped, Failed };
  std::string name;    ///< the tool manager's name ("Fixed point", "Continuation", ...)
  std::string summary; ///< its outcome in words, as the Results dock said it
  Rgb colour{0, 0, 0};
  std::vector<double> x, y;  ///< its points on the map (a search: the path it took)
  std::vector<double> found; ///< a search's fixed point (map x, y); empty for none
  /// The multipliers of its fixed points, each with the family's parameter (a search: one, parameter 0).
  std::vector<std::pair<double, std::vector<std::complex<double>>>> multipliers;
  bool everyStep = false; ///< a tree: the multipliers filter shows each step (not by its period)
  Outcome outcome = Outcome::Finished;
  int id = 0; ///< its number in the tool manager, kept when it is put back (0: none known)
};

nlohmann::json toJson(const SavedTrajectory& t);
nlohmann::json toJson(const SavedToolOutput& t);
/// InputError naming where (e.g. "session.json:tools[0].found") a field is missing or mistyped.
SavedToolOutput savedToolOutputFromJson(const nlohmann::json& j, const Where& where);
/// InputError naming where (e.g. "session.json:trajectories[3].x") a field is missing or mistyped.
SavedTrajectory savedTrajectoryFromJson(const nlohmann::json& j, const Where& where);

struct Session {
  nlohmann::json scene;  ///< the scene document (as the control panel would run it)
  std::string scenePath; ///< the scene's file (relative files of the scene resolve from it; may be empty)
  std::string origin;    ///< what the window's title says the scene came from ("" : its file)
  std::vector<SavedTrajectory> trajectories;
  std::vector<SavedToolOutput> tools;            ///< the fixed points and families drawn on the map
  std::string results;                           ///< the Results log
  nlohmann::json gui = nlohmann::json::object(); ///< the window's own (layout, ...): kept as written
};

/// The key that marks a session document, with its format version (1).
inline constexpr const char* kSessionKey = "rollviz_session";
inline constexpr int kSessionFormat = 1;

/// Whether a parsed JSON document is a session (else it is a scene).
bool isSession(const nlohmann::json& document);
nlohmann::json sessionToJson(const Session& s);
/// InputError naming `file` and the field for what is not a session of this format.
Session sessionFromJson(const nlohmann::json& j, const std::string& file);
/// Reads a session file (InputError naming it when it cannot be read or is not a session).
Session readSession(const std::string& path);
/// The session in `path`, or nothing when the file is a scene (InputError when it cannot be read or parsed).
std::optional<Session> readSessionIfAny(const std::string& path);
/// Writes a session whole or not at all (a temporary name, then renamed); InputError for a path that
/// cannot be written.
void writeSession(const Session& s, const std::string& path);

} // namespace rv
