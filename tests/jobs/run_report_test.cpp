// report.md of `cordgrasp run`: the physics cells of the grasp table.
#include "cordgrasp/jobs/run_report.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace cordgrasp {
namespace {

/// A one-grasp run whose grasp dropped while closing.
struct DroppedInClose {
  PlanDocument plan;
  RunReport report;

  explicit DroppedInClose(bool preshape_overlap) {
    SimDocument sim;
    plan.grasps.resize(1);
    SimResult r;
    r.outcome = Outcome::kDropped;
    PhaseResult settle;
    settle.name = "settle";
    settle.outcome = Outcome::kHeld;
    PhaseResult close;
    close.name = "close";
    close.outcome = Outcome::kDropped;
    r.phases = {settle, close};
    r.preshape_overlap = preshape_overlap;
    sim.results = {r};
    sim.grasp_indices = {0};
    report.plan = plan;
    report.sim = sim;
  }
};

TEST(RunReport, PhysicsCellSaysWhenThePreshapeHandOverlapsTheCollisionShape) {
  const DroppedInClose overlapping(true);
  const std::string md = run_report_markdown(overlapping.report);
  EXPECT_NE(md.find("| dropped in close; the preshape hand overlaps the collision shape |"),
            std::string::npos)
      << md;
  const DroppedInClose clear(false);
  const std::string plain = run_report_markdown(clear.report);
  EXPECT_NE(plain.find("| dropped in close |"), std::string::npos) << plain;
  EXPECT_EQ(plain.find("overlaps"), std::string::npos) << plain;
}

TEST(RunReport, GraspRowGivesTheMotionWhileClosingAndTheFarthestPlannedContact) {
  DroppedInClose run(false);
  PhaseResult& close = run.report.sim->results[0].phases[1];
  close.outcome = Outcome::kHeld;
  close.translation_m = 0.0021;
  close.rotation_rad = 0.05;  // 2.9°
  run.report.sim->results[0].outcome = Outcome::kHeld;
  run.report.sim->results[0].planned_contact_offsets_m = {0.0004, 0.0013};
  const std::string md = run_report_markdown(run.report);
  EXPECT_NE(md.find("closing: shift [mm], turn [°]"), std::string::npos) << md;
  EXPECT_NE(md.find("| 2.1, 2.9 | 1.3 |"), std::string::npos) << md;
  // A planned contact the object does not touch: no distance.
  run.report.sim->results[0].planned_contact_offsets_m = {0.0004, std::nan("")};
  EXPECT_NE(run_report_markdown(run.report).find("| 2.1, 2.9 | – |"), std::string::npos);
}

TEST(RunReport, GraspRowGivesPHeldWithItsIntervalAndWhatFailuresGoWith) {
  DroppedInClose run(false);
  EXPECT_EQ(run_report_markdown(run.report).find("P(held)"), std::string::npos);
  HoldProbability h;
  h.held = 16;
  h.draws.resize(20);
  h.interval = wilson_interval(16, 20);  // 0.80 [0.58, 0.92]
  h.sensitivity.most_associated = UncertaintyFactor::kHandTurn;
  run.report.sim->hold_probabilities = {h};
  const std::string md = run_report_markdown(run.report);
  EXPECT_NE(md.find("| P(held) [95 %] | draws | failures go with |"), std::string::npos) << md;
  EXPECT_NE(md.find("| 0.80 [0.58, 0.92] | 20 | hand_turn |"), std::string::npos) << md;
}

}  // namespace
}  // namespace cordgrasp
