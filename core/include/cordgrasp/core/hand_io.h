#pragma once
#include <string>

#include "cordgrasp/core/hand_model.h"

namespace cordgrasp {

/// Directory of the shipped hands: <assets>/hands, <assets> = $CORDGRASP_ASSETS_DIR when set, else
/// the source tree's assets/ (compile definition CORDGRASP_ASSETS_DIR).
std::string shipped_hands_dir();

/// Resolves `--hand` text: an existing description file path, a hand folder holding
/// <folder name>.yaml, or the name of a shipped hand (assets/hands/<name>.yaml or
/// assets/hands/<name>/<name>.yaml).
/// @throws InputError naming the text when nothing matches.
std::string resolve_hand_path(const std::string& name_or_path);

/// Name of the default hand shipped in assets/hands.
const char* default_hand_name();

/// Loads a hand description (YAML, format in docs/hand-description.md) and the URDF it names
/// (parsed with urdfdom), with all collision/visual meshes in meters. Missing, placeholder or
/// impossible inertials are replaced (Inertial::substituted; one warning per hand on stderr).
/// @throws InputError naming the file and the problem (missing URDF or mesh, GCP link not found,
///         preshape naming an unknown joint, inverted limits, ...).
HandModel load_hand(const std::string& name_or_path);

}  // namespace cordgrasp
