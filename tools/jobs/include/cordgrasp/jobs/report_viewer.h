#pragma once
// The files of report.html's 3D view: three.js (Debian's libjs-three, its non-module build,
// which loads from file://) copied beside the report, and each grasp as a script holding its
// glTF binary (browsers refuse to fetch a file:// URL, but run a script from one).
#include <string>

#include "cordgrasp/core/grasp.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// Where the viewer's scripts and their licence come from.
struct ViewerSources {
  std::string three_js;           ///< three.js itself (three.min.js)
  std::string gltf_loader_js;     ///< THREE.GLTFLoader (examples/js/loaders/GLTFLoader.js)
  std::string orbit_controls_js;  ///< THREE.OrbitControls (examples/js/controls/OrbitControls.js)
  std::string licence;            ///< the package's copyright file, copied as the licence
};

/// The files CMake found at configure time (CORDGRASP_THREE_DIR, CORDGRASP_THREE_LICENCE).
ViewerSources default_viewer_sources();

/// Folder of the copied viewer files, relative to the report.
inline constexpr const char* kViewerDir = "viewer";

/// Copies the viewer's scripts and licence into out_dir/viewer/ (three.min.js,
/// GLTFLoader.js, OrbitControls.js, copyright: the licence). @throws InputError naming a source
/// file that is missing or a file that cannot be written.
void write_viewer_scripts(const std::string& out_dir,
                          const ViewerSources& sources = default_viewer_sources());

/// Writes out_dir/<name>.glb (the posed hand and the object, write_grasp_mesh's glTF binary)
/// and out_dir/<name>.glb.js, a script that stores the same bytes in base64 as
/// `window.cordgraspModels["<name>"]` (ReportViewer::models).
/// @throws InputError naming a file that cannot be written.
void write_grasp_model_script(const std::string& out_dir, const std::string& name,
                              const HandModel& hand, const Grasp& grasp, const Mesh& object);

}  // namespace cordgrasp
