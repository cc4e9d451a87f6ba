// report.md of `cordgrasp run`: the physics cell of the grasp table.
#include "cordgrasp/jobs/run_report.h"

#include <gtest/gtest.h>

#include <string>

namespace cordgrasp {
namespace {

/// A one-grasp run whose grasp dropped while closing.
struct DroppedInClose {
  PlanDocument plan;
  SimDocument sim;
  RunReport report;

  explicit DroppedInClose(bool preshape_overlap) {
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
    report.sim = &sim;
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

}  // namespace
}  // namespace cordgrasp
