#pragma once
// Reads the object rows of ../shared/data/MANIFEST.md (triangle counts, bbox, topology as
// measured with assimp when the data was staged), for dataset tests.
#include <Eigen/Core>
#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "test_paths.h"

namespace cordgrasp::test {

/// One row of the MANIFEST's objects table.
struct ManifestObject {
  std::string name;
  std::string file;   ///< relative to the shared data folder, e.g. objects/kit/Dog.obj
  int triangles = 0;  ///< as counted by `assimp info`
  Eigen::Vector3d size_m = Eigen::Vector3d::Zero();  ///< bbox extents, rounded to 1 mm
  bool watertight = false;
  int boundary_edges = 0;
  int non_manifold_edges = 0;
  int components = 0;
  int euler_characteristic = 0;
};

/// Splits a Markdown table row into trimmed cells.
inline std::vector<std::string> table_cells(const std::string& line) {
  std::vector<std::string> cells;
  std::stringstream in(line);
  std::string cell;
  std::getline(in, cell, '|');  // before the first bar
  while (std::getline(in, cell, '|')) {
    const auto b = cell.find_first_not_of(' '), e = cell.find_last_not_of(' ');
    cells.push_back(b == std::string::npos ? "" : cell.substr(b, e - b + 1));
  }
  return cells;
}

/// Object rows of MANIFEST.md; empty when the shared data folder is absent.
/// Adds a gtest failure for a row it cannot parse.
inline std::vector<ManifestObject> manifest_objects() {
  std::vector<ManifestObject> out;
  if (shared_data_dir().empty()) return out;
  std::ifstream in(shared_data_dir() + "/MANIFEST.md");
  const std::regex watertight(R"(watertight, (\d+) component\(s\), Euler char\. (-?\d+))");
  const std::regex open(R"(open: (\d+) boundary / (\d+) non-manifold edges, )"
                        R"((\d+) component\(s\), Euler char\. (-?\d+))");
  const std::regex bbox(R"(([\d.]+) x ([\d.]+) x ([\d.]+))");
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind("| ", 0) != 0 || line.find("`objects/") == std::string::npos) continue;
    const std::vector<std::string> c = table_cells(line);
    if (c.size() < 11) {
      ADD_FAILURE() << "MANIFEST object row with " << c.size() << " cells: " << line;
      continue;
    }
    ManifestObject o;
    o.name = c[0];
    o.file = c[1].substr(1, c[1].size() - 2);  // strip the backquotes
    o.triangles = std::stoi(c[8]);
    std::smatch m;
    if (std::regex_search(c[9], m, bbox))
      o.size_m = Eigen::Vector3d(std::stod(m[1]), std::stod(m[2]), std::stod(m[3]));
    if (std::regex_search(c[10], m, watertight)) {
      o.watertight = true;
      o.components = std::stoi(m[1]);
      o.euler_characteristic = std::stoi(m[2]);
    } else if (std::regex_search(c[10], m, open)) {
      o.boundary_edges = std::stoi(m[1]);
      o.non_manifold_edges = std::stoi(m[2]);
      o.components = std::stoi(m[3]);
      o.euler_characteristic = std::stoi(m[4]);
    } else {
      ADD_FAILURE() << "MANIFEST topology not understood: " << c[10];
      continue;
    }
    out.push_back(o);
  }
  return out;
}

}  // namespace cordgrasp::test
