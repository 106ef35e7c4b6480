#include "dynamics/core/ParameterTable.h"
#include "dynamics/core/Errors.h"
#include "dynamics/core/ModelRegistry.h"

#include <gtest/gtest.h>

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

} // namespace
} // namespace rv
