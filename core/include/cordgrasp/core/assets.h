#pragma once
// Where the project's own assets (shipped hand descriptions, generated objects) live, and how
// --hand / --object text names them.
#include <string>

namespace cordgrasp {

/// The assets folder: $CORDGRASP_ASSETS_DIR when set; else, for programs and modules of the
/// build tree, the source tree's assets/; else share/cordgrasp of the installation holding the
/// running program or module (found relative to it), then of the configured install prefix.
std::string assets_dir();

/// <assets>/objects: the shipped objects as OBJ in meters (`cordgrasp generate-objects`).
std::string shipped_objects_dir();

/// Resolves `--object` text: an existing file path as is, else the name of a shipped object
/// (<assets>/objects/<name>.obj, e.g. "mug").
/// @throws InputError naming the text and the shipped names when nothing matches.
std::string resolve_object_path(const std::string& name_or_path);

/// Directory of the shipped hands: <assets>/hands.
std::string shipped_hands_dir();

/// Resolves `--hand` text: an existing description file path, a hand folder holding
/// <folder name>.yaml, or the name of a shipped hand (assets/hands/<name>.yaml or
/// assets/hands/<name>/<name>.yaml).
/// @throws InputError naming the text when nothing matches.
std::string resolve_hand_path(const std::string& name_or_path);

/// Name of the default hand shipped in assets/hands.
const char* default_hand_name();

}  // namespace cordgrasp
