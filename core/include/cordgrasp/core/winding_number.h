#pragma once
#include <Eigen/Core>
#include <memory>
#include <vector>

#include "cordgrasp/core/mesh_bvh.h"

namespace cordgrasp {

/// Generalized winding numbers of a triangle soup (Jacobson, Kavan, Sorkine-Hornung 2013) over
/// its BVH: the triangles of a node seen from afar count as one dipole (Barill et al., "Fast
/// winding numbers for soups and clouds", 2018, first order). 1 inside a closed surface wound
/// outward (2 where two such components overlap), 0 outside, fractional near holes.
struct WindingNumberTree {
  std::shared_ptr<const MeshBvh> bvh;
  std::vector<Eigen::Vector3d> area_normal;  ///< per node: Σ area · unit normal [m²]
  std::vector<Eigen::Vector3d> centroid;     ///< per node: area-weighted triangle centroid [m]
};

/// The dipoles of every node of `bvh` (O(triangles)).
WindingNumberTree build_winding_number_tree(std::shared_ptr<const MeshBvh> bvh);

/// Winding number of the tree's surface about `p`: exact (solid angles, van Oosterom and
/// Strackee) for the triangles of nodes whose bounding sphere is within 3 radii of `p`,
/// dipoles beyond (absolute error a few hundredths).
double winding_number(const WindingNumberTree& tree, const Eigen::Vector3d& p);

}  // namespace cordgrasp
