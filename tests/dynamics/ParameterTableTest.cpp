#include "dynamics/core/ParameterTable.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"
#include "dynamics/core/SettingsTable.h"

#include <gtest/gtest.h>
#include <limits>

namespace rv {
namespace {

TEST(ParameterTable, RejectsUnknownIdsAndOutOfRangeValuesByName) {
  const ParameterTable table{{.id = "step", .defaultValue = 0.1, .min = 1e-9, .max = 1},
                             {.id = "order", .defaultValue = 15, .min = 3, .max = 27, .integer = true}};
  ParameterValues p(table);
  EXPECT_EQ(p["step"], 0.1);
  try {
    p.set("stpe", 1, "scene.json:integrator.stpe");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("stpe"), std::string::npos);
    EXPECT_NE(std::string(e.what()).find("known: step order"), std::string::npos);
  }
  EXPECT_THROW(p.set("step", 2), InputError);
  EXPECT_THROW(p.set("order", 7.5), InputError);
  p.set("order", 7);
  EXPECT_EQ(p["order"], 7);
}

TEST(ModelRegistry, HasTheContractIdsAndUnknownIdsListTheKnownOnes) {
  const auto& r = ModelRegistry::global();
  EXPECT_EQ(r.get("chaplygin_ball").info->id, "chaplygin_ball");
  EXPECT_EQ(r.get("lorenz").info->id, "lorenz");
  try {
    r.get("no_such_problem");
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("chaplygin_ball"), std::string::npos);
  }
}

TEST(ModelRegistry, EveryModelsDefaultsBuildAndItsObservablesEvaluate) {
  for (const auto& e : ModelRegistry::global().entries()) {
    const auto m = e.create(ParameterValues(e.info->parameters));
    EXPECT_EQ(m->dimension(), static_cast<int>(e.info->stateNames.size()));
    EXPECT_GE(m->findObservable("t"), 0) << e.info->id;
    for (const auto& n : e.info->integralNames)
      EXPECT_GE(m->findObservable(n), 0) << e.info->id << " " << n;
  }
}

// a settings struct's table declared once beside its members: the defaults are the struct's, read() sets
// each member from its parameter, a choice maps names to values in the order given (not the enum's)
struct Knobs {
  enum class Way { Up, Down };
  double step = 0.25;
  long points = 40;
  Way way = Way::Down;
  bool enabled = true;
  struct {
    double tolerance = 1e-6;
  } inner;
  double bound = std::numeric_limits<double>::infinity(); // the table cannot write it: its own default
  int unset = 0;                                          // no parameter of the table
};

TEST(SettingsTable, DefaultsAreTheStructsAndReadSetsEachMember) {
  using T = SettingsTable<Knobs>;
  const T table{T::number(&Knobs::step, {.id = "step", .description = "d"}),
                T::number(&Knobs::points, {.id = "points", .min = 1, .max = 100, .description = "d"}),
                T::choice(&Knobs::way, {.id = "way", .description = "d", .choices = {"down", "up"}},
                          std::vector{Knobs::Way::Down, Knobs::Way::Up}),
                T::choice(&Knobs::enabled, {.id = "enabled", .description = "d", .choices = {"no", "yes"}},
                          std::vector{false, true}),
                T::number([](Knobs & k) -> auto& { return k.inner.tolerance; }, {.id = "tolerance"}),
                T::number(&Knobs::bound, {.id = "bound"}, 1e300),
                T::Field{{.id = "order", .defaultValue = 3}}};
  const auto& specs = table.table().specs();
  ASSERT_EQ(specs.size(), 7u);
  EXPECT_EQ(specs[0].defaultValue, 0.25);
  EXPECT_FALSE(specs[0].integer);
  EXPECT_EQ(specs[1].defaultValue, 40);
  EXPECT_TRUE(specs[1].integer);
  EXPECT_EQ(specs[2].defaultValue, 0); // "down", the first name
  EXPECT_EQ(specs[2].max, 1);
  EXPECT_TRUE(specs[2].integer);
  EXPECT_EQ(specs[3].defaultValue, 1); // "yes"
  EXPECT_EQ(specs[4].defaultValue, 1e-6);
  EXPECT_EQ(specs[5].defaultValue, 1e300);
  EXPECT_EQ(specs[6].defaultValue, 3);

  ParameterValues v(table.table());
  v.set("step", 0.5);
  v.set("points", 7);
  v.setChoice("way", "up");
  v.setChoice("enabled", "no");
  v.set("tolerance", 1e-9);
  v.set("bound", 2);
  const Knobs k = table.read(v);
  EXPECT_EQ(k.step, 0.5);
  EXPECT_EQ(k.points, 7);
  EXPECT_EQ(k.way, Knobs::Way::Up);
  EXPECT_FALSE(k.enabled);
  EXPECT_EQ(k.inner.tolerance, 1e-9);
  EXPECT_EQ(k.bound, 2);
  // the defaults read back as the struct's, and a member no parameter sets keeps what it is given
  Knobs given;
  given.unset = 5;
  const Knobs d = table.read(ParameterValues(table.table()), given);
  EXPECT_EQ(d.step, Knobs{}.step);
  EXPECT_EQ(d.way, Knobs::Way::Down);
  EXPECT_TRUE(d.enabled);
  EXPECT_EQ(d.bound, 1e300);
  EXPECT_EQ(d.unset, 5);
}

} // namespace
} // namespace rv
