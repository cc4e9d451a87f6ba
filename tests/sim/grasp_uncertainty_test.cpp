// Uncertain trials (grasp_uncertainty.h) and P(held) (hold_probability.h): the draws depend on
// (seed, grasp, trial) alone and follow their distributions; applying one moves the hand
// rigidly and changes μ, mass, centre of mass and grip force; the sequential test stops where
// the Wilson interval is decided; a rim pinch of the parallel gripper is less likely to hold a
// box than a pinch at its middle.
#include "cordgrasp/sim/grasp_uncertainty.h"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/finger_stage.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/shapes.h"
#include "cordgrasp/sim/hold_probability.h"
#include "cordgrasp/sim/validate_grasp.h"
#include "sim_test_util.h"

namespace cordgrasp {
namespace {

constexpr double kBoxSide_m = 0.05;       ///< make_box_mesh: a cube centred on the origin
constexpr double kOpenGripper_m = 0.05;   ///< preshape: pads 5 cm from the centre plane
constexpr double kPadPatchRadius_m = 0.005;  ///< the gripper's soft-finger pads
/// GCP to fingertips along the approach (assets/hands/parallel_gripper.yaml) [m].
constexpr double kGcpToTips_m = 0.02;
/// The rim pinch: the pad tips reach this far down the box's side faces [m].
constexpr double kRimOverlap_m = 0.002;
constexpr double kPoseTol_m = 1e-12;
constexpr int kSamples = 4000;            ///< draws of the distribution checks
/// Sample σ and means of kSamples draws are within this of their value (≈ 4 standard errors).
constexpr double kSampleRelTol = 0.06;
/// Draws per grasp in the physics comparison (≤ 10, lift only: a few seconds).
constexpr int kComparisonDraws = 10;
/// The rim pinch's P(held) is at least this much below the centre pinch's.
constexpr double kMinHoldGap = 0.3;

const HandModel& gripper() {
  static const HandModel hand = load_hand("parallel_gripper");
  return hand;
}

const Mesh& box() {
  static const Mesh mesh = make_box_mesh(Eigen::Vector3d::Constant(kBoxSide_m));
  return mesh;
}

Grasp pinch_at_height(double z_m) {
  return test::top_down_pinch(gripper(), Eigen::Vector3d(0, 0, z_m), 0.5 * kBoxSide_m,
                              kOpenGripper_m);
}

SimParams gripper_params() {
  SimParams params;
  params.contact.soft_finger_radius_m = kPadPatchRadius_m;
  return params;
}

bool same_draw(const UncertaintyDraw& a, const UncertaintyDraw& b) {
  return a.hand_offset_G_m == b.hand_offset_G_m && a.hand_turn_G_rad == b.hand_turn_G_rad &&
         a.mu_factor == b.mu_factor && a.mass_factor == b.mass_factor &&
         a.com_offset_O_m == b.com_offset_O_m && a.squeeze_factor == b.squeeze_factor &&
         a.scores == b.scores;
}

TEST(DrawUncertainty, DependsOnSeedGraspAndTrialAloneAndOnEachOfThem) {
  const UncertaintyParams u;
  const UncertaintyDraw d = draw_uncertainty(u, 7, 3, 2);
  for (int repeat = 0; repeat < 3; ++repeat)  // no hidden state between calls
    EXPECT_TRUE(same_draw(d, draw_uncertainty(u, 7, 3, 2)));
  EXPECT_FALSE(same_draw(d, draw_uncertainty(u, 8, 3, 2)));
  EXPECT_FALSE(same_draw(d, draw_uncertainty(u, 7, 4, 2)));
  EXPECT_FALSE(same_draw(d, draw_uncertainty(u, 7, 3, 3)));
  EXPECT_FALSE(same_draw(draw_uncertainty(u, 7, 2, 3), draw_uncertainty(u, 7, 3, 2)));
}

TEST(DrawUncertainty, ZeroingOneSpreadLeavesTheOtherFactorsDrawsUnchanged) {
  UncertaintyParams without_friction;
  without_friction.mu_relative_spread = 0.0;
  const UncertaintyDraw a = draw_uncertainty(UncertaintyParams{}, 1, 0, 5);
  const UncertaintyDraw b = draw_uncertainty(without_friction, 1, 0, 5);
  EXPECT_EQ(b.mu_factor, 1.0);
  EXPECT_EQ(a.hand_offset_G_m, b.hand_offset_G_m);
  EXPECT_EQ(a.mass_factor, b.mass_factor);
  EXPECT_EQ(a.squeeze_factor, b.squeeze_factor);
  EXPECT_EQ(a.scores, b.scores);
}

TEST(DrawUncertainty, FollowsTheGaussianAndUniformSpreadsItIsGiven) {
  const UncertaintyParams u;
  double sum_sq_offset = 0.0, sum_sq_turn = 0.0, sum_sq_com = 0.0, sum_mu = 0.0;
  double lo_mass = 2.0, hi_mass = 0.0;
  for (int t = 0; t < kSamples; ++t) {
    const UncertaintyDraw d = draw_uncertainty(u, 11, 0, t);
    sum_sq_offset += d.hand_offset_G_m.squaredNorm();
    sum_sq_turn += d.hand_turn_G_rad.squaredNorm();
    sum_sq_com += d.com_offset_O_m.squaredNorm();
    sum_mu += d.mu_factor;
    lo_mass = std::min(lo_mass, d.mass_factor);
    hi_mass = std::max(hi_mass, d.mass_factor);
    ASSERT_GE(d.mu_factor, 1.0 - u.mu_relative_spread);
    ASSERT_LE(d.mu_factor, 1.0 + u.mu_relative_spread);
  }
  const double n = 3.0 * kSamples;  // three axes per vector
  EXPECT_NEAR(std::sqrt(sum_sq_offset / n), u.hand_offset_sigma_m,
              kSampleRelTol * u.hand_offset_sigma_m);
  EXPECT_NEAR(std::sqrt(sum_sq_turn / n), u.hand_turn_sigma_rad,
              kSampleRelTol * u.hand_turn_sigma_rad);
  EXPECT_NEAR(std::sqrt(sum_sq_com / n), u.com_offset_sigma_m,
              kSampleRelTol * u.com_offset_sigma_m);
  EXPECT_NEAR(sum_mu / kSamples, 1.0, kSampleRelTol * u.mu_relative_spread);
  // Uniform over ±30 %: the extremes come close to both ends.
  EXPECT_LT(lo_mass, 1.0 - (1.0 - kSampleRelTol) * u.mass_relative_spread);
  EXPECT_GT(hi_mass, 1.0 + (1.0 - kSampleRelTol) * u.mass_relative_spread);
}

TEST(ApplyUncertainty, NoneLeavesGraspAndPhysicsAsPlanned) {
  const Grasp g = pinch_at_height(0.0);
  const SimParams p = gripper_params();
  EXPECT_TRUE(is_none(uncertainty_none()));
  EXPECT_FALSE(is_none(UncertaintyParams{}));
  const UncertainTrial t = apply_uncertainty(g, p, draw_uncertainty(uncertainty_none(), 1, 0, 0));
  EXPECT_TRUE(t.grasp.X_OB.isApprox(g.X_OB, kPoseTol_m));
  EXPECT_TRUE(t.grasp.X_OG.isApprox(g.X_OG, kPoseTol_m));
  EXPECT_EQ(t.params.contact.mu, p.contact.mu);
  EXPECT_EQ(t.params.density_kgm3, p.density_kgm3);
  EXPECT_EQ(t.params.squeeze_weight_factor, p.squeeze_weight_factor);
  EXPECT_EQ(t.params.com_offset_x_m, 0.0);
}

TEST(ApplyUncertainty, MovesTheHandRigidlyInItsGcpFrameAndScalesTheObjectAndGrip) {
  const Grasp g = pinch_at_height(0.0);
  SimParams p = gripper_params();
  UncertaintyDraw d;
  d.hand_offset_G_m = Eigen::Vector3d(0.001, -0.002, 0.003);
  d.hand_turn_G_rad = Eigen::Vector3d(0.0, 0.0, 0.05);
  d.mu_factor = 0.8;
  d.mass_factor = 1.25;
  d.com_offset_O_m = Eigen::Vector3d(0.002, 0.0, -0.001);
  d.squeeze_factor = 0.9;
  const UncertainTrial t = apply_uncertainty(g, p, d);
  // The GCP moved by the offset, expressed in the planned GCP frame; the root moved with it.
  EXPECT_TRUE((g.X_OG.inverse() * t.grasp.X_OG.translation())
                  .isApprox(d.hand_offset_G_m, kPoseTol_m));
  EXPECT_TRUE((g.X_OB.inverse() * g.X_OG).isApprox(t.grasp.X_OB.inverse() * t.grasp.X_OG,
                                                    kPoseTol_m));
  EXPECT_NEAR(Eigen::AngleAxisd(g.X_OG.linear().transpose() * t.grasp.X_OG.linear()).angle(),
              0.05, kPoseTol_m);
  EXPECT_DOUBLE_EQ(t.params.contact.mu, 0.8 * p.contact.mu);
  EXPECT_DOUBLE_EQ(t.params.density_kgm3, 1.25 * p.density_kgm3);  // mass = density × volume
  EXPECT_FALSE(t.params.mass_kg.has_value());
  EXPECT_DOUBLE_EQ(t.params.com_offset_x_m, 0.002);
  EXPECT_DOUBLE_EQ(t.params.com_offset_z_m, -0.001);
  // Grip sized from the nominal μ and mass: k·m·g/μ with the true ones, times 0.9.
  EXPECT_DOUBLE_EQ(t.params.squeeze_weight_factor, p.squeeze_weight_factor * 0.9 * 0.8 / 1.25);
  p.mass_kg = 0.2;
  EXPECT_DOUBLE_EQ(*apply_uncertainty(g, p, d).params.mass_kg, 0.25);
}

/// The parallel gripper with its right pad uncoupled: two fingers that close on their own.
HandModel two_actor_gripper() {
  HandModel hand = gripper();
  const int left = find_joint(hand, "left_finger_joint");
  const int right = find_joint(hand, "right_finger_joint");
  hand.joints[static_cast<size_t>(right)].mimic.reset();
  const double speed = hand.actors.at(0).joints.at(0).direction_speed;
  hand.actors = {{"left", {{left, speed}}}, {"right", {{right, speed}}}};
  return hand;
}

/// The drawn pose's shift of the hand along the pads' closing axis (x_G = x_O) [m].
constexpr double kSideShift_m = 0.003;
/// A re-closed pad stops within the finger stage's contact tolerance of the face, plus its
/// bisection step [m].
constexpr double kReclosedTol_m = 1e-3;

TEST(CloseAtDrawnPose, AFingerTheDrawnPoseLeavesShortClosesOnAndOneThatMeetsEarlierKeepsThePlan) {
  const HandModel hand = two_actor_gripper();
  const auto collider = make_bullet_hand_collider(hand, box());
  const HandSetup setup = prepare_hand(hand, *collider);
  const Grasp planned =
      test::top_down_pinch(hand, Eigen::Vector3d(0, 0, 0), 0.5 * kBoxSide_m, kOpenGripper_m);
  UncertaintyDraw d;
  d.hand_offset_G_m = Eigen::Vector3d(kSideShift_m, 0, 0);
  const Grasp drawn = apply_uncertainty(planned, gripper_params(), d).grasp;
  const Grasp closed = close_at_drawn_pose(drawn, hand, setup, *collider);
  // One pad is now kSideShift_m further from its face: it closes on by about that much; the
  // other meets its face earlier and keeps the planned opening (it pushes the box there).
  int kept = 0, reclosed = -1;
  for (int j = 0; j < 2; ++j) {
    const double moved = drawn.q[j] - closed.q[j];
    if (moved == 0.0) {
      ++kept;
    } else {
      reclosed = j;
      EXPECT_NEAR(moved, kSideShift_m, kReclosedTol_m) << j;
    }
  }
  EXPECT_EQ(kept, 1);
  ASSERT_GE(reclosed, 0);
  // Its contacts are on the box's face, on the pad it moves.
  ASSERT_FALSE(closed.contacts.empty());
  for (const Contact& c : closed.contacts) {
    EXPECT_NEAR(std::abs(c.p_O.x()), 0.5 * kBoxSide_m, kReclosedTol_m);
    EXPECT_EQ(c.link, hand.joints[static_cast<size_t>(reclosed)].child_link);
  }
  EXPECT_TRUE(closed.X_OB.isApprox(drawn.X_OB, kPoseTol_m));  // the hand stays where drawn
}

TEST(CloseAtDrawnPose, TheCoupledGripperKeepsThePlanWhereverOnePadMeetsTheBoxEarlier) {
  const auto collider = make_bullet_hand_collider(gripper(), box());
  const HandSetup setup = prepare_hand(gripper(), *collider);
  const Grasp planned = pinch_at_height(0.0);
  UncertaintyDraw d;
  d.hand_offset_G_m = Eigen::Vector3d(-kSideShift_m, 0, 0);
  const Grasp drawn = apply_uncertainty(planned, gripper_params(), d).grasp;
  const Grasp closed = close_at_drawn_pose(drawn, gripper(), setup, *collider);
  EXPECT_EQ(closed.q, drawn.q);
  EXPECT_EQ(closed.contacts.size(), drawn.contacts.size());
}

TEST(ApplyUncertainty, TheCentreOfMassOffsetMovesTheSimulatedBodysCentre) {
  SimParams p = gripper_params();
  SimTests none;
  none.lift = none.shake = none.gravity6 = false;
  const SimResult nominal = validate_grasp(box(), gripper(), pinch_at_height(0.0), p, none);
  p.com_offset_y_m = 0.004;
  const SimResult moved = validate_grasp(box(), gripper(), pinch_at_height(0.0), p, none);
  EXPECT_TRUE((moved.object.com_O - nominal.object.com_O)
                  .isApprox(Eigen::Vector3d(0, 0.004, 0), kPoseTol_m));
  EXPECT_DOUBLE_EQ(moved.object.mass_kg, nominal.object.mass_kg);
}

TEST(CheckUncertaintyParams, NamesTheFieldOutOfRange) {
  UncertaintyParams u;
  u.mass_relative_spread = 1.5;
  try {
    check_uncertainty_params(u);
    FAIL() << "accepted a mass spread of 150 %";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("mass_relative_spread"), std::string::npos) << e.what();
  }
  u = UncertaintyParams{};
  u.hand_offset_sigma_m = -1e-3;
  EXPECT_THROW(check_uncertainty_params(u), std::invalid_argument);
}

TEST(StopDrawing, StopsOnceTheIntervalIsDecidedAndBeforeTheMinimumOnlyWhereItsVerdictIsSure) {
  HoldProbabilityParams p;  // threshold 0.8, 5 to 20 draws
  EXPECT_FALSE(stop_drawing(0, 2, p));   // [0, 0.66] but 3 of 5 is undecided
  EXPECT_TRUE(stop_drawing(0, 3, p));    // at most 2 of 5: below
  EXPECT_FALSE(stop_drawing(1, 3, p));   // 3 of 5 is undecided
  EXPECT_TRUE(stop_drawing(1, 4, p));    // at most 2 of 5
  EXPECT_FALSE(stop_drawing(2, 4, p));   // [0.15, 0.85]: undecided
  EXPECT_TRUE(stop_drawing(0, 5, p));    // [0, 0.43]: below
  EXPECT_TRUE(stop_drawing(2, 5, p));    // [0.12, 0.77]: below
  EXPECT_FALSE(stop_drawing(5, 5, p));   // [0.57, 1]: undecided
  EXPECT_FALSE(stop_drawing(15, 15, p));
  EXPECT_TRUE(stop_drawing(16, 16, p));  // [0.806, 1]: above
  EXPECT_TRUE(stop_drawing(17, 20, p));  // the most draws
  EXPECT_EQ(hold_verdict(wilson_interval(16, 16), 0.8), HoldVerdict::kAbove);
  EXPECT_EQ(hold_verdict(wilson_interval(2, 5), 0.8), HoldVerdict::kBelow);
  EXPECT_EQ(hold_verdict(wilson_interval(17, 20), 0.8), HoldVerdict::kUndecided);
}

TEST(StopDrawing, EndsEverySequenceWithTheVerdictOfATestThatLooksFirstAtTheMinimum) {
  // Every held / failed sequence of up to 10 draws, at three thresholds: the test that may stop
  // before min_draws ends with the verdict of one that never does, never later than it.
  for (const double threshold : {0.5, 0.8, 0.9}) {
    HoldProbabilityParams p;
    p.min_hold_probability = threshold;
    p.min_draws = 5;
    p.max_draws = 10;
    for (unsigned bits = 0; bits < (1u << p.max_draws); ++bits) {
      const auto run = [&](bool early) {
        int held = 0, draws = 0;
        while (true) {
          const bool stop = early ? stop_drawing(held, draws, p)
                                  : draws >= p.max_draws ||
                                        (draws >= p.min_draws &&
                                         hold_verdict(wilson_interval(held, draws), threshold) !=
                                             HoldVerdict::kUndecided);
          if (stop) break;
          held += (bits >> draws) & 1u;
          ++draws;
        }
        return std::make_pair(hold_verdict(wilson_interval(held, draws), threshold), draws);
      };
      const auto [verdict, draws] = run(true);
      const auto [verdict_at_minimum, draws_at_minimum] = run(false);
      ASSERT_EQ(verdict, verdict_at_minimum) << "threshold " << threshold << ", draws " << bits;
      ASSERT_LE(draws, draws_at_minimum);
    }
  }
}

TEST(ConfirmationTest, KeepsTheTestAndDrawsOtherConditions) {
  // The confirmation of an accepted grasp: the same threshold and draws, none of the first
  // test's conditions, the same every time.
  const HoldProbabilityParams first = hold_test_params(0.8, 20, 7);
  const HoldProbabilityParams second = confirmation_test(first);
  EXPECT_EQ(second.min_hold_probability, first.min_hold_probability);
  EXPECT_EQ(second.max_draws, first.max_draws);
  EXPECT_EQ(second.min_draws, first.min_draws);
  EXPECT_EQ(second.seed, confirmation_test(first).seed);
  for (int t = 0; t < first.max_draws; ++t)
    for (int u = 0; u < first.max_draws; ++u)
      EXPECT_NE(draw_uncertainty(UncertaintyParams{}, first.seed, 3, t).mu_factor,
                draw_uncertainty(UncertaintyParams{}, second.seed, 3, u).mu_factor)
          << t << " " << u;
}

TEST(FailureSensitivity, NamesTheFactorWhoseDrawsSetTheFailedTrialsApart) {
  std::vector<UncertainDrawResult> draws;
  for (int t = 0; t < 12; ++t) {
    UncertainDrawResult d;
    d.trial = t;
    d.draw = draw_uncertainty(UncertaintyParams{}, 3, 0, t);
    // Fails exactly when μ was drawn low.
    d.outcome = d.draw.mu_factor < 1.0 ? Outcome::kSlipped : Outcome::kHeld;
    draws.push_back(d);
  }
  const FailureSensitivity s = failure_sensitivity(draws, UncertaintyParams{});
  ASSERT_TRUE(s.most_associated.has_value());
  EXPECT_EQ(*s.most_associated, UncertaintyFactor::kFriction);
  ASSERT_EQ(s.factors.size(), static_cast<size_t>(kUncertaintyFactors));
  EXPECT_LT(s.factors[static_cast<size_t>(UncertaintyFactor::kFriction)].effect, 0.0);
  // Without friction spread the factor is left out; all held: nothing to tell apart.
  UncertaintyParams no_friction;
  no_friction.mu_relative_spread = 0.0;
  EXPECT_EQ(failure_sensitivity(draws, no_friction).factors.size(),
            static_cast<size_t>(kUncertaintyFactors - 1));
  for (UncertainDrawResult& d : draws) d.outcome = Outcome::kHeld;
  EXPECT_FALSE(failure_sensitivity(draws, UncertaintyParams{}).most_associated.has_value());
}

TEST(HoldProbability, ARimPinchIsLessLikelyToHoldThanAPinchAtTheMiddle) {
  SimTests lift;
  lift.shake = lift.gravity6 = false;
  HoldProbabilityParams test;
  test.max_draws = kComparisonDraws;
  const SimParams p = gripper_params();
  const UncertaintyParams u;
  const HoldProbability middle =
      estimate_hold_probability(box(), gripper(), pinch_at_height(0.0), 0, p, lift, u, test);
  // Pad tips kRimOverlap_m down the side faces: a hand 2 mm higher misses the box.
  const double rim_z = 0.5 * kBoxSide_m + kGcpToTips_m - kRimOverlap_m;
  const HoldProbability rim =
      estimate_hold_probability(box(), gripper(), pinch_at_height(rim_z), 0, p, lift, u, test);
  EXPECT_GE(middle.interval.p, rim.interval.p + kMinHoldGap)
      << hold_probability_line(middle) << "\n" << hold_probability_line(rim);
  EXPECT_LE(static_cast<int>(rim.draws.size()), kComparisonDraws);
  EXPECT_TRUE(rim.complete);
  // The same seed gives the same draws and verdicts, also with a re-closure collider lent to
  // the test and used before for another grasp (as validate and validated planning do).
  const HandModel hand = gripper();
  const Mesh object = box();
  DrawnPoseCloser closer(hand, object);
  estimate_hold_probability(object, hand, pinch_at_height(0.0), 0, p, lift, u, test, {}, 1,
                            &closer);
  const HoldProbability again = estimate_hold_probability(object, hand, pinch_at_height(rim_z), 0,
                                                          p, lift, u, test, {}, 1, &closer);
  ASSERT_EQ(again.draws.size(), rim.draws.size());
  for (size_t i = 0; i < rim.draws.size(); ++i) {
    EXPECT_TRUE(same_draw(again.draws[i].draw, rim.draws[i].draw));
    EXPECT_EQ(again.draws[i].outcome, rim.draws[i].outcome);
  }
}

}  // namespace
}  // namespace cordgrasp
