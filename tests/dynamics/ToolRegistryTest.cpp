// The tool registry is whole: unique ids, parents registered before their children, every tool reachable from
// the command line or a chart, every settings table's defaults inside its ranges.
#include "dynamics/tools/ToolRegistry.h"
#include "dynamics/core/Errors.h"

#include <gtest/gtest.h>
#include <set>

namespace rv {
namespace {

TEST(ToolRegistry, EveryEntryIsCompleteAndItsParentComesFirst) {
  std::set<std::string> seen;
  for (const auto& e : ToolRegistry::builtin().entries()) {
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
    EXPECT_EQ(&ToolRegistry::builtin().get(e.id), &e);
  }
  for (const char* id : {"poincare", "lyapunov", "spectrum", "fixedpoint", "continuation", "separatrix",
                         "bifurcation_tree", "surface", "ram", "diagram", "megno"})
    EXPECT_TRUE(seen.count(id)) << id;
}

TEST(ToolRegistry, UnknownIdIsAnInputErrorListingTheKnown) {
  try {
    (void)ToolRegistry::builtin().get("no_such_tool");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("megno"), std::string::npos) << e.what();
  }
  EXPECT_EQ(ToolRegistry::builtin().find("no_such_tool"), nullptr);
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
  for (const auto& e : ToolRegistry::builtin().entries())
    if (findToolSection(e.id)) {
      EXPECT_EQ(e.section, e.id);
    }
}

} // namespace
} // namespace rv
