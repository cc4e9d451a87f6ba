// Planner settings documents: partial files merge over the defaults, a plan.json repeats its
// plan, the YAML printed reads back, bad files are refused naming the file and the key, and
// the example in docs/algorithm.md §10c is a valid document.
#include "cordgrasp/jobs/plan_settings.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/jobs/plan_json.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

std::string write_file(const std::string& name, const std::string& text) {
  const std::string path =
      (std::filesystem::temp_directory_path() / ("cordgrasp_plan_settings_" + name)).string();
  std::ofstream(path) << text;
  return path;
}

std::string refusal(const std::string& name, const std::string& text) {
  PlanJobParams job;
  ValidationParams v;
  try {
    merge_plan_settings_file(write_file(name, text), &job, &v);
  } catch (const InputError& e) {
    return e.what();
  }
  return "";
}

TEST(PlanSettings, PartialYamlSetsItsKeysAndKeepsTheRest) {
  PlanJobParams job;
  ValidationParams v;
  merge_plan_settings_file(write_file("partial.yaml",
                                      "max_attempts: 40\n"
                                      "seed: 18446744073709551615\n"
                                      "cord: {sets: 5}\n"
                                      "quality: {contact: {soft_finger_radius_m: 0.004}}\n"
                                      "validation: {trials: 5, perturbation: {turn_rad: 0.02}}\n"),
                           &job, &v);
  EXPECT_EQ(job.plan.max_attempts, 40);
  EXPECT_EQ(job.plan.seed, 18446744073709551615ull);
  EXPECT_EQ(job.cord.sets, 5);
  ASSERT_TRUE(job.soft_finger_radius_m.has_value());
  EXPECT_DOUBLE_EQ(*job.soft_finger_radius_m, 0.004);
  EXPECT_EQ(v.trials, 5);
  EXPECT_DOUBLE_EQ(v.perturbation.turn_rad, 0.02);
  // Untouched: the defaults.
  EXPECT_EQ(job.plan.grasps, PlanParams{}.grasps);
  EXPECT_EQ(job.cord.sphere_points, CordParams{}.sphere_points);
  EXPECT_EQ(v.min_held, ValidationParams{}.min_held);
  EXPECT_DOUBLE_EQ(v.perturbation.offset_m, PerturbationParams{}.offset_m);
}

TEST(PlanSettings, PrintedYamlReadsBackToTheSameSettings) {
  PlanJobParams job;
  job.plan.diversity.min_hand_turn_deg = 33.0;
  job.cord.side_cord_policy = SideCordPolicy::kShrink;
  job.units = LengthUnits::kMillimeters;
  ValidationParams v;
  v.budget_s = 12.5;
  const std::string yaml = plan_settings_yaml(job, v);
  PlanJobParams back;
  ValidationParams back_v;
  merge_plan_settings_file(write_file("printed.yaml", yaml), &back, &back_v);
  EXPECT_EQ(plan_settings_yaml(back, back_v), yaml);
}

TEST(PlanSettings, APlanJsonRepeatsItsPlan) {
  const HandModel hand = load_hand("cordgrasp_sah");
  const std::string object = test::source_dir() + "/assets/objects/mug.obj";
  PlanJobParams p;
  p.plan.seed = 4;
  p.plan.grasps = 2;
  p.plan.time_limit_s = 1000.0;  // not hit: deterministic
  p.cord.sets = 6;
  p.cord.sphere_points = 3000;  // no option sets it: only the file carries it
  const Mesh mesh = load_job_mesh(p, object);
  const PlanDocument first = plan_job(p, mesh, object, hand);
  ASSERT_FALSE(first.grasps.empty());
  const std::string path = write_file("first.plan.json", "");
  write_plan_file(path, first, hand);

  PlanJobParams again;
  ValidationParams v;
  merge_plan_settings_file(path, &again, &v);
  EXPECT_EQ(again.cord.sphere_points, 3000);
  const PlanDocument second = plan_job(again, mesh, object, hand);
  ASSERT_EQ(second.grasps.size(), first.grasps.size());
  for (size_t i = 0; i < first.grasps.size(); ++i) {
    EXPECT_TRUE(second.grasps[i].X_OB.matrix() == first.grasps[i].X_OB.matrix()) << i;
    EXPECT_EQ(second.grasps[i].epsilon, first.grasps[i].epsilon) << i;
  }
  EXPECT_EQ(plan_to_json(second, hand).at("parameters"), plan_to_json(first, hand).at("parameters"));
}

TEST(PlanSettings, BadFilesAreRefusedNamingTheFileAndTheKey) {
  EXPECT_NE(refusal("sets.yaml", "cord: {sets: 0}\n").find("cord.sets: 0 is not in [1, 100000]"),
            std::string::npos);
  EXPECT_NE(refusal("unknown.yaml", "cord: {setz: 3}\n").find("cord: unknown key(s) 'setz'"),
            std::string::npos);
  EXPECT_NE(refusal("nan.yaml", "time_limit_s: .nan\n").find("time_limit_s: not a finite number"),
            std::string::npos);
  EXPECT_NE(refusal("type.json", "{\"max_attempts\": \"many\"}").find("max_attempts: expected"),
            std::string::npos);
  EXPECT_NE(refusal("held.yaml", "validation: {trials: 2, min_held: 3}\n")
                .find("validation.min_held: 3 is more than validation.trials (2)"),
            std::string::npos);
  EXPECT_NE(refusal("syntax.yaml", "cord: {sets: [\n").find("YAML syntax error"),
            std::string::npos);
  EXPECT_NE(refusal("list.json", "[1, 2]").find("expected a mapping"), std::string::npos);
  const std::string named = refusal("named.yaml", "cord: {sets: 0}\n");
  EXPECT_NE(named.find("cordgrasp_plan_settings_named.yaml"), std::string::npos) << named;
}

TEST(PlanSettings, TheDocumentedExampleIsAValidDocument) {
  std::ifstream in(test::source_dir() + "/docs/algorithm.md");
  std::stringstream text;
  text << in.rdbuf();
  const std::string doc = text.str();
  const size_t section = doc.find("## 10c.");
  ASSERT_NE(section, std::string::npos);
  const size_t begin = doc.find("```yaml\n", section);
  ASSERT_NE(begin, std::string::npos);
  const size_t end = doc.find("```", begin + 8);
  PlanJobParams job;
  ValidationParams v;
  merge_plan_settings_file(write_file("example.yaml", doc.substr(begin + 8, end - begin - 8)),
                           &job, &v);
  EXPECT_NE(plan_settings_yaml(job, v), plan_settings_yaml(PlanJobParams{}, ValidationParams{}));
}

}  // namespace
}  // namespace cordgrasp
