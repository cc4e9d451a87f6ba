#pragma once
#include <Eigen/Core>
#include <string>
#include <vector>

#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

// The shipped test objects (assets/objects, written by `cordgrasp generate-objects`). All are
// in meters, z up, resting on z = 0 and centred on the z axis (the pliers lie flat, handles
// toward −x). Sizes suit a Schunk-SAH-sized hand: each has a part 3–15 cm across. Multi-part
// objects are soups of closed parts that may overlap. Coordinates are rounded to 0.1 µm.

struct BoxObjectParams {
  Eigen::Vector3d size_m{0.05, 0.05, 0.08};  ///< full extents [m]
  double max_cell_m = 0.01;                  ///< grid cell size on the faces [m]
};
/// Closed box (face grids of ≤ 1 cm cells).
Mesh make_box_object(const BoxObjectParams& p = {});

struct CylinderObjectParams {
  double diameter_m = 0.035;  ///< [m]
  double length_m = 0.25;     ///< along z [m]
};
/// Closed long cylinder standing along z (the paper's Fig. 11 object).
Mesh make_long_cylinder_object(const CylinderObjectParams& p = {});

struct SphereObjectParams {
  double diameter_m = 0.06;  ///< [m]
};
/// Closed UV sphere.
Mesh make_sphere_object(const SphereObjectParams& p = {});

struct BottleObjectParams {
  double diameter_m = 0.07;  ///< body diameter [m]
  double height_m = 0.22;    ///< including the cap [m]
};
/// Closed bottle: body, shoulder, neck and cap, revolved.
Mesh make_bottle_object(const BottleObjectParams& p = {});

struct MugObjectParams {
  double outer_diameter_m = 0.08;   ///< [m]
  double height_m = 0.095;          ///< [m]
  double wall_m = 0.004;            ///< side wall thickness [m]
  double bottom_m = 0.006;          ///< bottom thickness [m]
  double handle_reach_m = 0.028;    ///< handle centre line beyond the wall, along +x [m]
  double handle_radius_m = 0.0055;  ///< handle tube radius [m]
};
/// Hollow mug (closed revolved shell) and a closed D handle tube on +x; the default object.
Mesh make_mug_object(const MugObjectParams& p = {});

struct WineGlassObjectParams {
  double bowl_diameter_m = 0.084;  ///< widest part of the bowl [m]
  double height_m = 0.2;           ///< [m]
};
/// Closed wine glass: foot, stem and a hollow bowl with 2 mm walls, revolved.
Mesh make_wine_glass_object(const WineGlassObjectParams& p = {});

struct TorusObjectParams {
  double major_radius_m = 0.04;   ///< ring radius [m]
  double minor_radius_m = 0.012;  ///< tube radius [m]
};
/// Closed torus lying flat (axis z).
Mesh make_torus_object(const TorusObjectParams& p = {});

struct PliersObjectParams {
  double length_m = 0.2;         ///< jaw tip to handle ends, along x [m]
  double handle_span_m = 0.066;  ///< distance between the handle ends' centre lines [m]
};
/// Two-handled pliers-like tool lying flat: pivot, two jaws, two handles with grips (7 closed
/// parts).
Mesh make_pliers_object(const PliersObjectParams& p = {});

struct KettleObjectParams {
  double base_diameter_m = 0.12;  ///< body diameter at the bottom [m]
  double height_m = 0.155;        ///< body and lid knob [m]
};
/// Kettle-like closed body with a D-shaped side handle on −x and a tapered spout on +x.
Mesh make_kettle_object(const KettleObjectParams& p = {});

/// Deliberately defective 6 cm cube: top face missing (open), a fin sharing one box edge with
/// two box faces (one non-manifold edge) and three flipped faces.
Mesh make_defective_object();

/// Names of the shipped objects in generation order: box, long_cylinder, sphere, bottle, mug,
/// wine_glass, torus, pliers, kettle, defective.
const std::vector<std::string>& shipped_object_names();

/// Name of the default object ("mug").
std::string default_object_name();

/// The shipped object `name` with default parameters. @throws std::invalid_argument if unknown.
Mesh make_object_mesh(const std::string& name);

}  // namespace cordgrasp
