// Grasp regions to and from JSON (for plan.json).
#include "cordgrasp/jobs/region_json.h"

#include <gtest/gtest.h>

#include "cordgrasp/core/error.h"

namespace cordgrasp {
namespace {

GraspRegion sample_region() {
  GraspRegion r;
  r.p1 = {0.1, 0.2, 0.3};
  r.p2 = {0.4, 0.5, 0.6};
  r.p3 = {-0.1, -0.2, -0.3};
  r.normal = {0, 0, 1};
  r.p_l = {0.01, 0.02, 0.03};
  r.p_r = {-0.01, 0.0, 0.05};
  r.p_m = 0.5 * (r.p_l + r.p_r);
  r.cord_case = CordCase::kII;
  r.n = 1;
  r.front_cords = {{{0, 0, 0}, {1, 1, 1}}, {{0.5, 0.25, 0.125}}, {{2, 2, 2}, {3, 3, 3}, {4, 4, 4}}};
  r.xi_m = 0.031;
  r.chi_m2 = 1.5e-4;
  r.from_local_improvement = true;
  return r;
}

TEST(RegionJson, RoundTripsEveryFieldExactly) {
  const GraspRegion r = sample_region();
  const GraspRegion back = region_from_json(nlohmann::json::parse(region_to_json(r).dump()));
  EXPECT_EQ(back.p1, r.p1);
  EXPECT_EQ(back.p2, r.p2);
  EXPECT_EQ(back.p3, r.p3);
  EXPECT_EQ(back.normal, r.normal);
  EXPECT_EQ(back.p_l, r.p_l);
  EXPECT_EQ(back.p_r, r.p_r);
  EXPECT_EQ(back.p_m, r.p_m);
  EXPECT_EQ(back.cord_case, r.cord_case);
  EXPECT_EQ(back.n, r.n);
  EXPECT_EQ(back.front_cords, r.front_cords);
  EXPECT_EQ(back.xi_m, r.xi_m);
  EXPECT_EQ(back.chi_m2, r.chi_m2);
  EXPECT_EQ(back.from_local_improvement, r.from_local_improvement);
}

TEST(RegionJson, MissingOrInconsistentFieldsAreNamed) {
  nlohmann::json j = region_to_json(sample_region());
  j.erase("p_l");
  try {
    region_from_json(j);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("'p_l'"), std::string::npos) << e.what();
  }
  j = region_to_json(sample_region());
  j["n"] = 2;
  try {
    region_from_json(j);
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("2n + 1 = 5"), std::string::npos) << e.what();
  }
  j = region_to_json(sample_region());
  j["case"] = "III";
  EXPECT_THROW(region_from_json(j), InputError);
  j["case"] = 1;  // numeric form accepted
  EXPECT_EQ(region_from_json(j).cord_case, CordCase::kI);
  j = region_to_json(sample_region());
  j["p1"] = "here";
  EXPECT_THROW(region_from_json(j), InputError);
}

}  // namespace
}  // namespace cordgrasp
