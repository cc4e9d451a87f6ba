// load_hand / resolve_hand_path on small hand-written URDFs and the shipped primitive hands.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <limits>
#include <string>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/geometry_points.h"
#include "cordgrasp/core/hand_fingers.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/hand_conventions.h"
#include "hand_checks.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

namespace fs = std::filesystem;
using test::test_data;

constexpr double kTol = 1e-12;
constexpr double kPosTol_m = 1e-9;
constexpr double kMeshTol_m = 1e-8;  // meshes are read in single precision

const Joint& joint(const HandModel& h, const std::string& name) {
  const int j = find_joint(h, name);
  EXPECT_GE(j, 0) << name;
  return h.joints.at(j);
}

const Link& link(const HandModel& h, const std::string& name) {
  const int l = find_link(h, name);
  EXPECT_GE(l, 0) << name;
  return h.links.at(l);
}

TEST(LoadHand, JointsAreTopologicallyOrderedWithLinksNamedWithSpaces) {
  const HandModel h = load_hand(test_data("hands/two_link/two_link.yaml"));
  EXPECT_EQ(h.name, "two_link");
  ASSERT_EQ(h.links.size(), 4u);
  ASSERT_EQ(h.joints.size(), 3u);
  EXPECT_EQ(h.links[h.root_link].name, "base");
  EXPECT_EQ(h.links[h.root_link].parent_joint, -1);
  for (size_t j = 0; j < h.joints.size(); ++j) {
    EXPECT_LT(h.joints[j].parent_link, h.joints[j].child_link);
    EXPECT_EQ(h.links[h.joints[j].child_link].parent_joint, static_cast<int>(j));
  }
  EXPECT_GE(find_link(h, "upper arm"), 0);
  EXPECT_GE(find_joint(h, "tool frame"), 0);
  EXPECT_EQ(degrees_of_freedom(h), 2);
  EXPECT_NEAR(total_mass(h), 0.5 + 0.1 + 0.05 + 0.001, kTol);
}

TEST(LoadHand, TwoLinkChainForwardKinematicsMatchesHandComputation) {
  const HandModel h = load_hand(test_data("hands/two_link/two_link.yaml"));
  const int shoulder = find_joint(h, "shoulder");
  const int elbow = find_joint(h, "elbow");
  for (const auto& [q1, q2] :
       {std::pair{0.0, 0.0}, {0.7, -1.1}, {-1.2, 1.9}, {M_PI / 2, -M_PI / 2}}) {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(3);
    q[shoulder] = q1;
    q[elbow] = q2;
    const auto X = link_poses(h, q);
    // Elbow at (0,0,0.1) + Rz(q1)(0.3,0,0); tool at elbow + Rz(q1+q2)(0.2,0,0).
    const Eigen::Vector3d p_elbow(0.3 * std::cos(q1), 0.3 * std::sin(q1), 0.1);
    const Eigen::Vector3d p_tool =
        p_elbow + Eigen::Vector3d(0.2 * std::cos(q1 + q2), 0.2 * std::sin(q1 + q2), 0.0);
    EXPECT_TRUE(X[find_link(h, "fore arm")].translation().isApprox(p_elbow, kPosTol_m));
    const Eigen::Isometry3d& X_tool = X[find_link(h, "tool")];
    EXPECT_LT((X_tool.translation() - p_tool).norm(), kPosTol_m);
    const Eigen::Matrix3d R = Eigen::AngleAxisd(q1 + q2, Eigen::Vector3d::UnitZ()).matrix();
    EXPECT_LT((X_tool.linear() - R).norm(), kPosTol_m);
    // GCP: 1 cm further along the tool x axis, its +z turned onto the tool's +x (pitch 90 deg).
    const Eigen::Isometry3d X_WG = gcp_pose(h, X);
    EXPECT_LT((X_WG.translation() - (p_tool + 0.01 * R.col(0))).norm(), kPosTol_m);
    EXPECT_LT((X_WG.linear().col(2) - R.col(0)).norm(), kPosTol_m);
  }
}

TEST(LoadHand, PreshapeListsGivenValuesAndClampsUnlistedZeros) {
  const HandModel h = load_hand(test_data("hands/two_link/two_link.yaml"));
  ASSERT_EQ(h.preshape.size(), 3);
  EXPECT_DOUBLE_EQ(h.preshape[find_joint(h, "shoulder")], 0.25);
  EXPECT_DOUBLE_EQ(h.preshape[find_joint(h, "elbow")], 0.0);
  ASSERT_EQ(h.actors.size(), 1u);
  EXPECT_EQ(h.actors[0].name, "finger");
  ASSERT_EQ(h.actors[0].joints.size(), 1u);
  EXPECT_EQ(h.actors[0].joints[0].joint, find_joint(h, "elbow"));
  EXPECT_DOUBLE_EQ(h.actors[0].joints[0].direction_speed, 1.0);
}

TEST(LoadHand, HonoursJointTypesLimitsAxesAndMimic) {
  const HandModel h = load_hand(test_data("hands/features/features.yaml"));
  EXPECT_EQ(h.name, "features");  // defaults to the file stem
  const Joint& roll = joint(h, "wrist roll");
  EXPECT_EQ(roll.type, JointType::kContinuous);
  EXPECT_EQ(roll.lower, -std::numeric_limits<double>::infinity());
  EXPECT_EQ(roll.upper, std::numeric_limits<double>::infinity());
  EXPECT_TRUE(roll.axis.isApprox(Eigen::Vector3d::UnitZ()));  // "0 0 2" normalized
  const Joint& slide = joint(h, "slide");
  EXPECT_EQ(slide.type, JointType::kPrismatic);
  EXPECT_DOUBLE_EQ(slide.lower, 0.0);
  EXPECT_DOUBLE_EQ(slide.upper, 0.05);
  EXPECT_DOUBLE_EQ(slide.effort_limit, 40.0);
  EXPECT_DOUBLE_EQ(slide.velocity_limit, 0.0);  // "-1" = unlimited, stored as "not given"
  const Joint& mirror = joint(h, "slide mirror");
  ASSERT_TRUE(mirror.mimic.has_value());
  EXPECT_EQ(mirror.mimic->master_joint, find_joint(h, "slide"));
  EXPECT_DOUBLE_EQ(mirror.mimic->offset, 0.001);
  EXPECT_EQ(degrees_of_freedom(h), 2);  // wrist roll + slide; the mirror follows
  EXPECT_NEAR(h.preshape[find_joint(h, "slide mirror")], 0.021, kTol);

  // Prismatic motion along the axis, mimic mirrored.
  Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(h.joints.size()));
  q[find_joint(h, "slide")] = 0.03;
  const auto X = link_poses(h, apply_couplings(h, q));
  EXPECT_TRUE(X[find_link(h, "slider")].translation().isApprox(Eigen::Vector3d(0.03, 0.02, 0.01)));
  EXPECT_TRUE(
      X[find_link(h, "mirror")].translation().isApprox(Eigen::Vector3d(-0.031, -0.02, 0.01)));
}

TEST(LoadHand, ReadsGeometryMaterialsAndSharesScaledMeshes) {
  const HandModel h = load_hand(test_data("hands/features/features.yaml"));
  const Link& palm = link(h, "palm base");
  ASSERT_EQ(palm.collisions.size(), 2u);
  EXPECT_EQ(palm.collisions[0].kind, Geometry::Kind::kBox);
  EXPECT_TRUE(palm.collisions[0].box_size_m.isApprox(Eigen::Vector3d(0.1, 0.08, 0.02)));
  EXPECT_EQ(palm.collisions[1].kind, Geometry::Kind::kCylinder);
  EXPECT_DOUBLE_EQ(palm.collisions[1].radius_m, 0.01);
  EXPECT_DOUBLE_EQ(palm.collisions[1].length_m, 0.05);
  EXPECT_TRUE(palm.collisions[1].X_LG.translation().isApprox(Eigen::Vector3d(0, 0, -0.035)));
  ASSERT_EQ(palm.visuals.size(), 2u);
  EXPECT_TRUE(palm.visuals[0].rgba.isApprox(Eigen::Vector4d(0, 0, 1, 1)));    // global "Blue"
  EXPECT_TRUE(palm.visuals[1].rgba.isApprox(Eigen::Vector4d(1, 0, 0, 0.5)));  // inline
  EXPECT_EQ(palm.visuals[1].kind, Geometry::Kind::kSphere);

  const Link& slider = link(h, "slider");
  ASSERT_EQ(slider.collisions.size(), 1u);
  ASSERT_EQ(slider.visuals.size(), 2u);
  const Geometry& col = slider.collisions[0];
  ASSERT_EQ(col.kind, Geometry::Kind::kMesh);
  ASSERT_TRUE(col.mesh);
  EXPECT_EQ(col.mesh->triangles.size(), 4u);
  EXPECT_TRUE(fs::path(col.mesh_path).is_absolute() || fs::exists(col.mesh_path));
  double max_coord = 0.0;
  for (const auto& v : col.mesh->vertices) max_coord = std::max(max_coord, v.maxCoeff());
  EXPECT_NEAR(max_coord, 0.05, kMeshTol_m);     // scale 0.5 applied
  EXPECT_EQ(slider.visuals[0].mesh, col.mesh);  // same file and scale: shared
  EXPECT_NE(slider.visuals[1].mesh, col.mesh);  // same file, scale 1: its own copy
  EXPECT_TRUE(slider.visuals[0].rgba.isApprox(Eigen::Vector4d(0.7, 0.7, 0.7, 1.0)));
}

TEST(LoadHand, SubstitutesMissingAndImpossibleInertialsKeepingPlausibleMass) {
  const HandModel h = load_hand(test_data("hands/features/features.yaml"));
  EXPECT_FALSE(link(h, "palm base").inertial.substituted);
  EXPECT_FALSE(link(h, "rotor").inertial.substituted);
  EXPECT_DOUBLE_EQ(link(h, "rotor").inertial.mass_kg, 0.02);

  const Inertial& slider = link(h, "slider").inertial;  // no <inertial>
  EXPECT_TRUE(slider.substituted);
  // Solid box of the collision tetrahedron's bounds (0.05 m cube) at 700 kg/m^3.
  EXPECT_NEAR(slider.mass_kg, 700.0 * 0.05 * 0.05 * 0.05, 1e-6);
  EXPECT_LT((slider.com_m - Eigen::Vector3d::Constant(0.025)).norm(), kMeshTol_m);

  const Inertial& mirror = link(h, "mirror").inertial;  // 10 g with I = 1e-3 kg m^2: impossible
  EXPECT_TRUE(mirror.substituted);
  EXPECT_DOUBLE_EQ(mirror.mass_kg, 0.01);
  const double i_box = 0.01 * (0.02 * 0.02 + 0.02 * 0.02) / 12.0;
  EXPECT_TRUE(mirror.inertia_kgm2.isApprox(Eigen::Matrix3d::Identity() * i_box, 1e-9));
}

TEST(LoadHand, WarnsOncePerHandNamingTheSubstitutedLinks) {
  // A private copy so that no earlier load in this process has warned about it yet.
  const fs::path dir = fs::temp_directory_path() / ("cordgrasp_warn_" + std::to_string(::getpid()));
  fs::remove_all(dir);
  fs::create_directories(dir);
  fs::copy(test_data("hands/features"), dir, fs::copy_options::recursive);
  const std::string yaml = (dir / "features.yaml").string();
  testing::internal::CaptureStderr();
  load_hand(yaml);
  load_hand(yaml);
  const std::string err = testing::internal::GetCapturedStderr();
  fs::remove_all(dir);
  EXPECT_NE(err.find("'slider'"), std::string::npos) << err;
  EXPECT_NE(err.find("'mirror'"), std::string::npos) << err;
  EXPECT_EQ(err.find("'rotor'"), std::string::npos) << err;
  EXPECT_EQ(err.find("warning"), err.rfind("warning")) << "warned more than once:\n" << err;
}

TEST(LoadHand, PalmWidthOverrideSoftFingerRadiusAndThumbLinksAreRead) {
  const HandModel h = load_hand(test_data("hands/features/features.yaml"));
  ASSERT_TRUE(h.palm_width_m.has_value());
  EXPECT_DOUBLE_EQ(*h.palm_width_m, 0.07);
  EXPECT_DOUBLE_EQ(h.soft_finger_radius_m, 0.004);
  EXPECT_DOUBLE_EQ(load_hand("cordgrasp_sah").soft_finger_radius_m, 0.0);  // point contacts
  ASSERT_EQ(h.thumb_links.size(), 1u);
  EXPECT_EQ(h.thumb_links[0], find_link(h, "slider"));
  EXPECT_TRUE(
      gcp_pose(h, link_poses(h, h.preshape)).translation().isApprox(Eigen::Vector3d(0, 0, 0.05)));
}

// --- bad input ---------------------------------------------------------------------------------

struct BadHandCase {
  const char* file;     ///< under tests/data/hands/bad
  const char* message;  ///< expected in the error
};

class LoadHandBadInput : public testing::TestWithParam<BadHandCase> {};

TEST_P(LoadHandBadInput, ThrowsOneLineNamingTheFileAndTheProblem) {
  const std::string path = test_data(std::string("hands/bad/") + GetParam().file);
  try {
    load_hand(path);
    FAIL() << "no error for " << path;
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find(GetParam().message), std::string::npos) << what;
    EXPECT_EQ(what.find('\n'), std::string::npos) << "not one line: " << what;
    EXPECT_EQ(what.rfind("load_hand: '", 0), 0u) << what;
  }
}

INSTANTIATE_TEST_SUITE_P(
    AllCases, LoadHandBadInput,
    testing::Values(
        BadHandCase{"missing_urdf.yaml", "URDF 'does_not_exist.urdf' not found"},
        BadHandCase{"missing_mesh.yaml", "mesh file 'meshes/nope.stl' not found"},
        BadHandCase{"gcp_link_not_found.yaml", "GCP link 'no_such_link' not found"},
        BadHandCase{"preshape_unknown_joint.yaml", "preshape names unknown joint 'no_such_joint'"},
        BadHandCase{"preshape_outside_limits.yaml", "outside its limits"},
        BadHandCase{"actor_unknown_joint.yaml", "actor 'finger' names unknown joint 'wrist'"},
        BadHandCase{"coupling_unknown_joint.yaml",
                    "coupling master names unknown joint 'no_such_master'"},
        BadHandCase{"inverted_limits.yaml", "joint 'elbow' has inverted limits"},
        BadHandCase{"no_moving_joint.yaml", "URDF has no moving joint"},
        BadHandCase{"joint_cycle.yaml", "joints form a cycle through link 'a'"},
        BadHandCase{"two_parents.yaml", "link 'c' is the child of two joints"},
        BadHandCase{"yaml_syntax_error.yaml", "YAML syntax error at line"},
        BadHandCase{"millimetres.yaml", "looks like it is in millimetres"},
        BadHandCase{"malformed_urdf.yaml", "URDF parse error"},
        BadHandCase{"unknown_key.yaml", "unknown key 'actor'"},
        BadHandCase{"soft_finger_radius_mm.yaml", "soft_finger_radius_m must be in [0, 0.05) m"}),
    [](const testing::TestParamInfo<BadHandCase>& info) {
      std::string n = fs::path(info.param.file).stem().string();
      return n;
    });

TEST(LoadHandBadInputFile, NamesTheFileThatIsWrong) {
  // The URDF is named for URDF problems, the description for description problems.
  try {
    load_hand(test_data("hands/bad/inverted_limits.yaml"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("inverted_limits.urdf'"), std::string::npos);
  }
  try {
    load_hand(test_data("hands/bad/gcp_link_not_found.yaml"));
    FAIL();
  } catch (const InputError& e) {
    EXPECT_NE(std::string(e.what()).find("gcp_link_not_found.yaml'"), std::string::npos);
  }
}

// --- resolving names ---------------------------------------------------------------------------

TEST(ResolveHandPath, FindsShippedHandsByNameInFileOrFolderLayout) {
  EXPECT_EQ(fs::path(resolve_hand_path("cordgrasp_sah")).filename(), "cordgrasp_sah.yaml");
  EXPECT_EQ(fs::path(resolve_hand_path("schunk_sah")).filename(), "schunk_sah.yaml");
  const std::string file = test_data("hands/two_link/two_link.yaml");
  EXPECT_EQ(resolve_hand_path(file), file);
  EXPECT_EQ(fs::path(resolve_hand_path(test_data("hands/two_link"))), fs::path(file));
}

TEST(ResolveHandPath, UnknownNameListsShippedHands) {
  try {
    resolve_hand_path("no_such_hand");
    FAIL();
  } catch (const InputError& e) {
    const std::string what = e.what();
    EXPECT_NE(what.find("'no_such_hand'"), std::string::npos) << what;
    EXPECT_NE(what.find("cordgrasp_sah"), std::string::npos) << what;
  }
}

TEST(ResolveHandPath, RejectsAUrdfWithAHint) {
  EXPECT_THROW(resolve_hand_path(test_data("hands/two_link/two_link.urdf")), InputError);
}

TEST(ResolveHandPath, AssetsDirectoryCanBeOverriddenByEnvironment) {
  const fs::path dir =
      fs::temp_directory_path() / ("cordgrasp_assets_" + std::to_string(::getpid()));
  fs::create_directories(dir / "hands" / "mine");
  fs::copy_file(test_data("hands/two_link/two_link.urdf"),
                dir / "hands" / "mine" / "two_link.urdf");
  fs::copy_file(test_data("hands/two_link/two_link.yaml"), dir / "hands" / "mine" / "mine.yaml");
  ::setenv("CORDGRASP_ASSETS_DIR", dir.c_str(), 1);
  EXPECT_EQ(shipped_hands_dir(), (dir / "hands").string());
  const HandModel h = load_hand("mine");
  EXPECT_EQ(h.name, "two_link");
  EXPECT_THROW(resolve_hand_path("cordgrasp_sah"), InputError);
  ::unsetenv("CORDGRASP_ASSETS_DIR");
  fs::remove_all(dir);
  EXPECT_NO_THROW(resolve_hand_path("cordgrasp_sah"));
}

// --- the project's own hands -------------------------------------------------------------------

TEST(ShippedHands, DefaultHandIsTheSahModelAndLoads) {
  EXPECT_STREQ(default_hand_name(), "cordgrasp_sah");
  EXPECT_NO_THROW(load_hand(default_hand_name()));
}

TEST(ShippedHands, CordgraspSahIsAFourFingerSahSizedHand) {
  const HandModel h = load_hand("cordgrasp_sah");
  int moving = 0, mimic = 0;
  for (const Joint& j : h.joints) {
    moving += j.is_moving();
    mimic += j.mimic.has_value();
    if (j.is_moving()) {
      EXPECT_GT(j.effort_limit, 0.0) << j.name;
      EXPECT_GT(j.velocity_limit, 0.0) << j.name;
      EXPECT_LT(j.lower, j.upper) << j.name;
    }
  }
  EXPECT_EQ(moving, 17);  // 4 fingers x 4 + thumb opposition
  EXPECT_EQ(mimic, 4);    // distal = middle in every finger
  EXPECT_EQ(degrees_of_freedom(h), 13);
  EXPECT_EQ(h.actors.size(), 4u);
  EXPECT_GT(total_mass(h), 1.0);
  EXPECT_LT(total_mass(h), 1.5);
  for (const Link& l : h.links) {
    EXPECT_FALSE(l.inertial.substituted) << l.name;
    EXPECT_FALSE(l.collisions.empty()) << l.name;
    EXPECT_EQ(l.collisions.size(), l.visuals.size()) << l.name;
    for (const Geometry& g : l.collisions) EXPECT_NE(g.kind, Geometry::Kind::kMesh) << l.name;
  }
  // SAH ranges: proximal -4..75 deg, middle 4..75 deg, abduction +-15 deg.
  constexpr double kDeg = M_PI / 180.0;
  EXPECT_NEAR(joint(h, "index_proximal").lower, -4 * kDeg, 1e-8);
  EXPECT_NEAR(joint(h, "index_middle").upper, 75 * kDeg, 1e-8);
  EXPECT_NEAR(joint(h, "ring_abduction").upper, 15 * kDeg, 1e-8);
  // Fingers ~10 cm from the proximal joint to the tip, fingertips ~9 cm apart across the palm.
  const auto X = link_poses(h, apply_couplings(h, h.preshape));
  const std::vector<Finger> fingers = hand_fingers(h);
  ASSERT_EQ(fingers.size(), 4u);
  const Finger& index = fingers[1];
  EXPECT_EQ(h.actors[index.actor].name, "index");
  EXPECT_TRUE(fingers[0].is_thumb);
  const Eigen::Vector3d p_tip = X[index.tip_link] * index.p_tip_L;
  const Eigen::Vector3d p_prox = X[find_link(h, "index_proximal_link")].translation();
  EXPECT_NEAR((p_tip - p_prox).norm(), 0.1, 0.01);
}

TEST(ShippedHands, ParallelGripperOpensTenCentimetresWithMimicFinger) {
  const HandModel h = load_hand("parallel_gripper");
  EXPECT_EQ(degrees_of_freedom(h), 1);
  const Joint& left = joint(h, "left_finger_joint");
  const Joint& right = joint(h, "right_finger_joint");
  ASSERT_TRUE(right.mimic.has_value());
  EXPECT_EQ(right.mimic->master_joint, find_joint(h, "left_finger_joint"));
  EXPECT_GE(left.effort_limit, 50.0);
  EXPECT_LE(left.effort_limit, 100.0);
  // Pad faces: distance between the two pads' inner faces equals 2 q.
  for (double q_open : {0.0, 0.02, 0.05}) {
    Eigen::VectorXd q = Eigen::VectorXd::Zero(static_cast<Eigen::Index>(h.joints.size()));
    q[find_joint(h, "left_finger_joint")] = q_open;
    const auto X = link_poses(h, apply_couplings(h, q));
    auto inner_face_y = [&](const std::string& name, double sign) {
      double best = sign * 1e9;
      const int l = find_link(h, name);
      std::vector<Eigen::Vector3d> pts;
      append_collision_points(h.links[l], pts);
      for (const auto& p : pts) {
        const double y = (X[l] * p).y();
        best = sign > 0 ? std::min(best, y) : std::max(best, y);
      }
      return best;
    };
    EXPECT_NEAR(inner_face_y("left_finger", 1) - inner_face_y("right_finger", -1), 2 * q_open,
                1e-12);
  }
  EXPECT_NEAR(left.upper, 0.05, 1e-12);  // opening 0..10 cm
}

TEST(ShippedHands, GcpPointsIntoTheGraspAndActorsClose) {
  for (const char* name : {"cordgrasp_sah", "parallel_gripper"}) {
    const HandModel h = load_hand(name);
    test::expect_hand_conventions(h, 0.3, 0.003);
    EXPECT_TRUE(h.palm_normal.has_value()) << name;
  }
}

TEST(ShippedHands, PalmNormalIsReadAsAUnitVectorOnItsLink) {
  const HandModel h = load_hand("cordgrasp_sah");
  ASSERT_TRUE(h.palm_normal.has_value());
  EXPECT_EQ(h.links[h.palm_normal->link].name, "palm");
  EXPECT_NEAR(h.palm_normal->n_L.norm(), 1.0, 1e-12);
  EXPECT_TRUE(h.palm_normal->n_L.isApprox(Eigen::Vector3d::UnitX()));
}

TEST(HandConventions, FlippedPalmNormalIsReported) {
  HandModel h = load_hand("cordgrasp_sah");
  EXPECT_TRUE(check_hand_conventions(h).empty());
  h.palm_normal->n_L = -h.palm_normal->n_L;
  const auto problems = check_hand_conventions(h);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("palm normal"), std::string::npos) << problems.front();
}

TEST(HandConventions, ReversedActorIsReported) {
  HandModel h = load_hand("cordgrasp_sah");
  for (auto& e : h.actors[1].joints) e.direction_speed = -e.direction_speed;
  const auto problems = check_hand_conventions(h);
  ASSERT_FALSE(problems.empty());
  EXPECT_NE(problems.front().find("actor 'index'"), std::string::npos) << problems.front();
}

}  // namespace
}  // namespace cordgrasp
