// The third-party hands in ../shared/data/hands with their descriptions in assets/hands.
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <cmath>
#include <map>
#include <set>
#include <string>

#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/palm_width.h"
#include "hand_checks.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kPosTol_m = 1e-7;
constexpr double kRotTol = 1e-7;
/// Closing check: 0.3 rad (or 0.3 x speed m) of actor motion, i.e. 15 finger-stage steps of
/// 0.02 rad (docs/algorithm.md §7.4), must bring every fingertip >= 3 mm nearer the GCP axis.
constexpr double kClosingStep = 0.3;
constexpr double kMinClosing_m = 0.003;

/// Joint counts of each staged hand, from ../shared/data/MANIFEST.md.
struct ManifestHand {
  const char* name;
  int fixed;
  int revolute;
  int prismatic;
};
constexpr ManifestHand kManifestHands[] = {
    {"schunk_sah", 22, 16, 0},   {"icub_right_hand", 6, 20, 0}, {"armar3_right_hand", 13, 11, 0},
    {"allegro_right", 4, 16, 0}, {"panda_hand", 1, 0, 2},       {"barrett_bh282", 1, 8, 0},
};

TEST(HandDataset, EveryStagedHandHasADescriptionAndLoadsWithManifestJointCounts) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  std::set<std::string> staged;
  for (const auto& e : std::filesystem::directory_iterator(test::shared_data_dir() + "/hands"))
    if (e.is_directory()) staged.insert(e.path().filename().string());
  std::set<std::string> described;
  for (const ManifestHand& m : kManifestHands) described.insert(m.name);
  EXPECT_EQ(staged, described) << "a staged hand without a description (or vice versa)";
  for (const ManifestHand& m : kManifestHands) {
    SCOPED_TRACE(m.name);
    const HandModel h = load_hand(m.name);
    std::map<JointType, int> count;
    for (const Joint& j : h.joints) ++count[j.type];
    EXPECT_EQ(count[JointType::kFixed], m.fixed);
    EXPECT_EQ(count[JointType::kRevolute], m.revolute);
    EXPECT_EQ(count[JointType::kPrismatic], m.prismatic);
    EXPECT_EQ(h.links.size(), h.joints.size() + 1);
    EXPECT_NE(h.urdf_path.find("shared/data/hands/" + std::string(m.name)), std::string::npos);
  }
}

TEST(HandDataset, EveryDescriptionShippedInAssetsLoads) {
  CORDGRASP_REQUIRE_SHARED_DATA();  // some descriptions name URDFs in ../shared/data
  const std::string dir = shipped_hands_dir();
  std::vector<std::string> files = test::files_in(dir, ".yaml");
  for (const auto& e : std::filesystem::directory_iterator(dir))
    if (e.is_directory())
      for (const auto& f : test::files_in(e.path().string(), ".yaml")) files.push_back(f);
  EXPECT_GE(files.size(), 8u);
  for (const auto& f : files) {
    SCOPED_TRACE(f);
    const HandModel h = load_hand(f);
    test::expect_hand_conventions(h, kClosingStep, kMinClosing_m);
    EXPECT_TRUE(h.palm_normal.has_value()) << "every shipped hand sets palm_normal";
  }
}

TEST(HandDataset, GcpPalmNormalAndActorsFollowTheConventionsOnEveryHand) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  for (const ManifestHand& m : kManifestHands)
    test::expect_hand_conventions(load_hand(m.name), kClosingStep, kMinClosing_m);
}

TEST(HandDataset, SahGcpInPreshapeIsTheSimoxRightArmGcp) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  const HandModel h = load_hand("schunk_sah");
  EXPECT_EQ(h.links[h.gcp.link].name, "Right Arm GCP_link");
  // Simox SAH_RightHand.xml: "Right Arm GCP" = (100, 22, 180) mm, pitch 30 deg, from "Right Hand
  // Init", which sits at the root ("Right Hand Start") with identity (docs/algorithm.md §1).
  const Eigen::Isometry3d X_WG = gcp_pose(h, link_poses(h, h.preshape));
  EXPECT_LT((X_WG.translation() - Eigen::Vector3d(0.100, 0.022, 0.180)).norm(), kPosTol_m);
  const Eigen::Matrix3d R = Eigen::AngleAxisd(M_PI / 6, Eigen::Vector3d::UnitY()).matrix();
  EXPECT_LT((X_WG.linear() - R).norm(), kRotTol);
}

TEST(HandDataset, SahFingerPoseAgreesWithComposedUrdfOrigins) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  const HandModel h = load_hand("schunk_sah");
  Eigen::VectorXd q = apply_couplings(h, h.preshape);
  const double q_base = 0.1, q_prox = 0.6, q_mid = 0.4;
  q[find_joint(h, "forefinger.baseJoint")] = q_base;
  q[find_joint(h, "forefinger.proximalJoint")] = q_prox;
  q[find_joint(h, "forefinger.middleJoint")] = q_mid;
  const auto X = link_poses(h, apply_couplings(h, q));
  // The URDF origins, composed by hand: rpy = Rz(yaw) Ry(pitch) Rx(roll).
  auto rpy = [](double r, double p, double y) {
    return Eigen::Matrix3d(Eigen::AngleAxisd(y, Eigen::Vector3d::UnitZ()) *
                           Eigen::AngleAxisd(p, Eigen::Vector3d::UnitY()) *
                           Eigen::AngleAxisd(r, Eigen::Vector3d::UnitX()));
  };
  auto rz = [](double a) {
    return Eigen::Matrix3d(Eigen::AngleAxisd(a, Eigen::Vector3d::UnitZ()));
  };
  Eigen::Isometry3d X_expected = Eigen::Isometry3d::Identity();
  X_expected.translate(Eigen::Vector3d(-0.003, 0.04025, 0.15584));
  X_expected.rotate(rpy(0, -1.57079633, -3.10611011) * rz(q_base));
  X_expected.rotate(rpy(1.57079633, 0, 0) * rz(q_prox));
  X_expected.translate(Eigen::Vector3d(0.0678, 0, 0));
  X_expected.rotate(rz(q_mid));
  const Eigen::Isometry3d& X_got = X[find_link(h, "forefinger.middleJoint_link")];
  EXPECT_LT((X_got.translation() - X_expected.translation()).norm(), kPosTol_m);
  EXPECT_LT((X_got.linear() - X_expected.linear()).norm(), kRotTol);
  // distal = middle (coupling from the description, as the real SAH).
  const Joint& distal = h.joints[find_joint(h, "forefinger.distalJoint")];
  ASSERT_TRUE(distal.mimic.has_value());
  EXPECT_EQ(distal.mimic->master_joint, find_joint(h, "forefinger.middleJoint"));
}

TEST(HandDataset, MeshScaleIsHonouredOnTheIcubTopCover) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  const HandModel h = load_hand("icub_right_hand");
  const Link& palm = h.links[find_link(h, "r_hand")];
  ASSERT_EQ(palm.visuals.size(), 2u);
  const Geometry& cover = palm.visuals[1];
  ASSERT_TRUE(cover.mesh);
  EXPECT_NE(cover.mesh_path.find("full_RightTopCover.stl"), std::string::npos);
  Eigen::Vector3d lo = Eigen::Vector3d::Constant(1e9), hi = -lo;
  for (const auto& v : cover.mesh->vertices) {
    lo = lo.cwiseMin(v);
    hi = hi.cwiseMax(v);
  }
  // MANIFEST: 65.340 x 71.081 x 36.702 in the file (mm), scale 0.001 in the URDF.
  EXPECT_NEAR((hi - lo).x(), 0.06534, 1e-4);
  EXPECT_NEAR((hi - lo).y(), 0.071081, 1e-4);
}

TEST(HandDataset, InertialsArePhysicalAfterSubstitution) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  for (const ManifestHand& m : kManifestHands) {
    const HandModel h = load_hand(m.name);
    for (const Link& l : h.links) {
      SCOPED_TRACE(std::string(m.name) + " / " + l.name);
      EXPECT_GT(l.inertial.mass_kg, 0.0);
      const Eigen::Vector3d ev =
          Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d>(l.inertial.inertia_kgm2).eigenvalues();
      EXPECT_GT(ev.minCoeff(), 0.0);
      EXPECT_GE(ev(0) + ev(1), ev(2) * (1 - 1e-9));  // triangle inequality
    }
  }
}

TEST(HandDataset, OnlyMissingOrPlaceholderInertialsAreSubstituted) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  auto substituted = [](const HandModel& h) {
    std::set<std::string> out;
    for (const Link& l : h.links)
      if (l.inertial.substituted) out.insert(l.name);
    return out;
  };
  EXPECT_TRUE(substituted(load_hand("schunk_sah")).empty());  // estimated, but physical
  EXPECT_EQ(substituted(load_hand("panda_hand")), std::set<std::string>{"panda_hand_tcp"});
  const HandModel icub = load_hand("icub_right_hand");
  const auto s = substituted(icub);
  EXPECT_TRUE(s.count("r_hand_index_tip"));  // no <inertial>
  EXPECT_TRUE(s.count("r_hand_index_1"));    // 10 g with I = 1e-3 kg m^2
  EXPECT_DOUBLE_EQ(icub.links[find_link(icub, "r_hand_index_1")].inertial.mass_kg, 0.01);
  const HandModel armar = load_hand("armar3_right_hand");
  const Link& phalanx = armar.links[find_link(armar, "Index R J0_link")];  // 0.5 kg, 6x10x45 mm
  EXPECT_TRUE(phalanx.inertial.substituted);
  EXPECT_LT(phalanx.inertial.mass_kg, 0.05);
  EXPECT_FALSE(armar.links[find_link(armar, "Hand Palm 1 R_link")].inertial.substituted);
}

TEST(HandDataset, CouplingsFollowTheRealHands) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  const HandModel bh = load_hand("barrett_bh282");
  Eigen::VectorXd q = bh.preshape;
  q[find_joint(bh, "bh_j11_joint")] = 0.5;
  q[find_joint(bh, "bh_j12_joint")] = 1.0;
  q = apply_couplings(bh, q);
  EXPECT_DOUBLE_EQ(q[find_joint(bh, "bh_j21_joint")], 0.5);  // one spread motor
  EXPECT_NEAR(q[find_joint(bh, "bh_j13_joint")], 0.344, 1e-12);
  EXPECT_EQ(degrees_of_freedom(bh), 4);
  const HandModel panda = load_hand("panda_hand");
  EXPECT_EQ(degrees_of_freedom(panda), 1);  // URDF <mimic>
}

TEST(HandDataset, PalmWidthsAreHandSized) {
  CORDGRASP_REQUIRE_SHARED_DATA();
  for (const ManifestHand& m : kManifestHands) {
    const double w = measure_palm_width(load_hand(m.name));
    EXPECT_GT(w, 0.015) << m.name;
    EXPECT_LT(w, 0.16) << m.name;
  }
  EXPECT_NEAR(measure_palm_width(load_hand("panda_hand")), 0.022, 0.002);  // finger width
}

}  // namespace
}  // namespace cordgrasp
