// The exported bounded close (docs/export.md) and cordgrasp-mujoco-check running protocol
// standard on it: the start lies gap-short of the plan, the squeeze one travel past it at each
// joint's lever; MuJoCo holds planned grasps of a shipped hand and loses them without friction.
#include <gtest/gtest.h>
#include <mujoco/mujoco.h>
#include <unistd.h>

#include <algorithm>
#include <array>
#include <cstdio>
#include <filesystem>
#include <fstream>
#include <memory>
#include <sstream>
#include <string>
#include <utility>

#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/jobs/export_mjcf.h"
#include "cordgrasp/jobs/plan_json.h"
#include "cordgrasp/sim/sim_params.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;

constexpr double kTravelTol_m = 1e-9;  // lever × squeeze travel against squeeze_travel_m
/// The start gap doubles at most three times while a finger is too close (physics.md §3a).
constexpr double kMaxGapDoublings = 8.0;

/// One plan of the shipped hand and object, exported as MJCF, shared by the tests below.
class StandardCheck : public ::testing::Test {
 protected:
  static void SetUpTestSuite() {
    dir_ = new fs::path(fs::temp_directory_path() /
                        ("cordgrasp_standard_check_" + std::to_string(::getpid())));
    fs::create_directories(*dir_);
    const std::string plan = (*dir_ / "plan.json").string();
    const test::CommandResult planned = test::run_cordgrasp(
        "plan --hand cordgrasp_sah --object mug -n 3 --out " + plan);
    ASSERT_EQ(planned.exit_code, 0) << planned.output;
    const test::CommandResult exported = test::run_cordgrasp(
        "export --plan " + plan + " --format mjcf --out " + (*dir_ / "scene.xml").string());
    ASSERT_EQ(exported.exit_code, 0) << exported.output;
  }
  static void TearDownTestSuite() {
    std::error_code ec;
    fs::remove_all(*dir_, ec);
    delete dir_;
  }
  static fs::path* dir_;
};
fs::path* StandardCheck::dir_ = nullptr;

/// Runs cordgrasp-mujoco-check with `args` (its CSV to `csv`); returns the exit status and
/// the output.
std::pair<int, std::string> run_mujoco_check(const std::string& scene, const std::string& csv,
                                             const std::string& args) {
  const std::string cmd = std::string("\"") + CORDGRASP_MUJOCO_CHECK_EXE + "\" --scene " +
                          scene + " --out " + csv + " " + args + " 2>&1";
  FILE* pipe = popen(cmd.c_str(), "r");
  EXPECT_TRUE(pipe);
  std::array<char, 4096> buf{};
  std::string output;
  for (size_t n; (n = fread(buf.data(), 1, buf.size(), pipe)) > 0;) output.append(buf.data(), n);
  return {pclose(pipe), output};
}

/// Runs cordgrasp-mujoco-check with `args`; returns its CSV rows' `held` column.
using ModelPtr = std::unique_ptr<mjModel, void (*)(mjModel*)>;

/// The scene as MuJoCo loads it; null (with MuJoCo's message added as a test failure) when it
/// does not load.
ModelPtr load_model(const fs::path& scene) {
  char error[1000] = "";
  ModelPtr m(mj_loadXML(scene.c_str(), nullptr, error, sizeof(error)), mj_deleteModel);
  EXPECT_TRUE(m) << scene << ": " << error;
  return m;
}

std::vector<bool> mujoco_check_held(const std::string& scene, const std::string& args) {
  const std::string csv = scene + ".csv";
  const auto [status, output] = run_mujoco_check(scene, csv, args);
  EXPECT_EQ(status, 0) << output;
  std::ifstream in(csv);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("grasp,held,", 0), 0u) << line;
  std::vector<bool> held;
  while (std::getline(in, line)) held.push_back(line.substr(line.find(',') + 1, 1) == "1");
  return held;
}

TEST_F(StandardCheck, StartLiesGapShortOfThePlanAndTheSqueezeOneTravelPast) {
  const fs::path xml = *dir_ / "scene.xml";
  const ModelPtr m = load_model(xml);
  ASSERT_TRUE(m);
  std::unique_ptr<mjData, void (*)(mjData*)> d(mj_makeData(m.get()), mj_deleteData);
  const nlohmann::json json = read_plan_json((*dir_ / "plan.json").string());
  const HandModel hand = load_hand(plan_hand_path(json));
  const PlanDocument plan = plan_from_json(json, hand, (*dir_ / "plan.json").string());
  ASSERT_EQ(m->nkey, static_cast<int>(plan.grasps.size()));
  const SimParams standard = sim_params_for(Protocol::kStandard);
  const int object = mj_name2id(m.get(), mjOBJ_BODY, MjcfNames::kObjectBody);
  int pushing = 0;
  for (int k = 0; k < m->nkey; ++k) {
    const Grasp& g = plan.grasps[k];
    const Eigen::VectorXd lever = contact_levers(hand, g.q, g.X_OB, g.contacts);
    const auto numeric = [&](const char* what) {
      const int id = mj_name2id(m.get(), mjOBJ_NUMERIC, MjcfNames::close_numeric(k, what).c_str());
      EXPECT_GE(id, 0) << what;
      return m->numeric_data + m->numeric_adr[id];
    };
    const mjtNum* start = numeric(MjcfNames::kStart);
    const mjtNum* squeeze = numeric(MjcfNames::kSqueeze);
    // Hand joints are qpos 7 .. 7 + n − 1 (after the hand's free joint).
    mj_resetDataKeyframe(m.get(), d.get(), k);
    for (int a = 0; a < m->nu; ++a) {
      const int j = m->actuator_trnid[2 * a];
      const int hj = find_joint(hand, mj_id2name(m.get(), mjOBJ_JOINT, j));
      const double plan_q = m->key_ctrl[k * m->nu + a];
      const double start_q = start[m->jnt_qposadr[j] - 7];
      const double push = squeeze[a] - plan_q;
      if (push == 0.0) {
        EXPECT_NEAR(start_q, plan_q, 1e-9) << "grasp " << k << ": a holding joint starts at the plan";
        continue;
      }
      ++pushing;
      // Toward the preshape, by gap / lever (doubled at most three times) ...
      EXPECT_LT(push * (start_q - plan_q), 0.0) << "grasp " << k << " actuator " << a;
      EXPECT_LE(std::abs(start_q - plan_q) * lever[hj],
                kMaxGapDoublings * standard.reach_start_gap_m + kTravelTol_m);
      // ... and the squeeze target squeeze_travel_m past the planned contacts at its lever.
      EXPECT_NEAR(std::abs(push) * lever[hj], standard.squeeze_travel_m, kTravelTol_m);
    }
    // At the start no finger touches the object.
    for (int i = 0; i < m->nq - 14; ++i) d->qpos[7 + i] = start[i];
    mj_forward(m.get(), d.get());
    for (int c = 0; c < d->ncon; ++c) {
      const bool hand_object = (m->geom_bodyid[d->contact[c].geom1] == object) !=
                               (m->geom_bodyid[d->contact[c].geom2] == object);
      EXPECT_FALSE(hand_object) << "grasp " << k << ": a finger touches the object at the start";
    }
  }
  EXPECT_GT(pushing, 0);
}

TEST_F(StandardCheck, MujocoHoldsPlannedGraspsAndLosesThemWithoutFriction) {
  const std::string scene = (*dir_ / "scene.xml").string();
  const std::vector<bool> held = mujoco_check_held(scene, "");
  ASSERT_FALSE(held.empty());
  EXPECT_GE(std::count(held.begin(), held.end(), true), 1);
  const std::vector<bool> slippery = mujoco_check_held(scene, "--mu 0.01");
  ASSERT_EQ(slippery.size(), held.size());
  EXPECT_EQ(std::count(slippery.begin(), slippery.end(), true), 0);
}

/// A copy of the scene with `name`'s numeric element replaced by `element` ("" removes it).
std::string scene_with(const fs::path& scene, const std::string& name, const std::string& element,
                       const std::string& copy_name) {
  std::ifstream in(scene);
  std::stringstream text;
  text << in.rdbuf();
  std::string xml = text.str();
  const size_t at = xml.find("<numeric name=\"" + name + "\"");
  EXPECT_NE(at, std::string::npos) << name;
  if (at != std::string::npos) xml.replace(at, xml.find("/>", at) + 2 - at, element);
  // The copy lies beside the scene: its meshes folder is found by the same relative path.
  const fs::path copy = scene.parent_path() / copy_name;
  std::ofstream(copy) << xml;
  return copy.string();
}

TEST_F(StandardCheck, RunsThePhysicsSettingsTheSceneCarries) {
  const fs::path scene = *dir_ / "scene.xml";
  // The scene carries the protocol export ran the closes with (standard's phases).
  const ModelPtr m = load_model(scene);
  ASSERT_TRUE(m);
  const SimParams standard = sim_params_for(Protocol::kStandard);
  const auto scene_value = [&](const std::string& field) {
    const int id = mj_name2id(m.get(), mjOBJ_NUMERIC, MjcfNames::sim_numeric(field).c_str());
    EXPECT_GE(id, 0) << field;
    return id < 0 ? -1.0 : m->numeric_data[m->numeric_adr[id]];
  };
  constexpr double kWrittenRelTol = 1e-9;  // ten significant digits in the scene
  EXPECT_NEAR(scene_value("shake_time_s"), standard.shake_time_s,
              kWrittenRelTol * standard.shake_time_s);
  EXPECT_NEAR(scene_value("rock_angle_rad"), standard.rock_angle_rad,
              kWrittenRelTol * standard.rock_angle_rad);
  EXPECT_NEAR(scene_value("held_translation_m"), standard.held_translation_m,
              kWrittenRelTol * standard.held_translation_m);
  // The check follows them: with a held limit of a micrometre nothing is held.
  const std::vector<bool> held = mujoco_check_held(scene.string(), "");
  ASSERT_FALSE(held.empty());
  ASSERT_GE(std::count(held.begin(), held.end(), true), 1);
  const std::string strict =
      scene_with(scene, MjcfNames::sim_numeric("held_translation_m"),
                 "<numeric name=\"" + MjcfNames::sim_numeric("held_translation_m") +
                     "\" size=\"1\" data=\"1e-6\"/>",
                 "strict.xml");
  const std::vector<bool> strict_held = mujoco_check_held(strict, "");
  ASSERT_EQ(strict_held.size(), held.size());
  EXPECT_EQ(std::count(strict_held.begin(), strict_held.end(), true), 0);
  // A scene without them (an older export) is refused, naming the one missing.
  const std::string older =
      scene_with(scene, MjcfNames::sim_numeric("lift_time_s"), "", "older.xml");
  const auto [status, output] = run_mujoco_check(older, older + ".csv", "");
  EXPECT_NE(status, 0);
  EXPECT_NE(output.find("sim_lift_time_s"), std::string::npos) << output;
}

}  // namespace
}  // namespace cordgrasp
