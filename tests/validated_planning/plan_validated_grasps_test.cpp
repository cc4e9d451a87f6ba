// Validated planning (docs/algorithm.md §10a): accepted grasps hold when the written plan.json is
// validated again by a separate `cordgrasp validate`, and differ pairwise by the diversity
// threshold; the library algorithm (sim) called directly agrees with the job. The parallel
// gripper on the box keeps the CPU small (< 2 s per plan).
#include "cordgrasp/sim/plan_validated_grasps.h"

#include <gtest/gtest.h>
#include <sys/mman.h>
#include <sys/wait.h>
#include <unistd.h>

#include <atomic>
#include <cmath>
#include <csignal>
#include <filesystem>
#include <fstream>
#include <new>
#include <nlohmann/json.hpp>
#include <stdexcept>

#include "cordgrasp/core/assets.h"
#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/mesh_properties.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/validate_job.h"
#include "cordgrasp/jobs/validate_plan.h"
#include "cordgrasp/jobs/validated_plan_job.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr int kTrials = 3;
constexpr int kMinHeld = 2;
constexpr double kBudget_s = 60.0;  ///< not reached on the box (about 1 s)

struct BoxPlan {
  HandModel hand = load_hand("parallel_gripper");
  std::string object = test::source_dir() + "/assets/objects/box.obj";
  PlanJobParams job;
  ValidationParams v;
  Mesh mesh;

  explicit BoxPlan(int grasps) {
    job.plan.grasps = grasps;
    v.trials = kTrials;
    v.min_held = kMinHeld;
    v.budget_s = kBudget_s;
    mesh = load_job_mesh(job, object);
  }
  PlanDocument plan() const {
    return validated_plan_job(job, v, mesh, object, hand);
  }
};

std::string temp_dir(const std::string& name) {
  const auto dir = std::filesystem::temp_directory_path() /
                   ("cordgrasp_validated_" + name + "_" + std::to_string(::getpid()));
  std::filesystem::create_directories(dir);
  return dir.string();
}

TEST(PlanValidatedGrasps, AcceptedGraspsHoldWhenTheWrittenPlanIsValidatedAgain) {
  const BoxPlan box(2);
  const PlanDocument plan = box.plan();
  ASSERT_EQ(plan.grasps.size(), 2u);
  ASSERT_TRUE(plan.validation.has_value());
  const ValidationStats& s = plan.validation->stats;
  EXPECT_EQ(s.accepted, 2);
  // Every simulated candidate is accepted or counted where it was lost.
  EXPECT_EQ(s.simulated, s.accepted + s.rejected_early + s.lost_in_close + s.lost_in_lift +
                             s.lost_in_shake + s.lost_in_gravity6 + s.lost_in_later_trials);
  EXPECT_GE(s.force_closure, s.simulated + s.similar);
  ASSERT_TRUE(s.first_accepted_s.has_value());
  // Held in ≥ K trials, the first (the grasp as planned, which plan.json stores) among them.
  EXPECT_GE(s.held_as_planned, s.accepted);
  for (const GraspValidation& g : plan.validation->grasps) {
    EXPECT_GE(g.held_trials, kMinHeld);
    EXPECT_EQ(g.lift, Outcome::kHeld);
    EXPECT_EQ(g.shake, Outcome::kHeld);
  }

  const std::string dir = temp_dir("revalidate");
  const std::string plan_path = dir + "/plan.json";
  write_plan_file(plan_path, plan, box.hand);
  // Other nudges than the planner's (seed 99), in a separate process.
  const auto r = test::run_cordgrasp("validate --plan '" + plan_path + "' --tests lift,shake "
                                     "--trials " + std::to_string(kTrials) +
                                     " --seed 99 --out '" + dir + "/sim.json'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir + "/sim.json");
  const nlohmann::json sim = nlohmann::json::parse(in);
  ASSERT_EQ(sim.at("grasps").size(), 2u);
  for (const auto& g : sim.at("grasps")) {
    EXPECT_GE(g.at("trials").at("held").get<int>(), kMinHeld) << g.dump();
    // The first trial re-runs the grasp as planned, bit for bit: it holds again.
    EXPECT_EQ(g.at("trials").at("outcomes").at(0).get<std::string>(), "held") << g.dump();
    // Its planned contacts carry the light box's weight many times over.
    EXPECT_GT(g.at("weight_margin").get<double>(), 1.0) << g.dump();
  }
  std::filesystem::remove_all(dir);
}

/// Every pair of `grasps` passes the diversity test of `p` on an object of radius `radius_m`,
/// checked from the pose distances (not by grasps_differ itself).
void expect_pairwise_distinct(const std::vector<Grasp>& grasps, const DiversityParams& p,
                              double radius_m, const std::string& what) {
  const double min_gcp_m =
      std::max(p.min_gcp_distance_m, p.min_gcp_distance_per_radius * radius_m);
  for (size_t a = 0; a < grasps.size(); ++a)
    for (size_t b = a + 1; b < grasps.size(); ++b) {
      const GraspPoseDistance d = grasp_pose_distance(grasps[a], grasps[b]);
      EXPECT_TRUE(d.gcp_m >= min_gcp_m || d.hand_turn_rad >= p.min_hand_turn_deg * M_PI / 180.0)
          << what << " grasps " << a << "," << b << ": " << d.gcp_m << " m, "
          << d.hand_turn_rad << " rad";
    }
}

TEST(PlanValidatedGrasps, AcceptedGraspsDifferPairwiseByTheDiversityThreshold) {
  BoxPlan box(3);
  DiversityParams& d = box.job.plan.diversity;
  d.min_gcp_distance_m = 0.02;  // stricter than the defaults, so near copies do occur
  d.min_hand_turn_deg = 45.0;
  const PlanDocument plan = box.plan();
  ASSERT_GE(plan.grasps.size(), 2u);
  EXPECT_GT(plan.validation->stats.similar, 0);
  expect_pairwise_distinct(plan.grasps, d, bounding_radius(box.mesh, vertex_mean(box.mesh)),
                           "validated box");
}

/// The algorithm's inputs for `box` as a library user builds them by hand (sim level, no job):
/// seeds from plan.seed, the hand's soft-finger radius, the plan's time limit on the
/// exploration, the rules' protocol with the plan's friction model and squeeze-shift limit.
struct SimLevelInputs {
  PlanParams plan;
  CordParams cord;
  SimParams sim;

  explicit SimLevelInputs(const BoxPlan& box) : plan(box.job.plan), cord(box.job.cord) {
    plan.quality.contact.soft_finger_radius_m = box.hand.soft_finger_radius_m;
    plan.quality.seed = plan.seed;
    cord.seed = plan.seed;
    cord.time_limit_s = plan.time_limit_s;
    sim = sim_params_for(box.v.protocol);
    sim.contact = plan.quality.contact;
    sim.squeeze_shift_limit_m = box.v.squeeze_shift_limit_m;
  }
};

TEST(PlanValidatedGrasps, TheLibraryAlgorithmAcceptsDistinctHeldGraspsAndTheJobAgrees) {
  BoxPlan box(3);
  DiversityParams& d = box.job.plan.diversity;
  d.min_gcp_distance_m = 0.02;  // near copies occur: the diversity skip runs
  d.min_hand_turn_deg = 45.0;
  const SimLevelInputs in(box);
  const ValidatedPlan direct = plan_validated_grasps(box.mesh, box.hand, PlannerKind::kCord,
                                                     in.plan, in.cord, box.v, in.sim);
  EXPECT_FALSE(direct.interrupted);
  ASSERT_GE(direct.grasps.size(), 2u);  // pairs to check
  const PlanValidation& record = direct.validation;
  ASSERT_EQ(record.grasps.size(), direct.grasps.size());
  EXPECT_EQ(record.stats.accepted, static_cast<int>(direct.grasps.size()));
  EXPECT_GT(record.stats.similar, 0);
  EXPECT_EQ(record.params.min_held, kMinHeld);
  EXPECT_EQ(record.stats.force_closure, direct.stats.force_closure);
  for (const GraspValidation& g : record.grasps) {
    EXPECT_GE(g.held_trials, kMinHeld);
    EXPECT_LE(g.held_trials, g.trials);
    EXPECT_LE(g.trials, kTrials);
    EXPECT_EQ(g.lift, Outcome::kHeld);  // held as planned (require_held_as_planned)
  }
  expect_pairwise_distinct(direct.grasps, d, bounding_radius(box.mesh, vertex_mean(box.mesh)),
                           "sim-level validated box");

  // The job (plan document, physics_settings) reaches the same grasps and verdicts.
  const PlanDocument job = box.plan();
  ASSERT_EQ(job.grasps.size(), direct.grasps.size());
  ASSERT_TRUE(job.validation.has_value());
  for (size_t k = 0; k < job.grasps.size(); ++k) {
    EXPECT_TRUE(job.grasps[k].X_OB.matrix() == direct.grasps[k].X_OB.matrix()) << k;
    EXPECT_TRUE(job.grasps[k].q == direct.grasps[k].q) << k;
    EXPECT_EQ(job.grasps[k].region_rank, direct.grasps[k].region_rank) << k;
    EXPECT_EQ(job.validation->grasps[k].held_trials, record.grasps[k].held_trials) << k;
    EXPECT_EQ(job.validation->grasps[k].trials, record.grasps[k].trials) << k;
    EXPECT_EQ(job.validation->grasps[k].squeeze_shift_m, record.grasps[k].squeeze_shift_m) << k;
  }
  EXPECT_EQ(job.validation->stats.similar, record.stats.similar);
  EXPECT_EQ(job.validation->stats.simulated, record.stats.simulated);
  EXPECT_EQ(job.validation->stats.trials_run, record.stats.trials_run);
  EXPECT_EQ(job.stats.attempts, direct.stats.attempts);
  EXPECT_EQ(job.interrupted, "");

  // The cord planner needs its exploration parameters.
  EXPECT_THROW(plan_validated_grasps(box.mesh, box.hand, PlannerKind::kCord, in.plan,
                                     std::nullopt, box.v, in.sim),
               std::invalid_argument);
}

/// Stops and continues this process from a child process, half of the time, until destroyed:
/// wall-clock time then passes about twice as fast as this process's CPU time (a busy machine).
class HalfTimeStopper {
 public:
  HalfTimeStopper() {
    done_ = static_cast<std::atomic<int>*>(mmap(nullptr, sizeof(std::atomic<int>),
                                                PROT_READ | PROT_WRITE, MAP_SHARED | MAP_ANONYMOUS,
                                                -1, 0));
    new (done_) std::atomic<int>(0);
    const pid_t parent = ::getpid();
    child_ = ::fork();
    if (child_ == 0) {
      // Each stop is followed by a continue; the flag is read only between the pairs.
      while (done_->load() == 0) {
        ::kill(parent, SIGSTOP);
        ::usleep(kHalfPeriod_us);
        ::kill(parent, SIGCONT);
        ::usleep(kHalfPeriod_us);
      }
      ::_exit(0);
    }
  }
  ~HalfTimeStopper() {
    done_->store(1);
    if (child_ > 0) ::waitpid(child_, nullptr, 0);
    munmap(done_, sizeof(std::atomic<int>));
  }
  HalfTimeStopper(const HalfTimeStopper&) = delete;
  HalfTimeStopper& operator=(const HalfTimeStopper&) = delete;

 private:
  static constexpr useconds_t kHalfPeriod_us = 20000;
  std::atomic<int>* done_ = nullptr;
  pid_t child_ = -1;
};

TEST(PlanValidatedGrasps, SpendsItsCpuBudgetWhenWallTimePassesFaster) {
  // No grasp reaches the quality threshold: the whole budget goes to the planner, first to the
  // kettle's cord regions (wall-clock limits inside), then to the sampled fallback.
  constexpr double kBudget_s = 0.8;       ///< CPU
  constexpr double kSpentFraction = 0.9;  ///< of the budget, at least
  constexpr double kUnreachableEpsilon = 10.0;
  const HandModel hand = load_hand("parallel_gripper");
  const Mesh kettle = load_mesh(test::source_dir() + "/assets/objects/kettle.obj");
  const PlanJobParams job;
  PlanParams plan = job.plan;
  plan.grasps = 1;
  plan.quality.min_epsilon = kUnreachableEpsilon;
  plan.quality.contact.soft_finger_radius_m = hand.soft_finger_radius_m;
  ValidationParams v;
  v.budget_s = kBudget_s;
  const SimParams sim = sim_params_for(v.protocol);
  ValidatedPlan result;
  {
    const HalfTimeStopper busy;
    result = plan_validated_grasps(kettle, hand, PlannerKind::kCord, plan, job.cord, v, sim);
  }
  EXPECT_TRUE(result.grasps.empty());
  EXPECT_EQ(result.validation.stats.force_closure, 0);
  EXPECT_TRUE(result.validation.stats.budget_spent);
  EXPECT_GE(result.validation.stats.cpu_s, kSpentFraction * kBudget_s);
}

TEST(PlanValidatedGrasps, UnderUncertaintyAcceptsDecidedHoldProbabilitiesRankedTheSameForAnyJobs) {
  constexpr int kMaxDraws = 6;         ///< 6 of 6 held: Wilson low 0.61
  constexpr double kThreshold = 0.5;   ///< decidable within kMaxDraws
  BoxPlan box(2);
  box.v.tests = "lift";
  box.v.uncertainty = UncertaintyParams{};  // realistic: ~20 candidates, ~5 s CPU per plan
  box.v.min_hold_probability = kThreshold;
  box.v.max_draws = kMaxDraws;
  const SimLevelInputs in(box);
  std::vector<std::string> lines;
  const auto plan = [&](int jobs) {
    lines.clear();
    return plan_validated_grasps(box.mesh, box.hand, PlannerKind::kCord, in.plan, in.cord, box.v,
                                 in.sim, jobs,
                                 [&](const std::string& line) { lines.push_back(line); });
  };
  const ValidatedPlan one = plan(1);
  ASSERT_FALSE(one.grasps.empty());
  // Every acceptance followed a second test on draws of its own (the winner's curse).
  int accepted_lines = 0;
  for (const std::string& line : lines)
    if (line.find(", accepted (") != std::string::npos) {
      ++accepted_lines;
      EXPECT_NE(line.find("; confirmation: "), std::string::npos) << line;
    }
  EXPECT_EQ(accepted_lines, static_cast<int>(one.grasps.size()));
  const std::vector<GraspValidation>& record = one.validation.grasps;
  ASSERT_EQ(record.size(), one.grasps.size());
  double last_p = 1.0;
  for (const GraspValidation& g : record) {
    EXPECT_LE(g.trials, kMaxDraws);
    EXPECT_GT(wilson_interval(g.held_trials, g.trials).low, kThreshold);  // decided above
    EXPECT_EQ(g.lift, Outcome::kHeld);  // and held as planned
    const double p = static_cast<double>(g.held_trials) / g.trials;
    EXPECT_LE(p, last_p);  // ranked by P(held)
    last_p = p;
  }
  const ValidatedPlan two = plan(2);  // two draws at once: the same test, the same grasps
  ASSERT_EQ(two.grasps.size(), one.grasps.size());
  for (size_t k = 0; k < one.grasps.size(); ++k) {
    EXPECT_TRUE(two.grasps[k].X_OB.matrix() == one.grasps[k].X_OB.matrix()) << k;
    EXPECT_EQ(two.validation.grasps[k].held_trials, record[k].held_trials) << k;
    EXPECT_EQ(two.validation.grasps[k].trials, record[k].trials) << k;
  }
  EXPECT_GE(two.validation.stats.trials_run, one.validation.stats.trials_run);

  // The record keeps the model and reads back; a plan validated before P(held) (no such
  // keys) reads as one accepted by nudged trials.
  PlanDocument doc;
  doc.hand_name = box.hand.name;
  doc.grasps = one.grasps;
  doc.validation = one.validation;
  const nlohmann::json j = plan_to_json(doc, box.hand);
  const PlanDocument back = plan_from_json(j, box.hand, "plan.json");
  EXPECT_EQ(back.validation->params.uncertainty.mass_relative_spread,
            UncertaintyParams{}.mass_relative_spread);
  EXPECT_EQ(back.validation->params.max_draws, kMaxDraws);
  nlohmann::json older = j;
  for (const char* key : {"uncertainty", "min_hold_probability", "max_draws"})
    older["validation"]["parameters"].erase(key);
  const std::string dir = temp_dir("older");
  std::ofstream(dir + "/plan.json") << older.dump();
  const PlanDocument read =
      plan_from_json(read_plan_json(dir + "/plan.json"), box.hand, dir + "/plan.json");
  EXPECT_TRUE(is_none(read.validation->params.uncertainty));
  std::filesystem::remove_all(dir);
}

TEST(PlainPlanning, ReturnsGraspsThatDifferPairwiseOnEveryShippedObject) {
  // `cordgrasp plan --grasps 4` with its defaults (the default hand, the cord planner).
  constexpr int kGrasps = 4;
  const HandModel hand = load_hand(default_hand_name());
  PlanJobParams job;
  job.plan.grasps = kGrasps;
  const auto objects = test::files_in(test::source_dir() + "/assets/objects", ".obj");
  ASSERT_GE(objects.size(), 10u);
  int with_several = 0;
  for (const std::string& path : objects) {
    const Mesh mesh = load_job_mesh(job, path);
    const PlanDocument plan = plan_job(job, mesh, path, hand);
    with_several += plan.grasps.size() >= 2;
    expect_pairwise_distinct(plan.grasps, job.plan.diversity,
                             bounding_radius(mesh, vertex_mean(mesh)), path);
  }
  EXPECT_GE(with_several, 5);  // the test has pairs to check
}

TEST(PlanValidatedGrasps, ValidationRecordRoundTripsThroughPlanJsonAndIsReadStrictly) {
  const BoxPlan box(1);
  const PlanDocument plan = box.plan();
  ASSERT_EQ(plan.grasps.size(), 1u);
  nlohmann::json j = plan_to_json(plan, box.hand);
  const PlanDocument back = plan_from_json(j, box.hand, "plan.json");
  ASSERT_TRUE(back.validation.has_value());
  EXPECT_EQ(back.validation->grasps.size(), 1u);
  EXPECT_EQ(back.validation->grasps[0].held_trials, plan.validation->grasps[0].held_trials);
  EXPECT_EQ(back.validation->grasps[0].lift, plan.validation->grasps[0].lift);
  EXPECT_EQ(back.validation->stats.accepted, plan.validation->stats.accepted);
  EXPECT_EQ(back.validation->stats.lost_in_lift, plan.validation->stats.lost_in_lift);
  EXPECT_DOUBLE_EQ(back.validation->stats.object_mass_kg, plan.validation->stats.object_mass_kg);
  EXPECT_EQ(back.params.diversity.min_hand_turn_deg, box.job.plan.diversity.min_hand_turn_deg);

  // A plan written before the loss counts existed reads them as 0; an unknown count is refused.
  nlohmann::json older = j;
  older["validation"]["stats"].erase("lost_in_lift");
  older["validation"]["stats"].erase("lost_not_pressing");
  older["validation"]["stats"].erase("lost_below_weight_margin");
  const PlanDocument old_plan = plan_from_json(older, box.hand, "plan.json");
  EXPECT_EQ(old_plan.validation->stats.lost_in_lift, 0);
  EXPECT_EQ(old_plan.validation->stats.lost_not_pressing, 0);
  EXPECT_EQ(old_plan.validation->stats.lost_below_weight_margin, 0);
  nlohmann::json unknown_count = j;
  unknown_count["validation"]["stats"]["lost_in_space"] = 1;
  EXPECT_THROW(plan_from_json(unknown_count, box.hand, "plan.json"), InputError);

  nlohmann::json unknown = j;
  unknown["grasps"][0]["validation"]["held"] = 1;
  EXPECT_THROW(plan_from_json(unknown, box.hand, "plan.json"), InputError);
  nlohmann::json missing = j;
  missing["grasps"][0].erase("validation");
  EXPECT_THROW(plan_from_json(missing, box.hand, "plan.json"), InputError);
  nlohmann::json bad_outcome = j;
  bad_outcome["grasps"][0]["validation"]["lift"] = "fine";
  EXPECT_THROW(plan_from_json(bad_outcome, box.hand, "plan.json"), InputError);
}

TEST(PlanValidatedGrasps, ValidatingThePlanAgainTestsTheObjectItWasAcceptedWith) {
  constexpr double kMass_kg = 0.123;      // not the box's 500 kg/m³ × 200 cm³ = 0.1 kg
  constexpr double kSqueezeWeight = 12.0;  // not the default
  constexpr double kDensity_kgm3 = 1000.0;
  constexpr double kBoxVolume_m3 = 0.05 * 0.05 * 0.08;
  BoxPlan box(1);
  box.v.physics.mass_kg = kMass_kg;
  box.v.physics.squeeze_weight_factor = kSqueezeWeight;
  const PlanDocument plan = box.plan();
  ASSERT_EQ(plan.grasps.size(), 1u);
  EXPECT_DOUBLE_EQ(plan.validation->grasps[0].mass_kg, kMass_kg);  // simulated with it

  const std::string dir = temp_dir("overrides");
  const std::string plan_path = dir + "/plan.json";
  write_plan_file(plan_path, plan, box.hand);
  const auto validate = [&](const SimOverrides& overrides) {
    ValidateJobParams p;  // validate --plan; the density and squeeze weight: library only
    p.plan = plan_path;
    p.tests = "lift";
    p.physics = overrides;
    p.out = dir + "/sim.json";
    validate_job(p);
    std::ifstream in(dir + "/sim.json");
    return nlohmann::json::parse(in);
  };
  // Nothing given: the plan's record.
  nlohmann::json sim = validate({});
  EXPECT_DOUBLE_EQ(sim.at("object").at("mass_kg").get<double>(), kMass_kg);
  EXPECT_DOUBLE_EQ(sim.at("parameters").at("squeeze_weight_factor").get<double>(),
                   kSqueezeWeight);
  // A density given replaces the recorded mass (one choice of weight); the factor stays.
  SimOverrides density;
  density.density_kgm3 = kDensity_kgm3;
  sim = validate(density);
  EXPECT_NEAR(sim.at("object").at("mass_kg").get<double>(), kDensity_kgm3 * kBoxVolume_m3,
              1e-3 * kDensity_kgm3 * kBoxVolume_m3);
  EXPECT_DOUBLE_EQ(sim.at("parameters").at("squeeze_weight_factor").get<double>(),
                   kSqueezeWeight);
  SimOverrides weight;
  weight.squeeze_weight_factor = 0.0;
  sim = validate(weight);
  EXPECT_DOUBLE_EQ(sim.at("parameters").at("squeeze_weight_factor").get<double>(), 0.0);
  EXPECT_DOUBLE_EQ(sim.at("object").at("mass_kg").get<double>(), kMass_kg);
  std::filesystem::remove_all(dir);
}

TEST(PlanValidatedGrasps, ItsPhysicsSettingsFileIsRecordedAndUsedAgainByValidate) {
  constexpr int kIterations = 40;     // not the default 30
  constexpr double kLift_m = 0.05;    // not the default 10 cm
  const std::string dir = temp_dir("physics_file");
  const std::string file = dir + "/physics.yaml";
  std::ofstream(file) << "solver_iterations: " << kIterations << "\nlift_height_m: " << kLift_m
                      << "\n";
  BoxPlan box(1);
  box.v.physics_file = file;
  const PlanDocument plan = box.plan();
  ASSERT_EQ(plan.grasps.size(), 1u);
  EXPECT_EQ(plan.validation->params.physics_file, file);
  const std::string plan_path = dir + "/plan.json";
  write_plan_file(plan_path, plan, box.hand);
  const auto r = test::run_cordgrasp("validate --plan '" + plan_path + "' --tests lift --out '" +
                                     dir + "/sim.json'");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(dir + "/sim.json");
  const nlohmann::json sim = nlohmann::json::parse(in);
  EXPECT_EQ(sim.at("parameters").at("solver_iterations"), kIterations);
  EXPECT_DOUBLE_EQ(sim.at("parameters").at("lift_height_m").get<double>(), kLift_m);
  EXPECT_EQ(sim.at("grasps").at(0).at("outcome"), "held");  // as it was accepted
  // A bad file stops validated planning before any simulation, naming the file and field.
  std::ofstream(file) << "solver_iterations: 0\n";
  try {
    box.plan();
    FAIL() << "a solver_iterations of 0 was accepted";
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("physics.yaml': solver_iterations"), std::string::npos)
        << e.what();
  }
  std::filesystem::remove_all(dir);
}

TEST(PlanValidatedGrasps, SaysWhereCandidatesLostAnObjectTooHeavyForTheHand) {
  constexpr double kHeavy_kg = 20.0;  // far beyond the gripper's grip
  constexpr double kBudget_s = 2.0;   // CPU: a handful of candidates
  const std::string dir = temp_dir("heavy");
  const std::string file = dir + "/physics.yaml";
  std::ofstream(file) << "mass_kg: " << kHeavy_kg << "\n";
  BoxPlan box(1);
  box.v.physics_file = file;
  box.v.budget_s = kBudget_s;
  const PlanDocument plan = box.plan();
  ASSERT_TRUE(plan.validation.has_value());
  const ValidationStats& s = plan.validation->stats;
  EXPECT_EQ(s.accepted, 0);
  ASSERT_GT(s.simulated, 0);
  EXPECT_DOUBLE_EQ(s.object_mass_kg, kHeavy_kg);
  EXPECT_EQ(s.simulated, s.rejected_early + s.lost_in_close + s.lost_in_lift + s.lost_in_shake +
                             s.lost_in_gravity6 + s.lost_in_later_trials);
  EXPECT_GT(2 * (s.lost_in_lift + s.lost_in_shake), s.simulated);
  const std::string message = no_accepted_grasp_message("plan", plan, box.mesh);
  EXPECT_NE(message.find("lost the object (20.000 kg) in lift or shake"), std::string::npos)
      << message;
  // No contact of the gripper carries 20 kg within its effort limits: the weight margin, a
  // static bound computed before the physics, says so for every candidate lost to gravity.
  EXPECT_EQ(s.lost_below_weight_margin, s.lost_in_lift + s.lost_in_shake + s.lost_in_gravity6);
  EXPECT_NE(message.find("cannot carry its weight within the hand's joint effort limits"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find(std::to_string(s.lost_below_weight_margin) +
                         " with contacts too weak for the weight"),
            std::string::npos)
      << message;
  // The gripper's pads pressed the box at their effort caps: too weak, not idle.
  EXPECT_LT(2 * s.lost_not_pressing, s.lost_in_lift + s.lost_in_shake);
  EXPECT_NE(message.find("lost as planned in close " + std::to_string(s.lost_in_close) + ", lift " +
                         std::to_string(s.lost_in_lift)),
            std::string::npos)
      << message;
  // Candidates lost while closing say nothing of the weight.
  PlanDocument closing = plan;
  ValidationStats& c = closing.validation->stats;
  c.lost_in_close += c.lost_in_lift + c.lost_in_shake;
  c.lost_in_lift = c.lost_in_shake = 0;
  EXPECT_EQ(no_accepted_grasp_message("plan", closing, box.mesh).find("lost the object"),
            std::string::npos);
  // Fingers that touched the object without pressing it say so instead of blaming the weight.
  PlanDocument idle = plan;
  ValidationStats& i = idle.validation->stats;
  i.lost_not_pressing = i.lost_in_lift + i.lost_in_shake;
  i.lost_below_weight_margin = 0;
  const std::string idle_message = no_accepted_grasp_message("plan", idle, box.mesh);
  EXPECT_NE(idle_message.find("with no finger pressing it"), std::string::npos) << idle_message;
  EXPECT_EQ(idle_message.find("effort limits"), std::string::npos) << idle_message;
  // Pressing fingers whose contacts could carry the weight: neither the hand nor the squeeze.
  PlanDocument strong = plan;
  ValidationStats& g = strong.validation->stats;
  g.lost_below_weight_margin = g.lost_not_pressing = 0;
  const std::string strong_message = no_accepted_grasp_message("plan", strong, box.mesh);
  EXPECT_NE(strong_message.find("although their contacts could carry its weight"),
            std::string::npos)
      << strong_message;
  EXPECT_EQ(strong_message.find("effort limits"), std::string::npos) << strong_message;
  EXPECT_NE(idle_message.find(std::to_string(i.lost_not_pressing) +
                              " after the close with no finger pressing the object"),
            std::string::npos)
      << idle_message;
  std::filesystem::remove_all(dir);
}

TEST(GraspsDiffer, ByGcpDistanceOrHandTurn) {
  const DiversityParams v;  // 1 cm or a quarter of the radius, 20°
  constexpr double kSmallObjectRadius_m = 0.02;  // a quarter is 5 mm: 1 cm counts
  constexpr double kLargeObjectRadius_m = 0.08;  // a quarter is 2 cm
  Grasp a, b;
  EXPECT_FALSE(grasps_differ(a, b, v, kSmallObjectRadius_m));
  b.X_OG.translation() = Eigen::Vector3d(0.009, 0, 0);
  b.X_OB.linear() = Eigen::AngleAxisd(19.0 * M_PI / 180.0, Eigen::Vector3d::UnitZ()).matrix();
  EXPECT_FALSE(grasps_differ(a, b, v, kSmallObjectRadius_m));
  b.X_OG.translation() = Eigen::Vector3d(0.011, 0, 0);
  EXPECT_TRUE(grasps_differ(a, b, v, kSmallObjectRadius_m));
  // On a large object 1.1 cm is the same grasp slid along it; 2.1 cm is another.
  EXPECT_FALSE(grasps_differ(a, b, v, kLargeObjectRadius_m));
  b.X_OG.translation() = Eigen::Vector3d(0.0, 0.021, 0);
  EXPECT_TRUE(grasps_differ(a, b, v, kLargeObjectRadius_m));
  EXPECT_DOUBLE_EQ(min_gcp_distance_m(v, kLargeObjectRadius_m), 0.02);
  b.X_OG.translation().setZero();
  b.X_OB.linear() = Eigen::AngleAxisd(21.0 * M_PI / 180.0, Eigen::Vector3d::UnitX()).matrix();
  EXPECT_TRUE(grasps_differ(a, b, v, kLargeObjectRadius_m));
  EXPECT_NEAR(grasp_pose_distance(a, b).hand_turn_rad, 21.0 * M_PI / 180.0, 1e-12);
}

TEST(PlanValidatedGrasps, ACancelledPlanStopsBeforeItsNextCandidateAndSaysSo) {
  const BoxPlan box(2);
  std::atomic<int> signal{SIGINT};  // asked to stop before it began
  const PlanDocument plan = validated_plan_job(box.job, box.v, box.mesh, box.object, box.hand,
                                               1, {}, CancelToken(&signal));
  EXPECT_EQ(plan.interrupted, "SIGINT");
  EXPECT_TRUE(plan.stats.interrupted);
  EXPECT_TRUE(plan.grasps.empty());
  EXPECT_EQ(plan.validation->stats.simulated, 0);
  EXPECT_FALSE(plan.validation->stats.budget_spent);
  // Not cancelled: the same plan runs to its end.
  signal = 0;
  const PlanDocument whole = validated_plan_job(box.job, box.v, box.mesh, box.object, box.hand,
                                                1, {}, CancelToken(&signal));
  EXPECT_EQ(whole.interrupted, "");
  EXPECT_EQ(whole.grasps.size(), 2u);
}

TEST(ValidatePlan, ACancelledValidationSimulatesNothingAndIsMarkedIncomplete) {
  const BoxPlan box(1);
  const PlanDocument plan = box.plan();
  ASSERT_EQ(plan.grasps.size(), 1u);
  std::atomic<int> signal{SIGTERM};
  SimDocument doc = validate_plan(plan, box.hand, box.mesh, SimParams{}, SimTests{}, -1, {}, {},
                                  1, CancelToken(&signal));
  EXPECT_EQ(doc.interrupted, "SIGTERM");
  EXPECT_TRUE(doc.results.empty());
  EXPECT_TRUE(doc.grasp_indices.empty());
  EXPECT_EQ(doc.grasps_asked, 1);
  // Trials of a document whose grasps all ran, then cancelled: no grasp has every trial.
  signal = 0;
  doc = validate_plan(plan, box.hand, box.mesh, SimParams{}, SimTests{}, -1, {}, {}, 1,
                      CancelToken(&signal));
  ASSERT_EQ(doc.results.size(), 1u);
  EXPECT_EQ(doc.interrupted, "");
  signal = SIGINT;
  add_perturbed_trials(doc, plan, box.hand, box.mesh, 3, PerturbationParams{}, 1, {}, 1,
                       CancelToken(&signal));
  EXPECT_EQ(doc.interrupted, "SIGINT");
  EXPECT_TRUE(doc.results.empty());
  EXPECT_TRUE(doc.trial_outcomes.empty());
  EXPECT_EQ(doc.trials, 3);
}

TEST(PlanValidatedGrasps, RejectsMinHeldAboveTrials) {
  BoxPlan box(1);
  box.v.min_held = kTrials + 1;
  EXPECT_THROW(box.plan(), std::invalid_argument);
}

}  // namespace
}  // namespace cordgrasp
