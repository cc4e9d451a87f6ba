// Tools-side scene building: hand colours, hand + object pictures, overlays, snapshot series.
#include "cordgrasp/jobs/hand_scene.h"

#include <gtest/gtest.h>

#include <filesystem>

#include "cordgrasp/core/error.h"
#include "cordgrasp/core/hand_fingers.h"
#include "cordgrasp/core/hand_io.h"
#include "cordgrasp/core/kinematics.h"
#include "cordgrasp/core/mesh_io.h"
#include "cordgrasp/core/shapes.h"
#include "cordgrasp/render/png_io.h"
#include "image_stats.h"
#include "test_paths.h"

namespace cordgrasp {
namespace {

constexpr double kColorTol = 1e-12;

// A toy two-finger hand built in code: a box palm, a thumb and a finger of two cylinder
// phalanges each (revolute about y), the finger's distal joint a mimic of its proximal one.
HandModel toy_hand() {
  HandModel hand;
  hand.name = "toy";
  const auto link = [&hand](const std::string& name, Geometry g) {
    Link l;
    l.name = name;
    l.visuals.push_back(g);
    l.collisions.push_back(g);
    hand.links.push_back(l);
    return static_cast<int>(hand.links.size()) - 1;
  };
  Geometry palm;
  palm.kind = Geometry::Kind::kBox;
  palm.box_size_m = Eigen::Vector3d(0.08, 0.02, 0.08);
  link("palm", palm);
  Geometry phalanx;
  phalanx.kind = Geometry::Kind::kCylinder;
  phalanx.radius_m = 0.008;
  phalanx.length_m = 0.04;
  phalanx.X_LG.translation() = Eigen::Vector3d(0, 0, 0.02);
  const auto joint = [&hand](const std::string& name, int parent, int child,
                             const Eigen::Vector3d& p) {
    Joint j;
    j.name = name;
    j.type = JointType::kRevolute;
    j.parent_link = parent;
    j.child_link = child;
    j.X_PJ.translation() = p;
    j.axis = Eigen::Vector3d::UnitY();
    j.lower = -1.0;
    j.upper = 1.5;
    hand.joints.push_back(j);
    hand.links[child].parent_joint = static_cast<int>(hand.joints.size()) - 1;
    return static_cast<int>(hand.joints.size()) - 1;
  };
  const int thumb1 = link("thumb1", phalanx), thumb2 = link("thumb2", phalanx);
  const int finger1 = link("finger1", phalanx), finger2 = link("finger2", phalanx);
  const int jt1 = joint("jt1", 0, thumb1, Eigen::Vector3d(-0.03, 0, 0.04));
  const int jt2 = joint("jt2", thumb1, thumb2, Eigen::Vector3d(0, 0, 0.04));
  const int jf1 = joint("jf1", 0, finger1, Eigen::Vector3d(0.03, 0, 0.04));
  const int jf2 = joint("jf2", finger1, finger2, Eigen::Vector3d(0, 0, 0.04));
  hand.joints[jf2].mimic = Mimic{jf1, 1.0, 0.0};
  hand.actors.push_back(Actor{"finger", {{jf1, 1.0}}});
  hand.actors.push_back(Actor{"thumb", {{jt1, -1.0}, {jt2, -1.0}}});
  hand.thumb_links = {thumb1, thumb2};
  hand.preshape = Eigen::VectorXd::Zero(4);
  return hand;
}

TEST(HandLinkColors, PalmGreyThumbFirstPaletteColourAndMimicFollowsMaster) {
  const HandModel hand = toy_hand();
  const auto c = hand_link_colors(hand);
  ASSERT_EQ(c.size(), 5u);
  EXPECT_NEAR((c[1] - c[2]).norm(), 0.0, kColorTol);  // thumb links share a colour
  EXPECT_NEAR((c[3] - c[4]).norm(), 0.0, kColorTol);  // mimic link coloured like its master
  EXPECT_GT((c[1] - c[3]).norm(), 0.2);               // thumb and finger differ
  // Palm is a dark grey; fingers are saturated.
  EXPECT_NEAR(c[0][0], c[0][1], 0.1);
  EXPECT_LT(c[0].head<3>().maxCoeff(), 0.6);
  EXPECT_GT(c[1].head<3>().maxCoeff() - c[1].head<3>().minCoeff(), 0.3);
  // The thumb takes the first palette colour even though its actor is listed second.
  HandModel swapped = hand;
  std::swap(swapped.actors[0], swapped.actors[1]);
  EXPECT_NEAR((hand_link_colors(swapped)[1] - c[1]).norm(), 0.0, kColorTol);
}

TEST(HandLinkColors, ShippedHandsHaveOneColourPerFinger) {
  for (const char* name : {"cordgrasp_sah", "parallel_gripper"}) {
    SCOPED_TRACE(name);
    const HandModel hand = load_hand(name);
    const auto colors = hand_link_colors(hand);
    const auto fingers = hand_fingers(hand);
    ASSERT_GE(fingers.size(), 2u);
    std::vector<Rgba> finger_colors;
    for (const Finger& f : fingers) {
      for (int l : f.links) EXPECT_NEAR((colors[l] - colors[f.links[0]]).norm(), 0.0, kColorTol);
      for (const Rgba& other : finger_colors) EXPECT_GT((other - colors[f.links[0]]).norm(), 0.2);
      finger_colors.push_back(colors[f.links[0]]);
    }
    const Rgba palm = colors[hand.root_link];
    for (const Rgba& c : finger_colors) EXPECT_GT((c - palm).norm(), 0.2);
  }
}

TEST(ClosingConfiguration, MovesActorJointsTowardTheirClosingLimits) {
  const HandModel hand = load_hand("cordgrasp_sah");
  const Eigen::VectorXd open = closing_configuration(hand, 0.0);
  const Eigen::VectorXd closed = closing_configuration(hand, 1.0);
  EXPECT_TRUE(open.isApprox(clamp_to_limits(hand, apply_couplings(hand, hand.preshape))));
  for (const Actor& a : hand.actors)
    for (const Actor::Entry& e : a.joints)
      EXPECT_DOUBLE_EQ(closed[e.joint], e.direction_speed > 0 ? hand.joints[e.joint].upper
                                                              : hand.joints[e.joint].lower);
  const int distal = find_joint(hand, "index_distal");  // coupled to index_middle
  ASSERT_GE(distal, 0);
  EXPECT_DOUBLE_EQ(closed[distal], closed[find_joint(hand, "index_middle")]);
}

TEST(MakeHandMeshes, VisualOpaqueCollisionTranslucentOverIt) {
  const HandModel hand = toy_hand();
  EXPECT_EQ(make_hand_meshes(hand).parts.size(), 5u);
  HandStyle both;
  both.collision = true;
  const HandMeshes m = make_hand_meshes(hand, both);
  ASSERT_EQ(m.parts.size(), 10u);
  int translucent = 0;
  for (const auto& p : m.parts) translucent += p.rgba[3] < 1.0;
  EXPECT_EQ(translucent, 5);
  HandStyle collision_only;
  collision_only.visual = false;
  collision_only.collision = true;
  for (const auto& p : make_hand_meshes(hand, collision_only).parts) EXPECT_EQ(p.rgba[3], 1.0);
}

TEST(AddHand, ThrowsWhenLinkPosesDoNotMatch) {
  const HandModel hand = toy_hand();
  Scene scene;
  EXPECT_THROW(add_hand(scene, make_hand_meshes(hand), {Eigen::Isometry3d::Identity()}),
               std::invalid_argument);
}

using test::pixels_of_hue;

TEST(HandScene, PictureShowsHandAndObjectColours) {
  const HandModel hand = toy_hand();
  Eigen::VectorXd q(4);
  q << -0.4, -0.4, 0.5, 0.5;
  const auto X_WL = link_poses(hand, apply_couplings(hand, q));
  Scene scene;
  add_object(scene, std::make_shared<const Mesh>(make_sphere_mesh(0.025)),
             Eigen::Isometry3d(Eigen::Translation3d(0, 0, 0.1)));
  add_hand(scene, make_hand_meshes(hand), X_WL);
  scene.ground = Ground::kShadow;
  Renderer renderer;
  RenderParams params;
  params.width_px = 320;
  params.height_px = 240;
  params.supersample = 2;
  const Image image = renderer.render(scene, params);
  test::save_for_inspection(image, "hand_scene");
  const auto colors = hand_link_colors(hand);
  EXPECT_GT(pixels_of_hue(image, colors[1]), 100);  // thumb
  EXPECT_GT(pixels_of_hue(image, colors[3]), 100);  // finger
  const int grey = test::select_pixels(image, [](int r, int g, int b) {
                     return std::abs(r - g) < 4 && std::abs(g - b) < 4 && r > 90 && r < 235;
                   }).count;
  EXPECT_GT(grey, 500);  // the object (and the palm's greys)
}

TEST(RegionOverlay, DrawsEveryCordAndThreeMarkedPoints) {
  GraspRegion region;
  region.n = 1;
  for (int i = -1; i <= 1; ++i)
    region.front_cords.push_back(
        {{0.05, 0.01 * i, 0.0}, {0.0, 0.01 * i, 0.05}, {-0.05, 0.01 * i, 0}});
  region.p1 = Eigen::Vector3d(0, 0, 0.06);
  region.p_l = Eigen::Vector3d(-0.05, 0, 0);
  region.p_r = Eigen::Vector3d(0.05, 0, 0);
  Scene scene;
  add_region_overlay(scene, region, Eigen::Isometry3d(Eigen::Translation3d(1, 0, 0)), 0.05);
  ASSERT_EQ(scene.polylines.size(), 3u);
  EXPECT_GT(scene.polylines[1].width_px, scene.polylines[0].width_px);  // the seed cord
  EXPECT_TRUE(scene.polylines[0].p_W[0].isApprox(Eigen::Vector3d(1.05, -0.01, 0.0)));
  ASSERT_EQ(scene.points.size(), 3u);
  EXPECT_TRUE(scene.points[1].p_W.isApprox(Eigen::Vector3d(0.95, 0, 0)));
}

TEST(ContactOverlay, ArrowsAlongNormalsOrFrictionConesOfAngleAtanMu) {
  const std::vector<Contact> contacts = {{1, {0.02, 0, 0}, {1, 0, 0}},
                                         {2, {-0.02, 0, 0}, {-1, 0, 0}}};
  Eigen::Isometry3d X_WO = Eigen::Isometry3d::Identity();
  X_WO.linear() = Eigen::AngleAxisd(M_PI / 2, Eigen::Vector3d::UnitZ()).toRotationMatrix();
  Scene arrows;
  add_contact_overlay(arrows, contacts, X_WO, 0.05);
  ASSERT_EQ(arrows.arrows.size(), 2u);
  EXPECT_EQ(arrows.points.size(), 2u);
  EXPECT_TRUE(arrows.arrows[0].direction_W.normalized().isApprox(Eigen::Vector3d::UnitY()));
  OverlayStyle style;
  style.friction_cones = true;
  style.friction_coefficient = 0.4;
  Scene cones;
  add_contact_overlay(cones, contacts, X_WO, 0.05, style);
  ASSERT_EQ(cones.cones.size(), 2u);
  EXPECT_TRUE(cones.arrows.empty());
  EXPECT_NEAR(cones.cones[1].half_angle_rad, std::atan(0.4), 1e-12);
  EXPECT_TRUE(cones.cones[1].apex_W.isApprox(Eigen::Vector3d(0, -0.02, 0)));
}

TEST(GraspScene, HasObjectHandAtGraspPoseAndOverlays) {
  const HandModel hand = toy_hand();
  Grasp grasp;
  grasp.X_OB = Eigen::Isometry3d(Eigen::Translation3d(0.0, 0.0, -0.1));
  grasp.q = Eigen::VectorXd::Constant(4, 0.3);
  grasp.contacts = {{2, {0.02, 0, 0}, {1, 0, 0}}, {4, {-0.02, 0, 0}, {-1, 0, 0}}};
  GraspRegion region;
  region.n = 1;
  region.front_cords.assign(3, {{0.02, 0, 0}, {0, 0, 0.02}, {-0.02, 0, 0}});
  const auto object = std::make_shared<const Mesh>(make_sphere_mesh(0.02));
  const Scene scene =
      grasp_scene(hand, make_hand_meshes(hand), object, grasp, &region, OverlayStyle{});
  ASSERT_EQ(scene.meshes.size(), 1u + 5u);
  EXPECT_EQ(scene.meshes[0].mesh, object);
  // The palm (link 0, the root) sits at X_OB; finger links follow FK with couplings applied.
  const auto X_WL = link_poses(hand, apply_couplings(hand, grasp.q), grasp.X_OB);
  EXPECT_TRUE(scene.meshes[1].X_WM.isApprox(grasp.X_OB));
  EXPECT_TRUE(scene.meshes[5].X_WM.isApprox(X_WL[4] * hand.links[4].visuals[0].X_LG));
  EXPECT_EQ(scene.polylines.size(), 3u);
  EXPECT_EQ(scene.points.size(), 3u + 2u);
  EXPECT_EQ(scene.arrows.size(), 2u);
  EXPECT_THROW(grasp_scene(hand, make_hand_meshes(hand), object, Grasp{}), std::invalid_argument);
}

TEST(RenderSnapshots, OneCameraForAllFramesSoStillThingsStayStill) {
  const HandModel hand = toy_hand();
  const auto X_WL = link_poses(hand, Eigen::VectorXd::Zero(4));
  std::vector<SnapshotFrame> frames;
  for (int i = 0; i < 3; ++i) {
    SnapshotFrame f;
    f.X_WL = X_WL;                                                          // the hand stays put
    f.X_WO = Eigen::Isometry3d(Eigen::Translation3d(0.12, 0.0, 0.03 * i));  // object rises
    frames.push_back(f);
  }
  Renderer renderer;
  RenderParams params;
  params.width_px = 240;
  params.height_px = 180;
  params.supersample = 1;
  params.view.view = View::kFront;
  const auto images = render_snapshots(
      renderer, hand, std::make_shared<const Mesh>(make_box_mesh(Eigen::Vector3d::Constant(0.04))),
      frames, params);
  ASSERT_EQ(images.size(), 3u);
  for (int i = 0; i < 3; ++i) test::save_for_inspection(images[i], "snapshot" + std::to_string(i));
  const Rgba palm = hand_link_colors(hand)[0];
  std::vector<test::PixelSet> hand_px, object_px;
  for (const Image& image : images) {
    hand_px.push_back(test::select_pixels(image, [&](int r, int g, int b) {
      const Eigen::Vector3d c(r, g, b);
      return c.minCoeff() < 235 && c.normalized().dot(palm.head<3>().normalized()) > 0.9995 &&
             b > r + 3;  // the palm's bluish grey, not the neutral object grey
    }));
    object_px.push_back(test::select_pixels(image, [](int r, int g, int b) {
      return std::abs(r - g) <= 1 && std::abs(g - b) <= 1 && r > 60 && r < 235;
    }));
  }
  ASSERT_GT(hand_px[0].count, 100);
  for (int i = 1; i < 3; ++i) {
    EXPECT_NEAR(hand_px[i].centroid.x(), hand_px[0].centroid.x(), 0.5);
    EXPECT_NEAR(hand_px[i].centroid.y(), hand_px[0].centroid.y(), 0.5);
    EXPECT_LT(object_px[i].centroid.y(), object_px[i - 1].centroid.y() - 3.0);  // rises
  }
}

}  // namespace
}  // namespace cordgrasp

namespace cordgrasp {
namespace {

// The default hand placed by hand around the shipped mug (a synthetic grasp, not a plan):
// the picture shows both the fingers' colours and the object's grey.
TEST(GraspScene, DefaultHandOnMugShowsHandAndObjectColours) {
  const HandModel hand = load_hand(default_hand_name());
  const auto mug =
      std::make_shared<const Mesh>(load_mesh(test::source_dir() + "/assets/objects/mug.obj"));
  Grasp grasp;
  grasp.q = closing_configuration(hand, 0.4);
  Eigen::Isometry3d X_OG = Eigen::Isometry3d::Identity();  // approach along +y, at mid height
  X_OG.linear() << 1, 0, 0, 0, 0, 1, 0, -1, 0;
  X_OG.translation() = Eigen::Vector3d(0.0, -0.06, 0.05);
  grasp.X_OG = X_OG;
  grasp.X_OB = root_pose_for_gcp(hand, grasp.q, X_OG);
  Scene scene = grasp_scene(hand, make_hand_meshes(hand), mug, grasp);
  scene.ground = Ground::kShadow;
  Renderer renderer;
  RenderParams params;
  params.width_px = 320;
  params.height_px = 240;
  const Image image = renderer.render(scene, params);
  test::save_for_inspection(image, "default_hand_on_mug");
  const auto colors = hand_link_colors(hand);
  int finger_px = 0;
  for (const Finger& f : hand_fingers(hand)) finger_px += pixels_of_hue(image, colors[f.links[0]]);
  EXPECT_GT(finger_px, 300);
  const Eigen::Vector3d grey = object_color().head<3>();
  const int object_px = test::select_pixels(image, [](int r, int g, int b) {
                          return std::abs(r - g) <= 2 && std::abs(g - b) <= 2 && r > 60 && r < 240;
                        }).count;
  EXPECT_GT(object_px, 1000) << grey.transpose();
}

TEST(WriteSnapshots, OnePngPerFrameNamedByStemAndPhase) {
  namespace fs = std::filesystem;
  const fs::path dir = fs::temp_directory_path() / "cordgrasp_write_snapshots_test";
  fs::remove_all(dir);
  fs::create_directories(dir);
  const HandModel hand = toy_hand();
  const auto X_WL = link_poses(hand, Eigen::VectorXd::Zero(4));
  std::vector<SnapshotFrame> frames(3);
  frames[0].X_WL = frames[1].X_WL = frames[2].X_WL = X_WL;
  frames[0].name = "settled";
  frames[2].name = "gravity6 -x";
  Renderer renderer;
  RenderParams params;
  params.width_px = 64;
  params.height_px = 48;
  params.supersample = 1;
  const auto paths =
      write_snapshots(renderer, hand, nullptr, frames, dir.string(), "grasp3", params);
  ASSERT_EQ(paths.size(), 3u);
  EXPECT_EQ(fs::path(paths[0]).filename(), "grasp3_settled.png");
  EXPECT_EQ(fs::path(paths[1]).filename(), "grasp3_1.png");
  EXPECT_EQ(fs::path(paths[2]).filename(), "grasp3_gravity6_-x.png");
  for (const auto& p : paths) {
    const Image image = read_png(p);
    EXPECT_EQ(image.width, 64);
    EXPECT_EQ(image.height, 48);
  }
  EXPECT_THROW(
      write_snapshots(renderer, hand, nullptr, frames, (dir / "missing").string(), "g", params),
      InputError);
  fs::remove_all(dir);
}

}  // namespace
}  // namespace cordgrasp
