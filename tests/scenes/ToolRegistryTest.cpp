// The tool registry is whole: unique ids, parents registered before their children, every tool reachable from
// the command line or a chart, every settings table's defaults inside its ranges.
#include "dynamics/tools/ToolRegistry.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/integrators/Integrator.h"

#include <gtest/gtest.h>
#include <set>

namespace rv {
namespace {

// what a module (scenes/ModuleLoader.h) may not do: take an id that is registered, naming who has it
template <class F> std::string refusal(F&& f) {
  try {
    f();
  } catch (const InputError& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(Registries, RefuseATakenIdAndNameWhoHasIt) {
  ModelRegistry models;
  registerBuiltinModels(models);
  ModelEntry lorenz = ModelRegistry::global().get("lorenz");
  lorenz.origin = "/m/libsecond.so";
  EXPECT_EQ(refusal([&] { models.add(lorenz); }), "problem 'lorenz' is already registered by rollviz itself");
  EXPECT_EQ(models.entries().size(), ModelRegistry::global().entries().size());

  IntegratorRegistry integrators;
  IntegratorEntry rk4 = IntegratorRegistry::global().get("rk4");
  rk4.origin = "/m/libfirst.so";
  integrators.add(rk4);
  EXPECT_EQ(integrators.find("rk4")->origin, "/m/libfirst.so");
  EXPECT_EQ(refusal([&] { integrators.add(rk4); }),
            "integrator 'rk4' is already registered by /m/libfirst.so");

  ToolRegistry tools;
  ToolEntry orphan{.id = "orphan", .title = "t", .parent = "nowhere"};
  EXPECT_NE(refusal([&] { tools.add(orphan); }).find("its parent 'nowhere' is not registered"),
            std::string::npos);
  ToolEntry a{.id = "a", .title = "A", .command = "run-a"}, b{.id = "b", .title = "B", .command = "run-a"};
  tools.add(a);
  EXPECT_EQ(refusal([&] { tools.add(a); }), "tool 'a' is already registered by rollviz itself");
  EXPECT_EQ(refusal([&] { tools.add(b); }), "command 'run-a' is already registered by rollviz itself");

  static const ParameterTable table{{.id = "n", .label = "n", .defaultValue = 1}};
  EXPECT_EQ(refusal([&] {
              addToolSection({"poincare", "P", &table});
            }),
            "settings section 'poincare' is already registered by rollviz itself");
}

TEST(ToolRegistry, EveryEntryIsCompleteAndItsParentComesFirst) {
  std::set<std::string> seen;
  for (const auto& e : ToolRegistry::global().entries()) {
    SCOPED_TRACE(e.id);
    EXPECT_FALSE(e.title.empty());
    EXPECT_FALSE(e.description.empty());
    EXPECT_FALSE(e.reference.empty());
    EXPECT_FALSE(e.outputs.empty());
    EXPECT_EQ(e.computation.rfind("dynamics/", 0), 0u) << e.computation;
    EXPECT_FALSE(e.command.empty() && e.chartView.empty()) << "runs nowhere";
    if (!e.parent.empty()) {
      EXPECT_TRUE(seen.count(e.parent)) << "parent " << e.parent << " not before it";
    }
    EXPECT_TRUE(seen.insert(e.id).second) << "registered twice";
    EXPECT_EQ(&ToolRegistry::global().get(e.id), &e);
  }
  for (const char* id : {"poincare", "lyapunov", "spectrum", "fixedpoint", "continuation", "separatrix",
                         "bifurcation_tree", "surface", "ram", "diagram", "megno"})
    EXPECT_TRUE(seen.count(id)) << id;
}

TEST(ToolRegistry, UnknownIdIsAnInputErrorListingTheKnown) {
  try {
    (void)ToolRegistry::global().get("no_such_tool");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("megno"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ToolRegistry::global().find("no_such_tool"), nullptr);
}

TEST(ToolRegistry, SettingsTablesAreConsistent) {
  std::set<std::string> keys;
  for (const auto& s : toolSections()) {
    SCOPED_TRACE(s.key);
    EXPECT_TRUE(keys.insert(s.key).second);
    EXPECT_EQ(findToolSection(s.key), &s);
    ASSERT_NE(s.table, nullptr);
    for (const auto& p : s.table->specs()) {
      SCOPED_TRACE(p.id);
      EXPECT_LE(p.min, p.defaultValue);
      EXPECT_GE(p.max, p.defaultValue);
      EXPECT_FALSE(p.description.empty());
      if (!p.choices.empty()) {
        EXPECT_LT(p.defaultValue, static_cast<double>(p.choices.size()));
      }
      EXPECT_NO_THROW(ParameterValues(*s.table).set(p.id, p.defaultValue));
    }
  }
  // the tools with a settings table of their own name it as their section
  for (const auto& e : ToolRegistry::global().entries())
    if (findToolSection(e.id)) {
      EXPECT_EQ(e.section, e.id);
    }
}

} // namespace
} // namespace rv
