#include "cordgrasp/core/mesh_properties.h"

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <array>
#include <cmath>
#include <numeric>

namespace cordgrasp {

Aabb mesh_bounds(const Mesh& mesh) {
  Aabb box;
  if (mesh.vertices.empty()) return box;
  box.min = box.max = mesh.vertices.front();
  for (const auto& v : mesh.vertices) {
    box.min = box.min.cwiseMin(v);
    box.max = box.max.cwiseMax(v);
  }
  return box;
}

Eigen::Vector3d vertex_mean(const Mesh& mesh) {
  Eigen::Vector3d sum = Eigen::Vector3d::Zero();
  for (const auto& v : mesh.vertices) sum += v;
  return mesh.vertices.empty() ? sum : Eigen::Vector3d(sum / double(mesh.vertices.size()));
}

std::vector<Eigen::Vector3d> referenced_vertices(const Mesh& mesh) {
  std::vector<char> used(mesh.vertices.size(), 0);
  for (const auto& t : mesh.triangles)
    for (int k = 0; k < 3; ++k) used[static_cast<size_t>(t[k])] = 1;
  std::vector<Eigen::Vector3d> out;
  for (size_t i = 0; i < mesh.vertices.size(); ++i)
    if (used[i]) out.push_back(mesh.vertices[i]);
  return out;
}

double bounding_radius(const Mesh& mesh, const Eigen::Vector3d& center) {
  double r2 = 0.0;
  for (const auto& v : mesh.vertices) r2 = std::max(r2, (v - center).squaredNorm());
  return std::sqrt(r2);
}

double surface_area(const Mesh& mesh) {
  double area = 0.0;
  for (const auto& t : mesh.triangles) {
    const auto& a = mesh.vertices[t[0]];
    area += 0.5 * (mesh.vertices[t[1]] - a).cross(mesh.vertices[t[2]] - a).norm();
  }
  return area;
}

PrincipalAxes principal_axes(const Mesh& mesh) {
  PrincipalAxes out;
  Eigen::Matrix3d second = Eigen::Matrix3d::Zero();  // Σ ∫ x xᵀ dA
  Eigen::Vector3d first = Eigen::Vector3d::Zero();   // Σ ∫ x dA
  double area_total = 0.0;
  for (const auto& t : mesh.triangles) {
    const Eigen::Vector3d& a = mesh.vertices[t[0]];
    const Eigen::Vector3d& b = mesh.vertices[t[1]];
    const Eigen::Vector3d& c = mesh.vertices[t[2]];
    const double area = 0.5 * (b - a).cross(c - a).norm();
    if (area <= 0.0) continue;
    const Eigen::Vector3d s = a + b + c;
    second += (area / 12.0) * (s * s.transpose() + a * a.transpose() + b * b.transpose() +
                               c * c.transpose());
    first += (area / 3.0) * s;
    area_total += area;
  }
  out.area_m2 = area_total;
  if (area_total <= 0.0) return out;
  out.centroid = first / area_total;
  const Eigen::Matrix3d sigma = second / area_total - out.centroid * out.centroid.transpose();
  Eigen::SelfAdjointEigenSolver<Eigen::Matrix3d> eig(sigma);
  // Eigen returns ascending eigenvalues; store descending.
  for (int k = 0; k < 3; ++k) {
    out.variances[k] = eig.eigenvalues()[2 - k];
    out.axes.col(k) = eig.eigenvectors().col(2 - k).normalized();
  }
  // Deterministic sign: largest |component| of each axis positive; right-handed frame.
  for (int k = 0; k < 2; ++k) {
    Eigen::Index i;
    out.axes.col(k).cwiseAbs().maxCoeff(&i);
    if (out.axes(i, k) < 0) out.axes.col(k) *= -1.0;
  }
  out.axes.col(2) = out.axes.col(0).cross(out.axes.col(1));
  return out;
}

}  // namespace cordgrasp
