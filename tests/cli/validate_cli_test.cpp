// `cordgrasp validate`: a plan.json written here (the parallel gripper pinching the shipped
// box), its sim.json, the summary lines, and the errors for mismatched inputs.
#include <gtest/gtest.h>
#include <unistd.h>

#include <filesystem>
#include <fstream>
#include <map>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/jobs/sim_json.h"
#include "cordgrasp/jobs/validate_job.h"
#include "cordgrasp/render/animation.h"
#include "cordgrasp/sim/grasp_validation.h"
#include "cordgrasp/sim/sim_params.h"
#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

using test::run_cordgrasp;
using test::source_dir;

constexpr double kBoxHalfWidth_m = 0.025;  ///< assets/objects/box.obj: 5 × 5 × 8 cm, z ≥ 0
constexpr double kBoxCentreZ_m = 0.04;
constexpr std::uint64_t kPlanSeed = 7;

// plan.json "parameters" of a generic plan with seed kPlanSeed and μ 0.5 (every key present).
nlohmann::json generic_plan_parameters() {
  const HandModel hand = load_hand("parallel_gripper");
  PlanDocument doc;
  doc.planner = PlannerKind::kGeneric;
  doc.params.seed = kPlanSeed;
  doc.params.quality.contact.mu = 0.5;
  return plan_to_json(doc, hand).at("parameters");
}

nlohmann::json pose_json(const Eigen::Isometry3d& X) {
  const Eigen::Quaterniond q(X.linear());
  return {{"position_m", {X.translation().x(), X.translation().y(), X.translation().z()}},
          {"quaternion_wxyz", {q.w(), q.x(), q.y(), q.z()}}};
}

class ValidateCli : public ::testing::Test {
 protected:
  void SetUp() override {
    dir_ = std::filesystem::temp_directory_path() /
           ("cordgrasp_validate_" + std::to_string(::getpid()) + "_" +
            ::testing::UnitTest::GetInstance()->current_test_info()->name());
    std::filesystem::create_directories(dir_);
    write_plan(plan_path(), 2);
  }
  void TearDown() override { std::filesystem::remove_all(dir_); }

  std::string plan_path() const { return (dir_ / "plan.json").string(); }
  std::string out_path() const { return (dir_ / "sim.json").string(); }
  std::string box_path() const { return source_dir() + "/assets/objects/box.obj"; }

  /// A plan for the shipped parallel gripper: `grasps` copies of a top-down pinch at the box
  /// centre (pads on the ±x faces).
  void write_plan(const std::string& path, int grasps) const {
    const HandModel hand = load_hand("parallel_gripper");
    Eigen::Isometry3d X_OG = Eigen::Isometry3d::Identity();
    X_OG.linear() = Eigen::Vector3d(1, -1, -1).asDiagonal();
    X_OG.translation() = Eigen::Vector3d(0, 0, kBoxCentreZ_m);
    Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(hand.joints.size()));
    q[find_joint(hand, "left_finger_joint")] = kBoxHalfWidth_m;
    q = apply_couplings(hand, q);
    const Eigen::Isometry3d X_OB = root_pose_for_gcp(hand, q, X_OG);
    nlohmann::json grasp = {
        {"hand_pose", pose_json(X_OB)},
        {"gcp_pose", pose_json(X_OG)},
        {"joints",
         {{"left_finger_joint", q[find_joint(hand, "left_finger_joint")]},
          {"right_finger_joint", q[find_joint(hand, "right_finger_joint")]}}},
        {"preshape_joints", {{"left_finger_joint", 0.05}, {"right_finger_joint", 0.05}}},
        {"contacts", nlohmann::json::array()},
        {"force_closure", true},
        {"epsilon", 0.1},
        {"alpha_rad", 0.0}};
    nlohmann::json plan = {
        {"format", "cordgrasp-plan"},
        {"format_version", 2},
        {"cordgrasp_version", "test"},
        {"inputs",
         {{"hand", {{"name", "parallel_gripper"}, {"path", resolve_hand_path("parallel_gripper")},
                    {"urdf_path", ""}}},
          {"object", {{"path", box_path()}, {"name", "box"}, {"units", "m"},
                      {"triangles", 420}}}}},
        {"parameters", generic_plan_parameters()},
        {"stats", nlohmann::json::object()},
        {"grasps", nlohmann::json::array()}};
    for (int k = 0; k < grasps; ++k) plan["grasps"].push_back(grasp);
    std::ofstream(path) << plan.dump(1);
  }

  /// `validate --plan <plan> <args> --out <out>` fails, names `needle` and writes nothing.
  void expect_error(const std::string& args, const std::string& needle) const {
    const auto r = run_cordgrasp("validate --plan " + plan_path() + " " + args + " --out " +
                                 out_path());
    EXPECT_NE(r.exit_code, 0);
    EXPECT_NE(r.output.find(needle), std::string::npos) << r.output;
    EXPECT_FALSE(std::filesystem::exists(out_path()));
  }

  nlohmann::json read_out() const {
    std::ifstream in(out_path());
    return nlohmann::json::parse(in);
  }

  std::filesystem::path dir_;
};

/// `j` without its timings (wall-clock and CPU keys and the decomposition time).
nlohmann::json without_timings(const nlohmann::json& j) {
  if (j.is_object()) {
    nlohmann::json out = nlohmann::json::object();
    for (const auto& [key, value] : j.items())
      if (key.find("wall") == std::string::npos && key != "cpu_s" && key != "decomposition_s")
        out[key] = without_timings(value);
    return out;
  }
  if (j.is_array()) {
    nlohmann::json out = nlohmann::json::array();
    for (const auto& value : j) out.push_back(without_timings(value));
    return out;
  }
  return j;
}

TEST_F(ValidateCli, ThreadsDoNotChangeTheResults) {
  write_plan(plan_path(), 3);
  const std::string one = (dir_ / "one.json").string(), three = (dir_ / "three.json").string();
  const std::string args = "validate --plan " + plan_path() + " --tests lift --trials 2 -q";
  const auto r1 = run_cordgrasp(args + " --jobs 1 --out " + one);
  ASSERT_EQ(r1.exit_code, 0) << r1.output;
  const auto r3 = run_cordgrasp(args + " --jobs 3 --out " + three);
  ASSERT_EQ(r3.exit_code, 0) << r3.output;
  std::ifstream a(one), b(three);
  const nlohmann::json sim1 = nlohmann::json::parse(a), sim3 = nlohmann::json::parse(b);
  ASSERT_EQ(sim1["grasps"].size(), 3u);
  EXPECT_EQ(without_timings(sim1["grasps"]), without_timings(sim3["grasps"]));
  EXPECT_EQ(without_timings(sim1["summary"]), without_timings(sim3["summary"]));
  // The per-grasp lines come in grasp order whatever thread finished first.
  EXPECT_LT(r3.output.find("grasp 0:"), r3.output.find("grasp 1:")) << r3.output;
  EXPECT_LT(r3.output.find("grasp 1:"), r3.output.find("grasp 2:")) << r3.output;
}

TEST_F(ValidateCli, WritesSimJsonAndOneLinePerGraspAndATotal) {
  const auto r = run_cordgrasp("validate --plan " + plan_path() +
                               " --tests lift,shake --protocol thorough --out " + out_path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("grasp 0: held"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("grasp 1: held"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("held 2 / 2"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("validate: 2/2 grasps"), std::string::npos) << r.output;  // stderr
  const nlohmann::json sim = read_out();
  EXPECT_EQ(sim["format"], "cordgrasp-sim");
  EXPECT_EQ(sim["format_version"], 2);
  EXPECT_EQ(sim["summary"]["grasps"], 2);
  EXPECT_EQ(sim["summary"]["held"], 2);
  EXPECT_EQ(sim["inputs"]["plan_seed"], kPlanSeed);
  EXPECT_EQ(sim["inputs"]["hand"]["name"], "parallel_gripper");
  EXPECT_EQ(sim["parameters"]["tests"], "lift,shake");
  EXPECT_EQ(sim["parameters"]["protocol"], "thorough");
  EXPECT_EQ(sim["parameters"]["lift_hold_s"], 1.0);
  EXPECT_EQ(sim["parameters"]["contact"]["mu"], 0.5);
  EXPECT_TRUE(sim["backend"].get<std::string>().find("Bullet") != std::string::npos);
  ASSERT_EQ(sim["grasps"].size(), 2u);
  const auto& g = sim["grasps"][0];
  EXPECT_EQ(g["outcome"], "held");
  EXPECT_TRUE(g["failed_phase"].is_null());
  EXPECT_FALSE(g["preshape_overlap"].get<bool>());
  EXPECT_EQ(r.output.find("overlaps the object"), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("preshape overlaps 0"), std::string::npos) << r.output;
  std::vector<std::string> phases;
  for (const auto& p : g["phases"]) phases.push_back(p["name"]);
  EXPECT_EQ(phases, (std::vector<std::string>{"settle", "close", "lift", "shake"}));
  const auto& lift = g["phases"][2];
  EXPECT_TRUE(lift["joint_efforts"].contains("left_finger_joint"));
  // The held grasp's pads press the object at the end of the close; settle is before it.
  EXPECT_GE(g["phases"][1]["squeeze_effort_ratio"].get<double>(), kPressingEffortRatio);
  EXPECT_EQ(g["phases"][0]["squeeze_effort_ratio"].get<double>(), 0.0);
  EXPECT_TRUE(g["weight_margin"].is_null());  // this plan names no planned contacts
  EXPECT_GT(lift["contact_count"].get<int>(), 0);
  EXPECT_GT(lift["sim_time_s"].get<double>(), 1.9);
  EXPECT_GT(sim["object"]["mass_kg"].get<double>(), 0.0);
}

TEST_F(ValidateCli, MuOverrideOfZeroDropsEveryGrasp) {
  write_plan(plan_path(), 1);  // one grasp is enough here
  const auto r = run_cordgrasp("validate --plan " + plan_path() +
                               " --tests lift --mu 0 -q --protocol thorough --out " +
                               out_path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("held 0 / 1"), std::string::npos) << r.output;
  EXPECT_EQ(r.output.find("validate: "), std::string::npos) << r.output;  // --quiet
  const nlohmann::json sim = read_out();
  EXPECT_EQ(sim["parameters"]["contact"]["mu"], 0.0);
  EXPECT_EQ(sim["grasps"][0]["outcome"], "dropped");
  // The failure is counted under the phase that failed, in the summary and on stdout.
  const std::string failed = sim["grasps"][0]["failed_phase"];
  EXPECT_EQ(sim["summary"]["not_held_by_phase"][failed], 1);
  int failures = 0;
  for (const auto& [phase, count] : sim["summary"]["not_held_by_phase"].items())
    failures += count.get<int>();
  EXPECT_EQ(failures, 1);
  EXPECT_NE(r.output.find("not held by phase: settle "), std::string::npos) << r.output;
  EXPECT_NE(r.output.find(failed + " 1"), std::string::npos) << r.output;
}

TEST_F(ValidateCli, CompliantContactsAndTheTimeStepComeFromAYamlPhysicsFile) {
  write_plan(plan_path(), 1);  // one grasp is enough here
  const std::string file = (dir_ / "compliant.yaml").string();
  std::ofstream(file) << "# compliant contacts at 1/2000 s\ncontact_stiffness_Npm: 2e5\n"
                         "contact_damping_Nspm: 400\ntime_step_s: 0.0005\n";
  const auto r = run_cordgrasp("validate --plan " + plan_path() +
                               " --tests lift -q --physics " + file + " --out " +
                               out_path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json sim = read_out();
  EXPECT_EQ(sim["parameters"]["contact_stiffness_Npm"], 2e5);
  EXPECT_EQ(sim["parameters"]["contact_damping_Nspm"], 400.0);
  EXPECT_EQ(sim["parameters"]["time_step_s"], 0.0005);
  EXPECT_EQ(sim["grasps"][0]["outcome"], "held");
  // More steps than the default step takes for the same lift.
  const auto default_run =
      run_cordgrasp("validate --plan " + plan_path() + " --tests lift -q --out " +
                    out_path());
  ASSERT_EQ(default_run.exit_code, 0) << default_run.output;
  const nlohmann::json def = read_out();
  EXPECT_EQ(def["parameters"]["contact_stiffness_Npm"], SimParams{}.contact_stiffness_Npm);
  EXPECT_GT(sim["grasps"][0]["phases"][2]["steps"].get<int>(),
            def["grasps"][0]["phases"][2]["steps"].get<int>());
}

TEST_F(ValidateCli, PhysicsFileFieldsOverrideThePresetAndAreRecordedInSimJson) {
  write_plan(plan_path(), 1);  // one grasp is enough here
  const std::string file = (dir_ / "phases.json").string();
  std::ofstream(file) << R"({"shake_all_axes_at_once": true, "rock_frequency_hz": 2,
      "rock_time_s": 0.5, "shake_time_s": 0.5, "lift_hold_s": 0.2, "rest_exit_time_s": 0.05})";
  const auto r = run_cordgrasp("validate --plan " + plan_path() +
                               " --tests lift,shake -q --protocol thorough --physics " +
                               file + " --out " + out_path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json sim = read_out();
  EXPECT_EQ(sim["parameters"]["protocol"], "thorough");
  EXPECT_EQ(sim["parameters"]["shake_all_axes_at_once"], true);
  EXPECT_EQ(sim["parameters"]["rock_frequency_hz"], 2.0);
  EXPECT_EQ(sim["parameters"]["rock_time_s"], 0.5);
  EXPECT_EQ(sim["parameters"]["shake_time_s"], 0.5);
  EXPECT_EQ(sim["parameters"]["lift_hold_s"], 0.2);
  EXPECT_EQ(sim["parameters"]["rest_exit_time_s"], 0.05);
  EXPECT_EQ(sim["parameters"]["time_step_s"], 1.0 / 960.0);  // thorough's, not overridden
  EXPECT_EQ(sim["grasps"][0]["outcome"], "held");
  // One translation and one rotation segment of 0.5 s each.
  EXPECT_EQ(sim["grasps"][0]["phases"][3]["steps"], 960);
}

TEST_F(ValidateCli, PrintPhysicsPrintsTheEffectiveSettingsAsAFileThatReadsBack) {
  write_plan(plan_path(), 1);  // one grasp is enough here
  const std::string file = (dir_ / "in.json").string();
  std::ofstream(file) << R"({"solver_iterations": 30})";
  const auto r = run_cordgrasp("validate --plan " + plan_path() + " --protocol quick --mu 0.7" +
                               " --physics " + file + " --print-physics");
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("protocol: \"quick\""), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("solver_iterations: 30"), std::string::npos) << r.output;
  const std::string printed = (dir_ / "printed.yaml").string();
  std::ofstream(printed) << r.output;
  // Read back over another preset: every field is the printed one.
  const auto back = run_cordgrasp("validate --plan " + plan_path() + " --tests lift" +
                                  " -q --physics " + printed + " --out " + out_path());
  ASSERT_EQ(back.exit_code, 0) << back.output;
  const nlohmann::json p = read_out()["parameters"];
  EXPECT_EQ(p["protocol"], "quick");
  EXPECT_EQ(p["solver_iterations"], 30);
  EXPECT_EQ(p["contact"]["mu"], 0.7);
  EXPECT_EQ(p["time_step_s"], sim_params_for(Protocol::kQuick).time_step_s);
}

TEST_F(ValidateCli, PhysicsFileFromAnEarlierSimJsonRepeatsItsRunExactly) {
  const std::string first = (dir_ / "first.json").string();
  const std::string phases = (dir_ / "phases.json").string();
  std::ofstream(phases) << R"({"time_step_s": 0.0015, "rock_time_s": 0.4})";
  const auto a = run_cordgrasp("validate --plan " + plan_path() +
                               " --tests lift,shake --trials 2 -q --protocol thorough"
                               " --physics " + phases + " --out " + first);
  ASSERT_EQ(a.exit_code, 0) << a.output;
  // The default protocol differs from thorough: the file, not the preset, decides.
  const auto b = run_cordgrasp("validate --plan " + plan_path() +
                               " --tests lift,shake --trials 2 -q --physics " + first +
                               " --out " + out_path());
  ASSERT_EQ(b.exit_code, 0) << b.output;
  std::ifstream in(first);
  const nlohmann::json sim_a = nlohmann::json::parse(in), sim_b = read_out();
  EXPECT_EQ(sim_b["parameters"], sim_a["parameters"]);
  EXPECT_EQ(sim_b["parameters"]["protocol"], "thorough");
  EXPECT_EQ(sim_b["parameters"]["time_step_s"], 0.0015);
  EXPECT_EQ(without_timings(sim_b["grasps"]), without_timings(sim_a["grasps"]));
  EXPECT_EQ(without_timings(sim_b["summary"]), without_timings(sim_a["summary"]));
}

TEST_F(ValidateCli, PhysicsFileSetsTheFieldsItNamesAndRejectsUnknownOnes) {
  write_plan(plan_path(), 1);  // one grasp is enough here
  const std::string file = (dir_ / "physics.json").string();
  std::ofstream(file) << R"({"squeeze_travel_m": 0.002, "decomposition": {"max_hull_vertices": 32}})";
  const auto r = run_cordgrasp("validate --plan " + plan_path() + " --tests lift -q" +
                               " --physics " + file + " --out " + out_path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json p = read_out()["parameters"];
  EXPECT_EQ(p["squeeze_travel_m"], 0.002);
  EXPECT_EQ(p["decomposition"]["max_hull_vertices"], 32);
  // Every other field keeps the preset's value.
  const SimParams standard = sim_params_for(Protocol::kStandard);
  EXPECT_EQ(p["protocol"], to_string(standard.protocol));
  EXPECT_EQ(p["reach_start_gap_m"], standard.reach_start_gap_m);
  EXPECT_EQ(p["decomposition"]["concavity"], standard.decomposition.concavity);
  std::filesystem::remove(out_path());
  std::ofstream(file) << R"({"squeeze_travl_m": 0.002})";
  expect_error("--physics " + file, "squeeze_travl_m");
  std::ofstream(file) << R"({"squeeze_travel_m": "far"})";
  expect_error("--physics " + file, "squeeze_travel_m");
  std::ofstream(file) << "squeeze_travel_m: 0.002";
  expect_error("--physics " + file, "not JSON");
  std::ofstream(file) << R"({"time_step_s": 10})";  // once a segfault (0 steps)
  expect_error("--physics " + file, "time_step_s: 10 is not in [1e-05, 0.02]");
  std::ofstream(file) << R"({"decomposition": {"max_hull_vertices": 3}})";
  expect_error("--physics " + file, "max_hull_vertices: 3 is not in [4, 100000]");
  std::ofstream(file) << R"({"contact_stiffness_Npm": -1})";
  expect_error("--physics " + file, "contact_stiffness_Npm");
  std::ofstream(file) << R"({"object_shape": "blob"})";
  expect_error("--physics " + file, "object_shape");
  const std::string yaml = (dir_ / "physics.yaml").string();
  std::ofstream(yaml) << "squeeze_travel_m: [0.002";
  expect_error("--physics " + yaml, "YAML syntax error at line 1");
  std::ofstream(yaml) << "effort_scale: .nan";
  expect_error("--physics " + yaml, "effort_scale");
  expect_error("--physics " + (dir_ / "missing.json").string(), "missing.json");
}

TEST_F(ValidateCli, TraceWritesTheObjectInTheHandThroughEveryPhaseAsCsv) {
  write_plan(plan_path(), 1);  // one grasp is enough here
  const std::string trace = (dir_ / "trace.csv").string();
  const std::string every = (dir_ / "every.json").string();
  std::ofstream(every) << R"({"trace_interval_s": 0.5})";
  const auto r = run_cordgrasp("validate --plan " + plan_path() +
                               " --tests lift -q --protocol thorough --trace " + trace +
                               " --physics " + every + " --out " + out_path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  std::ifstream in(trace);
  std::string line;
  ASSERT_TRUE(std::getline(in, line));
  EXPECT_EQ(line, "grasp,phase,phase_end,sim_time_s,object_shift_m,object_turn_rad,contacts");
  int lift_samples = 0;
  std::vector<std::string> ends;
  while (std::getline(in, line)) {
    std::vector<std::string> cells;
    std::stringstream row(line);
    for (std::string cell; std::getline(row, cell, ',');) cells.push_back(cell);
    ASSERT_EQ(cells.size(), 7u) << line;
    EXPECT_EQ(cells[0], "0") << line;  // grasp 0 only
    if (cells[2] == "1") ends.push_back(cells[1]);
    else if (cells[1] == "lift") ++lift_samples;
  }
  EXPECT_EQ(lift_samples, 4);  // 2 s of lift every 0.5 s
  EXPECT_EQ(ends, (std::vector<std::string>{"settle", "close", "lift"}));
}

TEST_F(ValidateCli, TraceIntoAMissingFolderFailsBeforeSimulating) {
  expect_error("--trace " + (dir_ / "no" / "trace.csv").string(),
               "output directory does not exist");
}

TEST_F(ValidateCli, LeverOptionsAreGoneIntoThePhysicsFile) {
  // Experiments are settings files; the command line keeps what a user needs.
  for (const std::string option :
       {"--time-step 0.001", "--squeeze-direction contacts", "--object-fixed close",
        "--hull-vertices 32", "--warmstart", "--trial-offset 0.001", "--density 500",
        "--cache-dir /tmp", "--grasps 1"})
    expect_error(option, option.substr(0, option.find(' ')));
}

TEST_F(ValidateCli, TrialsRepeatEachGraspWithTheHandNudgedAndShowAPointContactPinchIsFragile) {
  // The nudge is 1 mm here: validate_job's perturbation (the command line keeps the default).
  write_plan(plan_path(), 1);
  ValidateJobParams p;
  p.plan = plan_path();
  p.tests = "lift";
  p.trials = 3;
  p.perturbation.offset_m = 0.001;
  p.protocol = Protocol::kThorough;
  p.out = out_path();
  std::string lines;
  ValidateJobCallbacks cb;
  cb.grasp_line = [&lines](const std::string& line) { lines += line + "\n"; };
  const auto run = [&] { return validate_job(p, cb); };
  const SimDocument doc = run();
  EXPECT_NE(lines.find("grasp 0: held in "), std::string::npos) << lines;
  EXPECT_EQ(doc.results.size(), 1u);
  const nlohmann::json sim = read_out();
  const auto& trials = sim["grasps"][0]["trials"];
  ASSERT_EQ(trials["count"], 3);
  ASSERT_EQ(trials["outcomes"].size(), 3u);
  EXPECT_EQ(trials["outcomes"][0], sim["grasps"][0]["outcome"]);  // trial 0: the plan itself
  // Each trial's motion of the object while the hand closed; trial 0's is the close phase's.
  ASSERT_EQ(trials["close_shift_m"].size(), 3u);
  ASSERT_EQ(trials["close_turn_rad"].size(), 3u);
  const auto& close = sim["grasps"][0]["phases"][1];
  ASSERT_EQ(close["name"], "close");
  EXPECT_EQ(trials["close_shift_m"][0], close["translation_m"]);
  EXPECT_EQ(trials["close_turn_rad"][0], close["rotation_rad"]);
  for (const auto& shift : trials["close_shift_m"]) EXPECT_GE(shift.get<double>(), 0.0);
  EXPECT_NE(trials["close_shift_m"][1], trials["close_shift_m"][0]);  // another start
  EXPECT_EQ(sim["parameters"]["trials"], 3);
  EXPECT_EQ(sim["parameters"]["trial_offset_m"], 0.001);
  EXPECT_EQ(sim["summary"]["trials"], 3);
  // This plan pinches with point contacts (no soft-finger radius), which carry no torque about
  // the line through the pads: the pinch as planned holds, but 1 mm off the centre line the
  // box turns out of it (at 1/960 s).
  // The trials show what the single run hides.
  EXPECT_EQ(sim["parameters"]["contact"]["soft_finger_radius_m"], 0.0);
  EXPECT_EQ(trials["outcomes"][0], "held");
  EXPECT_LT(trials["held"].get<int>(), 3) << trials.dump();
  // Same seed, same trials.
  run();
  EXPECT_EQ(read_out()["grasps"][0]["trials"], trials);
}

TEST_F(ValidateCli, UncertaintyGivesEachGraspAHoldProbabilityTheSameForAnyNumberOfThreads) {
  constexpr int kMaxDraws = 6;  ///< few draws: the box pinch costs ~0.05 s each (lift only)
  const std::string one = (dir_ / "one.json").string(), two = (dir_ / "two.json").string();
  const std::string args = "validate --plan " + plan_path() +
                           " --tests lift --uncertainty realistic --trials " +
                           std::to_string(kMaxDraws) + " --seed 5 -q";
  const auto r1 = run_cordgrasp(args + " --jobs 1 --out " + one);
  ASSERT_EQ(r1.exit_code, 0) << r1.output;
  const auto r2 = run_cordgrasp(args + " --jobs 2 --out " + two);
  ASSERT_EQ(r2.exit_code, 0) << r2.output;
  EXPECT_NE(r1.output.find("grasp 1: P(held) "), std::string::npos) << r1.output;
  EXPECT_NE(r1.output.find("P(held) above 0.80: "), std::string::npos) << r1.output;
  const auto read = [](const std::string& path) {
    std::ifstream in(path);
    return nlohmann::json::parse(in);
  };
  const nlohmann::json a = read(one), b = read(two);
  EXPECT_EQ(without_timings(a["grasps"]), without_timings(b["grasps"]));
  const nlohmann::json& h = a["grasps"][0]["hold_probability"];
  ASSERT_TRUE(h.is_object()) << a["grasps"][0].dump();
  const int draws = h["draws"];
  EXPECT_GE(draws, 5);
  EXPECT_LE(draws, kMaxDraws);
  ASSERT_EQ(h["draw_results"].size(), static_cast<size_t>(draws));
  EXPECT_LE(h["low"].get<double>(), h["p"].get<double>());
  EXPECT_GE(h["high"].get<double>(), h["p"].get<double>());
  EXPECT_EQ(h["threshold"], 0.8);
  // The two grasps are the same pinch, with their own draws (by grasp index).
  EXPECT_NE(h["draw_results"][0]["mu_factor"],
            a["grasps"][1]["hold_probability"]["draw_results"][0]["mu_factor"]);
  EXPECT_EQ(a["parameters"]["uncertainty"]["mass_relative_spread"], 0.3);
  EXPECT_EQ(a["parameters"]["hold_probability"]["max_draws"], kMaxDraws);
  // Without --uncertainty: no P(held), and the nudged trials as before.
  const auto plain = run_cordgrasp("validate --plan " + plan_path() + " --tests lift -q --out " +
                                   out_path());
  ASSERT_EQ(plain.exit_code, 0) << plain.output;
  EXPECT_FALSE(read_out()["grasps"][0].contains("hold_probability"));
  EXPECT_TRUE(read_out()["parameters"]["uncertainty"].is_null());
}

TEST_F(ValidateCli, UncertaintyFileWithABadFieldIsRefusedNamingItBeforeSimulating) {
  const std::string file = (dir_ / "uncertainty.yaml").string();
  std::ofstream(file) << "hand_offset_sigma_m: 0.002\nfriction_spread: 0.2\n";
  expect_error("--uncertainty " + file, "'friction_spread'");
  expect_error("--uncertainty " + file, file);
  std::ofstream(file) << "hand_offset_sigma_m: 0.2\n";
  expect_error("--uncertainty " + file, "hand_offset_sigma_m");
  expect_error("--uncertainty realistic --min-hold-probability 1.5", "min-hold-probability");
}

TEST_F(ValidateCli, ZeroTrialsIsAnError) { expect_error("--trials 0", "trials"); }

TEST_F(ValidateCli, SnapshotsWriteOnePngPerGraspAndPhase) {
  const std::filesystem::path shots = dir_ / "shots";
  std::filesystem::create_directories(shots);
  const auto r = run_cordgrasp("validate --plan " + plan_path() + " --tests lift -q --snapshots " +
                               shots.string() + " --out " + out_path());
  ASSERT_EQ(r.exit_code, 0) << r.output;
  for (const std::string k : {"0", "1"})
    for (const std::string phase : {"settle", "close", "lift"})
      EXPECT_EQ(test::png_size((shots / ("grasp_" + k + "_" + phase + ".png")).string()),
                std::make_pair(800u, 600u))
          << k << " " << phase;
  EXPECT_EQ(std::distance(std::filesystem::directory_iterator(shots), {}), 6);
}

/// Where the object is in an animation frame: the centroid [px] and count of its neutral grey
/// pixels (the object is drawn grey, the gripper's links in colours or slate), inside the
/// picture's middle rows (the top rows and the caption band hold text).
struct ObjectInImage {
  Eigen::Vector2d centroid_px = Eigen::Vector2d::Zero();
  int pixels = 0;
};

ObjectInImage object_in_image(const Image& image) {
  constexpr int kGreyTolerance = 10;          ///< max channel spread of the shaded grey object
  constexpr int kDarkest = 70, kLightest = 235;  ///< shaded object, not the white background
  ObjectInImage o;
  for (int y = image.height / 8; y < image.height * 7 / 8; ++y)
    for (int x = 0; x < image.width; ++x) {
      const std::uint8_t* p = image.pixel(x, y);
      const int lo = std::min({p[0], p[1], p[2]}), hi = std::max({p[0], p[1], p[2]});
      if (hi - lo > kGreyTolerance || lo < kDarkest || hi > kLightest) continue;
      o.centroid_px += Eigen::Vector2d(x, y);
      ++o.pixels;
    }
  if (o.pixels > 0) o.centroid_px /= o.pixels;
  return o;
}

TEST_F(ValidateCli, VideoShowsAHeldObjectStayingInTheHandAndADroppedOneLeavingIt) {
  constexpr int kWidth = 320, kHeight = 240;
  constexpr double kFps = 20.0;
  constexpr double kStillPx = 0.03 * kHeight;  ///< a held object's image moves less than this
  /// A dropped one's moves more (or it leaves): the tail after the failure stops once the
  /// object is drop_distance_m (10 cm) off, about 20 px below in this view.
  constexpr double kGonePx = 0.06 * kHeight;
  write_plan(plan_path(), 1);
  const auto animation = [&](const std::string& name, const std::string& args) {
    const std::filesystem::path dir = dir_ / name;
    std::filesystem::create_directories(dir);
    const auto r = run_cordgrasp("validate --plan " + plan_path() + " --tests lift -q " + args +
                                 " --video " + dir.string() + " --video-size " +
                                 std::to_string(kWidth) + "x" + std::to_string(kHeight) +
                                 " --video-fps 20 --out " + out_path());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    EXPECT_EQ(std::distance(std::filesystem::directory_iterator(dir), {}), 1);
    return read_animation((dir / "grasp_0.webp").string());
  };
  const std::vector<AnimationFrame> held = animation("held", "");
  EXPECT_EQ(read_out()["grasps"][0]["outcome"], "held");
  const double lift_s = read_out()["grasps"][0]["phases"].back()["sim_time_s"].get<double>();
  const std::vector<AnimationFrame> dropped = animation("dropped", "--mu 0");
  EXPECT_NE(read_out()["grasps"][0]["outcome"], "held");  // slips out: no friction

  ASSERT_GT(held.size(), 10u);
  EXPECT_EQ(held.front().image.width, kWidth);
  EXPECT_EQ(held.front().image.height, kHeight);
  // Played in simulated time, at about the frame rate, plus the verdict held at the end.
  EXPECT_GT(static_cast<double>(held.size()), 0.8 * kFps * lift_s);
  EXPECT_GT(held.back().timestamp_s, lift_s);
  const ObjectInImage held_first = object_in_image(held.front().image);
  const ObjectInImage held_last = object_in_image(held.back().image);
  ASSERT_GT(held_first.pixels, 200);
  EXPECT_GT(held_last.pixels, held_first.pixels / 2);
  EXPECT_LT((held_last.centroid_px - held_first.centroid_px).norm(), kStillPx);

  ASSERT_GT(dropped.size(), 2u);
  const ObjectInImage dropped_first = object_in_image(dropped.front().image);
  const ObjectInImage dropped_last = object_in_image(dropped.back().image);
  ASSERT_GT(dropped_first.pixels, 200);
  EXPECT_TRUE(dropped_last.pixels < dropped_first.pixels / 2 ||
              (dropped_last.centroid_px - dropped_first.centroid_px).norm() > kGonePx)
      << dropped_first.pixels << " px at " << dropped_first.centroid_px.transpose() << " → "
      << dropped_last.pixels << " px at " << dropped_last.centroid_px.transpose();
}

TEST_F(ValidateCli, VideoAnimatesEveryTrialTheSameForAnyNumberOfThreads) {
  const auto files = [&](int jobs) {
    const std::filesystem::path dir = dir_ / ("jobs" + std::to_string(jobs));
    std::filesystem::create_directories(dir);
    const auto r = run_cordgrasp("validate --plan " + plan_path() + " --tests lift -q --trials 2 " +
                                 "--video-size 160x120 --video " + dir.string() + " -j " +
                                 std::to_string(jobs) + " --out " + out_path());
    EXPECT_EQ(r.exit_code, 0) << r.output;
    std::map<std::string, std::string> bytes;
    for (const auto& e : std::filesystem::directory_iterator(dir))
      bytes[e.path().filename().string()] = test::read_text(e.path().string());
    return bytes;
  };
  const auto one = files(1);
  EXPECT_EQ(one.size(), 4u);  // two grasps, two trials each
  for (const std::string name : {"grasp_0.webp", "grasp_0_trial_1.webp", "grasp_1_trial_1.webp"})
    EXPECT_EQ(one.count(name), 1u) << name;
  EXPECT_EQ(files(2), one);  // byte for byte
}

TEST_F(ValidateCli, VideoIntoAMissingFolderIsAnErrorBeforeSimulating) {
  expect_error("--video " + (dir_ / "nowhere").string(), "--video");
}

TEST_F(ValidateCli, SnapshotsIntoAMissingFolderIsAnErrorBeforeSimulating) {
  expect_error("--snapshots " + (dir_ / "nowhere").string(), "--snapshots");
}

// validate_job's hand and object, for a plan whose files moved: they must be the plan's.
TEST_F(ValidateCli, PlanForAnotherHandOrObjectIsAnErrorAndTheSameObjectIsAccepted) {
  ValidateJobParams p;
  p.plan = plan_path();
  p.tests = "lift";
  p.out = out_path();
  p.hand = "cordgrasp_sah";
  EXPECT_THROW(
      {
        try {
          validate_job(p);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("made for hand 'parallel_gripper'"),
                    std::string::npos)
              << e.what();
          throw;
        }
      },
      InputError);
  p.hand = "parallel_gripper";
  p.object = source_dir() + "/assets/objects/mug.obj";
  EXPECT_THROW(
      {
        try {
          validate_job(p);
        } catch (const InputError& e) {
          EXPECT_NE(std::string(e.what()).find("was planned for object"), std::string::npos)
              << e.what();
          throw;
        }
      },
      InputError);
  EXPECT_FALSE(std::filesystem::exists(out_path()));
  p.object = box_path();
  EXPECT_EQ(validate_job(p).results.size(), 2u);
  EXPECT_EQ(read_out()["summary"]["grasps"], 2);
}

TEST_F(ValidateCli, UnknownTestOrMissingPlanIsAnError) {
  auto r = run_cordgrasp("validate --plan " + plan_path() + " --tests lift,wobble --out " +
                         out_path());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("wobble"), std::string::npos) << r.output;
  r = run_cordgrasp("validate --plan " + (dir_ / "missing.json").string() + " --out " +
                    out_path());
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("missing.json"), std::string::npos) << r.output;
}

TEST(FailuresLine, CountsEachGraspThatDidNotHoldUnderItsFirstFailedPhase) {
  auto result = [](std::vector<std::pair<std::string, Outcome>> phases, bool overlap) {
    SimResult r;
    r.outcome = Outcome::kHeld;
    for (const auto& [name, outcome] : phases) {
      PhaseResult p;
      p.name = name;
      p.outcome = outcome;
      r.phases.push_back(p);
      if (outcome != Outcome::kHeld && outcome != Outcome::kNotRun && r.held()) r.outcome = outcome;
    }
    r.preshape_overlap = overlap;
    return r;
  };
  const std::vector<SimResult> results = {
      result({{"settle", Outcome::kHeld}, {"close", Outcome::kDropped}, {"lift", Outcome::kNotRun}},
             true),
      result({{"settle", Outcome::kHeld}, {"close", Outcome::kHeld}, {"lift", Outcome::kSlipped},
              {"shake", Outcome::kNotRun}},
             false),
      result({{"settle", Outcome::kHeld}, {"close", Outcome::kHeld}, {"lift", Outcome::kHeld}},
             false),
      result({{"settle", Outcome::kHeld}, {"close", Outcome::kDropped}}, false)};
  // The grasp lost in the lift ended its close with no finger pressing (ratio 0): counted.
  EXPECT_EQ(failures_line(results),
            "not held by phase: settle 0, close 2, lift 1, shake 0, gravity6 0; preshape "
            "overlaps 1; no finger pressing after the close 1");
  std::vector<SimResult> pressed = results;
  pressed[1].phases[1].squeeze_effort_ratio = 1.0;  // its fingers pressed at their caps
  EXPECT_EQ(failures_line(pressed),
            "not held by phase: settle 0, close 2, lift 1, shake 0, gravity6 0; preshape "
            "overlaps 1");
  EXPECT_FALSE(pressed[1].lost_without_pressing());
  EXPECT_TRUE(results[1].lost_without_pressing());
  EXPECT_FALSE(results[0].lost_without_pressing());  // lost in the close: not counted
}

TEST(SimResultLine, SaysHowFarSettlePushedTheObjectWhenThePreshapeHandOverlapsIt) {
  SimResult r;
  r.outcome = Outcome::kDropped;
  PhaseResult settle;
  settle.name = "settle";
  settle.outcome = Outcome::kHeld;
  settle.translation_m = 0.0123;
  r.phases = {settle};
  r.preshape_overlap = true;
  EXPECT_NE(sim_result_line(r).find("overlaps the object's collision shape (settle moved "
                                         "it 12.3 mm)"),
            std::string::npos)
      << sim_result_line(r);
  r.preshape_overlap = false;
  EXPECT_EQ(sim_result_line(r).find("overlaps"), std::string::npos);
}

}  // namespace
}  // namespace cordgrasp
