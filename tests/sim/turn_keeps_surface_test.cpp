// turn_keeps_surface: the turns the fingers cannot tell from no turn (a sphere about its centre,
// a cylinder about its axis, a square box by a quarter turn) and the ones they can.
#include "cordgrasp/sim/turn_keeps_surface.h"

#include <gtest/gtest.h>

#include <Eigen/Geometry>
#include <cmath>
#include <random>
#include <stdexcept>

#include "cordgrasp/core/shapes.h"

namespace cordgrasp {
namespace {

constexpr double kTolerance_m = 1e-3;              ///< the contact distance of the physics' default
constexpr double kTurn_rad = 20.0 * M_PI / 180.0;  ///< past the held limit (15°)

Eigen::Matrix3d turn(double angle_rad, const Eigen::Vector3d& axis) {
  return Eigen::AngleAxisd(angle_rad, axis.normalized()).toRotationMatrix();
}

TEST(TurnKeepsSurface, ASphereTurnedAboutItsCentreAnyWay) {
  Mesh sphere = make_sphere_mesh(0.03);
  for (Eigen::Vector3d& v : sphere.vertices) v += Eigen::Vector3d(0.1, -0.02, 0.05);  // off O
  const ObjectSurface& s = object_surface(sphere);
  std::mt19937 rng(7);
  std::normal_distribution<double> n(0.0, 1.0);
  for (int k = 0; k < 20; ++k) {
    const Eigen::Vector3d axis(n(rng), n(rng), n(rng));
    EXPECT_TRUE(turn_keeps_surface(s, turn(kTurn_rad + 0.1 * k, axis), kTolerance_m))
        << "turn " << k;
  }
}

TEST(TurnKeepsSurface, AHemisphereOnlyAboutItsAxis) {
  // The upper half of a sphere: its centroid lies on z, half a radius up.
  const Mesh sphere = make_sphere_mesh(0.03);
  Mesh dome;
  dome.vertices = sphere.vertices;
  for (const Eigen::Vector3i& t : sphere.triangles)
    if (sphere.vertices[t[0]].z() >= 0 && sphere.vertices[t[1]].z() >= 0 &&
        sphere.vertices[t[2]].z() >= 0)
      dome.triangles.push_back(t);
  const ObjectSurface& s = object_surface(dome);
  EXPECT_TRUE(turn_keeps_surface(s, turn(kTurn_rad, Eigen::Vector3d::UnitZ()), kTolerance_m));
  EXPECT_FALSE(turn_keeps_surface(s, turn(kTurn_rad, Eigen::Vector3d::UnitX()), kTolerance_m));
}

TEST(TurnKeepsSurface, ACylinderOnlyAboutItsAxis) {
  const Mesh cylinder = make_cylinder_mesh(0.02, 0.1);  // along z
  const ObjectSurface& s = object_surface(cylinder);
  EXPECT_TRUE(turn_keeps_surface(s, turn(kTurn_rad, Eigen::Vector3d::UnitZ()), kTolerance_m));
  EXPECT_FALSE(turn_keeps_surface(s, turn(kTurn_rad, Eigen::Vector3d::UnitX()), kTolerance_m));
  // A few degrees about a cross axis already move its ends by millimetres.
  EXPECT_FALSE(
      turn_keeps_surface(s, turn(3.0 * M_PI / 180.0, Eigen::Vector3d::UnitY()), kTolerance_m));
}

TEST(TurnKeepsSurface, ABoxOnlyByTheQuarterTurnsOfItsSquareSection) {
  const Mesh box = make_box_mesh(Eigen::Vector3d(0.05, 0.05, 0.08));
  const ObjectSurface& s = object_surface(box);
  EXPECT_FALSE(turn_keeps_surface(s, turn(kTurn_rad, Eigen::Vector3d::UnitZ()), kTolerance_m));
  EXPECT_TRUE(turn_keeps_surface(s, turn(M_PI / 2, Eigen::Vector3d::UnitZ()), kTolerance_m));
  EXPECT_FALSE(turn_keeps_surface(s, turn(M_PI / 2, Eigen::Vector3d::UnitX()), kTolerance_m));
  EXPECT_TRUE(turn_keeps_surface(s, Eigen::Matrix3d::Identity(), kTolerance_m));
}

TEST(TurnKeepsSurface, RefusesAMeshWithoutTriangles) {
  Mesh empty;
  empty.name = "empty";
  EXPECT_THROW(object_surface(empty), std::invalid_argument);
}

}  // namespace
}  // namespace cordgrasp
