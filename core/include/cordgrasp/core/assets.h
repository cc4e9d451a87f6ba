#pragma once
// Where the project's own assets (hands built from primitives, generated objects) live.
#include <string>

namespace cordgrasp {

/// The assets folder: $CORDGRASP_ASSETS_DIR when set, else the source tree's assets/
/// (compile definition CORDGRASP_ASSETS_DIR).
std::string assets_dir();

/// <assets>/objects: the shipped objects as OBJ in meters (`cordgrasp generate-objects`).
std::string shipped_objects_dir();

/// Resolves `--object` text: an existing file path as is, else the name of a shipped object
/// (<assets>/objects/<name>.obj, e.g. "mug").
/// @throws InputError naming the text and the shipped names when nothing matches.
std::string resolve_object_path(const std::string& name_or_path);

}  // namespace cordgrasp
