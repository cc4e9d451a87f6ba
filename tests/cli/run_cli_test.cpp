// `cordgrasp run`: the main job on the shipped defaults writes every file; no grasp is a
// clear failure that still leaves the plan and the report; bad arguments fail before work.
#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "cordgrasp/jobs/run_job.h"
#include "cordgrasp/render/animation.h"
#include "test_files.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;
using test::png_size;
using test::quoted;
using test::read_json;
using test::read_text;
using test::run_cordgrasp;
using test::TempDir;

constexpr int kGrasps = 2;
constexpr unsigned kWidth_px = 800, kHeight_px = 600;  ///< run's picture size


TEST(CliRun, DefaultsWritePlanSimReportAndPictures) {
  TempDir dir;
  // --no-validate keeps the CPU small; CliRun.ValidatesByDefault covers validated planning.
  const auto r = run_cordgrasp("run --grasps " + std::to_string(kGrasps) +
                               " --no-validate --quiet --out-dir " +
                               quoted(dir.path.string()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json plan = read_json(dir.file("plan.json"));
  const nlohmann::json sim = read_json(dir.file("sim.json"));
  EXPECT_EQ(plan.at("inputs").at("hand").at("name"), "cordgrasp_sah");
  EXPECT_EQ(plan.at("inputs").at("object").at("name"), "mug");
  const size_t n = plan.at("grasps").size();
  ASSERT_GE(n, 1u);
  EXPECT_LE(n, static_cast<size_t>(kGrasps));
  EXPECT_EQ(sim.at("grasps").size(), n);
  EXPECT_EQ(sim.at("parameters").at("tests"), "lift,shake");
  const std::string report = read_text(dir.file("report.md"));
  for (size_t k = 0; k < n; ++k) {
    const std::string planned = "grasp_" + std::to_string(k) + ".png";
    const std::string physics = "grasp_" + std::to_string(k) + "_physics.png";
    EXPECT_EQ(png_size(dir.file(planned)), std::make_pair(kWidth_px, kHeight_px)) << planned;
    EXPECT_GT(png_size(dir.file(physics)).first, 0u) << physics;
    const std::string animation = "grasp_" + std::to_string(k) + ".webp";
    EXPECT_GT(read_animation(dir.file(animation)).size(), 10u) << animation;
    EXPECT_NE(report.find("(" + planned + ")"), std::string::npos) << report;
    EXPECT_NE(report.find(sim.at("grasps").at(k).at("outcome").get<std::string>()),
              std::string::npos);
  }
  EXPECT_NE(report.find("| 0 |"), std::string::npos) << report;
  // Each grasp's P(held) under the realistic model, a preview of a few draws.
  EXPECT_EQ(sim.at("parameters").at("uncertainty").at("mu_relative_spread"), 0.2);
  for (size_t k = 0; k < n; ++k) {
    const nlohmann::json& h = sim.at("grasps").at(k).at("hold_probability");
    EXPECT_GE(h.at("draws").get<int>(), 1) << k;
    EXPECT_LE(h.at("draws").get<int>(), RunParams{}.hold_preview_draws) << k;
    EXPECT_LE(h.at("low").get<double>(), h.at("p").get<double>()) << k;
  }
  EXPECT_NE(report.find("P(held) [95 %]"), std::string::npos) << report;
  // report.html beside it, with each grasp's picture and 3D model (tests/browser opens one).
  const std::string html = read_text(dir.file("report.html"));
  for (size_t k = 0; k < n; ++k) {
    const std::string grasp = "grasp_" + std::to_string(k);
    EXPECT_NE(html.find("src=\"" + grasp + ".png\""), std::string::npos) << grasp;
    EXPECT_NE(html.find("src=\"" + grasp + ".glb.js\""), std::string::npos) << grasp;
    EXPECT_TRUE(fs::exists(dir.path / (grasp + ".glb"))) << grasp;
  }
  EXPECT_TRUE(fs::exists(dir.path / "viewer" / "three.min.js"));
  // Nothing half-written is left behind: no temporary files.
  for (const auto& e : fs::recursive_directory_iterator(dir.path)) {
    const std::string ext = e.path().extension().string();
    EXPECT_TRUE(e.is_directory() || ext == ".json" || ext == ".png" || ext == ".md" ||
                ext == ".webp" || ext == ".html" || ext == ".glb" || ext == ".js" ||
                e.path().filename() == "copyright")
        << e.path();
    EXPECT_NE(e.path().filename().string()[0], '.') << e.path();
  }
  EXPECT_TRUE(r.output.empty() || r.output.find("run [") == std::string::npos) << r.output;

  // validate on the written plan reproduces run's physics exactly.
  const auto v = run_cordgrasp("validate --plan " + quoted(dir.file("plan.json")) +
                               " --tests lift,shake -q --out " + quoted(dir.file("again.json")));
  ASSERT_EQ(v.exit_code, 0) << v.output;
  const nlohmann::json again = read_json(dir.file("again.json"));
  for (size_t k = 0; k < n; ++k) {
    EXPECT_EQ(again["grasps"][k]["outcome"], sim["grasps"][k]["outcome"]) << k;
    EXPECT_EQ(again["grasps"][k]["phases"].back()["translation_m"],
              sim["grasps"][k]["phases"].back()["translation_m"])
        << k;
  }
}

TEST(CliRun, HoldProbabilityPreviewIsTheSameBesideThePicturesAsAfterThem) {
  // With two threads the draws run beside the pictures, with one after them.
  TempDir dir;
  std::vector<nlohmann::json> previews;
  for (const char* jobs : {"1", "2"}) {
    const std::string out = dir.file(std::string("jobs") + jobs);
    const auto r = run_cordgrasp(
        "run --hand parallel_gripper --object box --grasps 2 "
        "--no-validate --quiet --jobs " +
        std::string(jobs) + " --out-dir " + quoted(out));
    ASSERT_EQ(r.exit_code, 0) << r.output;
    nlohmann::json grasps = read_json(out + "/sim.json").at("grasps");
    ASSERT_EQ(grasps.size(), 2u) << jobs;
    nlohmann::json hs;
    for (const auto& g : grasps) {
      nlohmann::json h = g.at("hold_probability");
      for (auto& d : h.at("draw_results")) d.erase("cpu_s"), d.erase("wall_time_s");
      h.erase("cpu_s");
      h.erase("wall_time_s");
      hs.push_back(h);
    }
    previews.push_back(hs);
    EXPECT_TRUE(fs::exists(fs::path(out) / "grasps.png")) << jobs;
  }
  EXPECT_EQ(previews[0], previews[1]);
}

TEST(CliRun, ValidatesByDefault) {
  TempDir dir;
  const auto r = run_cordgrasp("run --hand parallel_gripper --object box --grasps 2 --no-render "
                               "--quiet --out-dir " + quoted(dir.path.string()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("accepted 2 / 2"), std::string::npos) << r.output;
  const nlohmann::json plan = read_json(dir.file("plan.json"));
  ASSERT_EQ(plan.at("grasps").size(), 2u);
  EXPECT_EQ(plan.at("validation").at("stats").at("accepted"), 2);
  for (const auto& g : plan.at("grasps"))
    EXPECT_GE(g.at("validation").at("held_trials").get<int>(), 2) << g.dump();
  EXPECT_NE(read_text(dir.file("report.md")).find("held trials"), std::string::npos);
}

TEST(CliRun, UncertaintyAcceptsByHoldProbabilityAndReportsItWithItsInterval) {
  TempDir dir;
  // At most 6 draws (the settings file), decided above 0.5 by 6 of 6 (Wilson low 0.61).
  const std::string settings = dir.write("draws.yaml", "validation:\n  max_draws: 6\n");
  const auto r = run_cordgrasp(
      "run --hand parallel_gripper --object box --grasps 1 --no-render --quiet --uncertainty "
      "realistic --min-hold-probability 0.5 --settings " + quoted(settings) + " --out-dir " +
      quoted(dir.path.string()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json plan = read_json(dir.file("plan.json"));
  const nlohmann::json& v = plan.at("validation").at("parameters");
  EXPECT_EQ(v.at("uncertainty").at("mu_relative_spread"), 0.2);
  EXPECT_EQ(v.at("min_hold_probability"), 0.5);
  EXPECT_EQ(v.at("max_draws"), 6);
  ASSERT_EQ(plan.at("grasps").size(), 1u);
  EXPECT_LE(plan.at("grasps")[0].at("validation").at("trials").get<int>(), 6);
  // sim.json estimates P(held) again with the grasp's own draws; the report shows it.
  const nlohmann::json sim = read_json(dir.file("sim.json"));
  const nlohmann::json& h = sim.at("grasps")[0].at("hold_probability");
  EXPECT_LE(h.at("draws").get<int>(), 6);
  EXPECT_EQ(h.at("threshold"), 0.5);
  const std::string report = read_text(dir.file("report.md"));
  EXPECT_NE(report.find("P(held) [95 %]"), std::string::npos) << report;
  EXPECT_NE(report.find("P(held) under uncertainty lies above 0.50"), std::string::npos)
      << report;
  // validate --plan re-checks under the plan's model, threshold and draws unless told
  // otherwise (here with other draws: --seed 2).
  const std::string again = dir.file("again.json");
  auto v2 = run_cordgrasp("validate --plan " + quoted(dir.file("plan.json")) +
                          " --tests lift --seed 2 -q --out " + quoted(again));
  ASSERT_EQ(v2.exit_code, 0) << v2.output;
  const nlohmann::json re = read_json(again);
  EXPECT_EQ(re.at("parameters").at("uncertainty").at("mu_relative_spread"), 0.2);
  const nlohmann::json& h2 = re.at("grasps")[0].at("hold_probability");
  EXPECT_EQ(h2.at("threshold"), 0.5);
  EXPECT_LE(h2.at("draws").get<int>(), 6);
  v2 = run_cordgrasp("validate --plan " + quoted(dir.file("plan.json")) +
                     " --tests lift --uncertainty none -q --out " + quoted(again));
  ASSERT_EQ(v2.exit_code, 0) << v2.output;
  EXPECT_TRUE(read_json(again).at("parameters").at("uncertainty").is_null());
}

TEST(CliRun, ProgressGoesToStderrUnlessQuiet) {
  TempDir dir;
  const auto r = run_cordgrasp("run --grasps 1 --tests none --no-render --out-dir " +
                               quoted(dir.path.string()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  EXPECT_NE(r.output.find("run [0."), std::string::npos) << r.output;
  EXPECT_NE(r.output.find("report"), std::string::npos) << r.output;
  EXPECT_FALSE(fs::exists(dir.file("sim.json")));
  EXPECT_FALSE(fs::exists(dir.file("grasp_0.png")));
  EXPECT_NE(read_text(dir.file("report.md")).find("Physics: skipped"), std::string::npos);
}

// Without friction, force closure in 3D takes at least 7 contacts: the parallel gripper (palm and
// two jaws, one contact each) at mu 0 with point contacts cannot find a grasp, so run must fail
// — yet keep plan and report. (Point contacts alone were not enough: a palm-and-jaws grasp of
// three point contacts with friction can be force closure, and one build found two.)
TEST(CliRun, NoGraspExitsNonZeroWithAClearMessageAndStillWritesTheReport) {
  TempDir dir;
  const std::string settings = dir.write(
      "point_contacts.yaml", "quality: {contact: {soft_finger_radius_m: 0}}\ntime_limit_s: 1\n");
  const auto r = run_cordgrasp("run --hand parallel_gripper --settings " + quoted(settings) +
                               " --mu 0 --object box --quiet --out-dir " +
                               quoted((dir.path / "out").string()));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("no force-closure grasp of box with parallel_gripper"),
            std::string::npos)
      << r.output;
  EXPECT_EQ(read_json(dir.file("out/plan.json")).at("grasps").size(), 0u);
  EXPECT_NE(read_text(dir.file("out/report.md")).find("No force-closure grasp"),
            std::string::npos);
  EXPECT_FALSE(fs::exists(dir.file("out/sim.json")));
}

// The gripper's description carries a 5 mm pad patch, used by planner and physics alike.
TEST(CliRun, GripperUsesItsHandsSoftFingerRadiusInPlanAndPhysics) {
  TempDir dir;
  const std::string settings =
      dir.write("generic.yaml", "planner: generic\ntime_limit_s: 5\n");
  const auto r = run_cordgrasp(
      "run --hand parallel_gripper --object box --settings " + quoted(settings) +
      " --grasps 1 --no-render --tests lift --quiet --out-dir " +
      quoted((dir.path / "out").string()));
  ASSERT_EQ(r.exit_code, 0) << r.output;
  const nlohmann::json plan = read_json(dir.file("out/plan.json"));
  const nlohmann::json sim = read_json(dir.file("out/sim.json"));
  EXPECT_EQ(plan["parameters"]["planner"], "generic");
  EXPECT_EQ(plan["parameters"]["quality"]["contact"]["soft_finger_radius_m"], 0.005);
  EXPECT_EQ(sim["parameters"]["contact"]["soft_finger_radius_m"], 0.005);
  EXPECT_EQ(plan["grasps"].size(), 1u);
}

TEST(CliRun, UnknownObjectNameIsOneLineErrorListingTheShippedOnes) {
  TempDir dir;
  const auto r = run_cordgrasp("run --object teapot --out-dir " + quoted(dir.path.string()));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("--object 'teapot': no such file, nor a shipped object (box,"),
            std::string::npos)
      << r.output;
  EXPECT_TRUE(fs::is_empty(dir.path));
  // A bad input creates no output folder either.
  const fs::path out = dir.path / "not-created";
  const auto bad_hand =
      run_cordgrasp("run --hand no_such_hand --out-dir " + quoted(out.string()));
  EXPECT_NE(bad_hand.exit_code, 0);
  EXPECT_FALSE(fs::exists(out)) << bad_hand.output;
}

TEST(CliRun, MillimetreFileReadAsMetersIsWarnedAboutAndAutoReadsItAsMillimetres) {
  TempDir dir;
  const std::string box = quoted(test::test_data("meshes/box_100mm.obj"));
  const std::string rest = " --tests none --no-render --quiet --out-dir " +
                           quoted((dir.path / "out").string());
  const std::string quick = quoted(dir.write("quick.yaml", "time_limit_s: 1\n"));
  const std::string as_mm = quoted(dir.write("auto.yaml", "time_limit_s: 1\nunits: auto\n"));
  const auto as_m = run_cordgrasp("run --object " + box + " --settings " + quick + rest);
  EXPECT_NE(as_m.output.find("m across: if the file is in millimetres, give --units mm"),
            std::string::npos)
      << as_m.output;
  const auto as_auto = run_cordgrasp("run --settings " + as_mm + " --object " + box + rest);
  EXPECT_NE(as_auto.output.find("--units auto read the file as millimetres"), std::string::npos)
      << as_auto.output;
  EXPECT_EQ(as_auto.output.find("m across"), std::string::npos) << as_auto.output;
}

TEST(CliRun, BadTestNameFailsBeforePlanning) {
  TempDir dir;
  const auto r =
      run_cordgrasp("run --tests lift,wobble --out-dir " + quoted(dir.path.string()));
  EXPECT_NE(r.exit_code, 0);
  EXPECT_NE(r.output.find("wobble"), std::string::npos) << r.output;
  EXPECT_TRUE(fs::is_empty(dir.path));
}

}  // namespace
}  // namespace cordgrasp
