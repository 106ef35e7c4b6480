// Scene files: the shipped scenes load; every error names the file and the JSON path (or the flag).
#include "scenes/SceneLoader.h"
#include "dynamics/core/Errors.h"
#include "dynamics/tools/FourierSpectrum.h"
#include "dynamics/tools/Lyapunov.h"
#include "dynamics/tools/ToolRegistry.h"

#include <cmath>
#include <gtest/gtest.h>

namespace rv {
namespace {

using nlohmann::json;

std::string sceneError(const json& doc, const std::vector<SceneOverride>& sets = {}) {
  try {
    sceneFromJson(doc, "s.json", sets);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

json ball() {
  return json::parse(R"({"problem": "chaplygin_ball", "parameters": {"energy": 0.5, "c": 0.3},
                         "initial": {"map": [0.5, 0.2]}})");
}

TEST(SceneLoader, ShippedScenesLoad) {
  for (const char* id : {"chaplygin_ball", "lorenz"}) {
    const Scene s = loadScene(defaultScenePath(id));
    EXPECT_EQ(s.model->info().id, id);
    EXPECT_EQ(s.initialState.size(), s.model->dimension());
  }
}

TEST(SceneLoader, ErrorsNameFileAndJsonPath) {
  json j = ball();
  j["parameters"]["I9"] = 1;
  EXPECT_NE(sceneError(j).find("s.json:parameters.I9: unknown parameter"), std::string::npos)
      << sceneError(j);
  j = ball();
  j["parameters"]["m"] = "heavy";
  EXPECT_NE(sceneError(j).find("s.json:parameters.m: expected a number"), std::string::npos) << sceneError(j);
  j = ball();
  j["problem"] = "no_such_problem";
  EXPECT_NE(sceneError(j).find("s.json:problem: unknown problem 'no_such_problem'"), std::string::npos)
      << sceneError(j);
  j = ball();
  j["integrator"] = {{"method", "rk5"}};
  EXPECT_NE(sceneError(j).find("s.json:integrator.method: unknown integrator 'rk5'"), std::string::npos)
      << sceneError(j);
  j = ball();
  j["integrator"] = {{"step", -1}};
  EXPECT_NE(sceneError(j).find("s.json:integrator.step"), std::string::npos) << sceneError(j);
  j = ball();
  j["view"] = {{"objects", {{"ball", {{"color", "blue"}}}}}};
  EXPECT_NE(sceneError(j).find("s.json:view.objects.ball.color: expected a colour"), std::string::npos)
      << sceneError(j);
  j = ball();
  j["initial"] = {{"map", {0.5, 5.0}}};
  EXPECT_NE(sceneError(j).find("s.json:initial.map: L/G must lie in [-1, 1]"), std::string::npos)
      << sceneError(j);
  j = ball();
  j["parameters"]["I3"] = 5;
  EXPECT_NE(sceneError(j).find("s.json:parameters: I3 = 5 exceeds I1 + I2"), std::string::npos)
      << sceneError(j);
  j = ball();
  j["colour"] = 1;
  EXPECT_NE(sceneError(j).find("s.json:colour: unknown key"), std::string::npos) << sceneError(j);
}

TEST(SceneLoader, ViewOptionsAreCheckedAndKept) {
  json j = ball();
  j["view"] = {
      {"kind", "apex"},
      {"looking_in", "body"},
      {"multisamples", 4},
      {"axes", {{"style", "box"}, {"min", {0, 0, 0}}, {"max", {1, 2, 3}}, {"tickmarks", 4}}},
      {"objects", {{"ball", {{"texture", "stripes"}, {"grid_density", 2}}}, {"box", {{"size", {1, 2, 3}}}}}}};
  const Scene s = sceneFromJson(j, "s.json", {});
  EXPECT_EQ(s.view.kind, ViewKind::Apex);
  EXPECT_EQ(s.view.lookingIn, LookingIn::Body);
  EXPECT_EQ(s.view.multisamples, 4);
  EXPECT_EQ(s.view.axes.style, AxesOptions::Style::Box);
  EXPECT_EQ(s.view.axes.tickmarks, 4);
  EXPECT_TRUE(s.view.objects.at("ball").texture.ends_with("assets/textures/stripes.png"));
  EXPECT_EQ(s.view.objects.at("ball").gridDensity, 2);
  EXPECT_EQ(s.view.objects.at("box").size, (std::array<double, 3>{1, 2, 3}));
  const auto fails = [&](const json& view, const std::string& what) {
    json k = ball();
    k["view"] = view;
    EXPECT_NE(sceneError(k).find(what), std::string::npos) << sceneError(k);
  };
  fails({{"kind", "sideways"}}, "s.json:view.kind: expected motion or apex");
  fails({{"axes", {{"style", "fancy"}}}}, "s.json:view.axes.style: expected none, normal or box");
  fails({{"axes", {{"min", {0, 0, 0}}, {"max", {1, 0, 1}}}}}, "s.json:view.axes.max: must exceed min");
  fails({{"axes", {{"tickmarks", 2.5}}}}, "s.json:view.axes.tickmarks: must be a whole number");
  fails({{"objects", {{"ball", {{"texture", "no_such_picture"}}}}}},
        "s.json:view.objects.ball.texture: no texture");
  fails({{"objects", {{"box", {{"size", {1, -2, 3}}}}}}}, "s.json:view.objects.box.size.1: must be positive");
  fails({{"multisamples", 64}}, "s.json:view.multisamples: must lie in [0, 16]");
}

TEST(SceneLoader, OverridesSetParametersAndFields) {
  const Scene s =
      sceneFromJson(ball(), "s.json", {parseOverride("energy=0.4"), parseOverride("integrator.step=0.002")});
  EXPECT_EQ(s.model->parameters()["energy"], 0.4);
  EXPECT_EQ((*s.integratorParameters)["step"], 0.002);
  EXPECT_NEAR(s.model->integrals(s.initialState.data())[0], 0.4, 1e-12);
  EXPECT_NE(
      sceneError(ball(), {parseOverride("no_such_param=1")}).find("--set no_such_param: unknown parameter"),
      std::string::npos);
  EXPECT_NE(sceneError(ball(), {parseOverride("bogus.x=1")}).find("--set bogus.x: unknown scene field"),
            std::string::npos);
  EXPECT_THROW(parseOverride("energy"), InputError);
}

TEST(SceneLoader, MalformedJsonIsAnInputErrorNamingTheFile) {
  const std::string path = ::testing::TempDir() + "/bad.json";
  FILE* f = std::fopen(path.c_str(), "w");
  std::fputs("{ \"problem\": ", f);
  std::fclose(f);
  try {
    loadScene(path);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find(path + ":$: malformed JSON"), std::string::npos) << e.what();
  }
}

std::string loadError(const std::string& path) {
  try {
    loadScene(path);
  } catch (const InputError& e) {
    return e.what();
  }
  return "(no error)";
}

std::string writeFile(const std::string& name, const std::string& text) {
  const std::string path = ::testing::TempDir() + "/" + name;
  FILE* f = std::fopen(path.c_str(), "w");
  std::fputs(text.c_str(), f);
  std::fclose(f);
  return path;
}

TEST(SceneLoader, KeyWrittenTwiceIsNamedWithItsPath) {
  // JSON leaves duplicate keys undefined; the parser would keep the last one silently
  const std::string top = writeFile("dup1.json", R"({"problem": "lorenz", "problem": "lorenz"})");
  EXPECT_NE(loadError(top).find(top + ":problem: key written twice"), std::string::npos) << loadError(top);
  const std::string nested =
      writeFile("dup2.json",
                R"({"problem": "lorenz", "parameters": {"rho": 28, "sigma": 10, "rho": 20}, "initial": {}})");
  EXPECT_NE(loadError(nested).find(nested + ":parameters.rho: key written twice"), std::string::npos)
      << loadError(nested);
  const std::string inArray =
      writeFile("dup3.json", R"({"problem": "lorenz", "view": {"list": [1, {"a": 1}, {"a": 1, "a": 2}]}})");
  EXPECT_NE(loadError(inArray).find(inArray + ":view.list.2.a: key written twice"), std::string::npos)
      << loadError(inArray);
  // the same key in two objects is fine
  const std::string twoObjects = writeFile(
      "nodup.json",
      R"({"problem": "lorenz", "parameters": {"rho": 28}, "initial": {"state": {"x": 1, "y": 1, "z": 1}},
                        "integrator": {"method": "rk4", "step": 0.01}})");
  EXPECT_EQ(loadError(twoObjects), "(no error)");
}

TEST(SceneLoader, ANumberBeyondADoubleIsMalformedJson) {
  // found by tests/fuzz: nlohmann's out_of_range escaped as another exception (exit 1, not 2)
  const std::string big = writeFile("big.json", R"({"problem": "lorenz", "parameters": {"rho": 7e873177}})");
  EXPECT_NE(loadError(big).find(big + ":$: malformed JSON: number overflow"), std::string::npos)
      << loadError(big);
}

TEST(SceneLoader, ASetValueThatIsNotUtf8IsBadInput) {
  // found by tests/fuzz: writing the message (or the document) threw nlohmann's type_error
  EXPECT_NE(
      sceneError(ball(), {parseOverride("energy=\x9a")}).find("--set energy: the value is not valid UTF-8"),
      std::string::npos)
      << sceneError(ball(), {parseOverride("energy=\x9a")});
}

TEST(SceneLoader, FolderEmptyAndMissingScenePathsArePlainInputErrors) {
  const std::string dir = ::testing::TempDir();
  EXPECT_NE(loadError(dir).find(dir + ": is a folder, not a scene file"), std::string::npos)
      << loadError(dir);
  const std::string empty = writeFile("empty.json", "");
  EXPECT_NE(loadError(empty).find(empty + ": the scene file is empty"), std::string::npos)
      << loadError(empty);
  const std::string missing = dir + "/no_such_scene.json";
  EXPECT_NE(loadError(missing).find(missing + ": cannot open the scene file (no such file)"),
            std::string::npos)
      << loadError(missing);
}

} // namespace
} // namespace rv

namespace rv {
namespace {

// a value in the setting's range other than its default: the next choice, or a number inside the range
std::string otherValue(const ParameterSpec& p) {
  if (!p.choices.empty())
    return "\"" + p.choices[(static_cast<std::size_t>(p.defaultValue) + 1) % p.choices.size()] + "\"";
  double v = p.defaultValue + 1;
  // (a default of +-1e300, an open side, is not moved by adding 1: halve it)
  if (v > p.max || v == p.defaultValue) v = p.defaultValue != 0 ? p.defaultValue / 2 : p.defaultValue - 1;
  if (p.integer) v = std::round(v);
  return nlohmann::json(v).dump();
}

TEST(SceneLoader, EveryToolSettingRoundTripsThroughSetAndTheSavedScene) {
  for (const auto& section : toolSections())
    for (const auto& p : section.table->specs()) {
      const std::string key = section.key + "." + p.id, value = otherValue(p);
      SCOPED_TRACE(key + "=" + value);
      const Scene set = sceneFromJson(ball(), "s.json", {parseOverride(key + "=" + value)});
      const double expected = set.tool(section.key)[p.id];
      EXPECT_NE(expected, p.defaultValue);
      if (!p.choices.empty()) {
        EXPECT_EQ("\"" + set.tool(section.key).choice(p.id) + "\"", value);
      } else {
        EXPECT_EQ(expected, nlohmann::json::parse(value).get<double>());
      }
      const Scene saved = sceneFromJson(nlohmann::json::parse(set.document.dump()), "saved.json");
      EXPECT_EQ(saved.tool(section.key)[p.id], expected);
    }
}

TEST(SceneLoader, LyapunovAndMegnoSettingsComeFromTheirTables) {
  const Scene s = sceneFromJson(ball(), "s.json",
                                {parseOverride("lyapunov.mode=perturbed"), parseOverride("lyapunov.time=77"),
                                 parseOverride("lyapunov.renormalize=true"), parseOverride("megno.time=5")});
  const LyapunovSettings lyapunov = s.settings(lyapunovSettingsTable(), "lyapunov");
  EXPECT_EQ(lyapunov.mode, LyapunovSettings::Mode::Perturbed);
  EXPECT_EQ(lyapunov.maxTime, 77);
  EXPECT_TRUE(lyapunov.renormalizeIntegrals);
  EXPECT_EQ(s.tool("megno")["time"], 5);
  EXPECT_NE(sceneError(ball(), {parseOverride("lyapunov.interval=-1")}).find("lyapunov.interval"),
            std::string::npos)
      << sceneError(ball(), {parseOverride("lyapunov.interval=-1")});
  EXPECT_NE(sceneError(ball(), {parseOverride("megno.nonsense=1")}).find("megno.nonsense"),
            std::string::npos);
}

TEST(SceneLoader, SpectrumAndPlotSettingsComeFromTheirTablesBesideTheirTextKeys) {
  json j = ball();
  j["spectrum"] = {{"function", "M1"}, {"samples", 512}, {"peaks", 3}};
  j["plot"] = {
      {"x", "t"},          {"y", "M1"},  {"z", "M2"},   {"condition", "t"},    {"period", 0.5},
      {"max_points", 300}, {"x_min", 0}, {"x_max", 10}, {"point_type", "big"}, {"hold_proportions", true}};
  const Scene s = sceneFromJson(j, "s.json");
  const SpectrumSettings spectrum = s.settings(spectrumSettingsTable(), "spectrum");
  EXPECT_EQ(s.document["spectrum"]["function"], "M1");
  EXPECT_EQ(spectrum.samples, 512);
  EXPECT_EQ(spectrum.peaks, 3);
  EXPECT_EQ(s.plot.settings.axes, (std::vector<std::string>{"t", "M1", "M2"}));
  EXPECT_EQ(s.plot.settings.period, 0.5);
  EXPECT_EQ(s.plot.settings.maxPoints, 300);
  EXPECT_EQ(s.plot.chart.range[0], 0.0);
  EXPECT_EQ(s.plot.chart.range[1], 10.0);
  EXPECT_FALSE(s.plot.chart.range[2]);
  EXPECT_EQ(s.plot.chart.pointSize, 7.0f);
  EXPECT_TRUE(s.plot.chart.holdProportions);
  // the defaults are the structs' own (one declaration)
  const Scene d = sceneFromJson(ball(), "s.json");
  EXPECT_EQ(d.settings(spectrumSettingsTable(), "spectrum").samples, SpectrumSettings{}.samples);
  EXPECT_EQ(d.plot.settings.period, PlotSettings{}.period);
  EXPECT_EQ(d.plot.chart.pointSize, PlotChartOptions{}.pointSize);
  // bad values are named by their path; an unknown key is told the section's keys, text keys included
  const auto bad = [](const char* set, const char* expected) {
    const std::string e = sceneError(ball(), {parseOverride(set)});
    EXPECT_NE(e.find(expected), std::string::npos) << set << ": " << e;
  };
  bad("spectrum.samples=4", "s.json:spectrum.samples");
  bad("plot.point_type=\"huge\"", "s.json:plot.point_type");
  bad("plot.nonsense=1", "known: period max_points time_limit hold_proportions point_type x y z condition");
  bad("spectrum.nonsense=1", "function");
  bad("plot.x=3", "s.json:plot.x: expected");
  json r = ball();
  r["plot"] = {{"y_min", 2}, {"y_max", 1}};
  EXPECT_NE(sceneError(r).find("s.json:plot.y_max: must exceed y_min"), std::string::npos) << sceneError(r);
}

} // namespace
} // namespace rv
