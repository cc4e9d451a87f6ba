#pragma once
// Drafting a hand description from a URDF alone (docs/hand-description.md, "Drafting a
// description"): fingers, closing joints and signs, thumb, palm normal, GCP, preshape.
#include <functional>
#include <memory>
#include <string>
#include <vector>

#include "cordgrasp/core/hand_collider.h"
#include "cordgrasp/core/hand_description.h"
#include "cordgrasp/core/hand_model.h"
#include "cordgrasp/core/mesh.h"

namespace cordgrasp {

/// One guess of the draft and how sure it is.
struct DraftGuess {
  std::string what;         ///< "thumb", "palm normal", "actor index", ...
  std::string value;        ///< the guess, as text
  double confidence = 0.0;  ///< 0 (a coin toss) .. 1 (sure)
  std::string why;          ///< the evidence, one short phrase
};

/// A drafted description: the hand as it would load, its YAML and what was guessed.
struct HandDraft {
  HandModel hand;                     ///< URDF plus the drafted description
  std::string yaml;                   ///< the description file (format 1)
  std::vector<DraftGuess> guesses;    ///< one per guess, in YAML order
  std::vector<std::string> problems;  ///< check_hand_conventions of the draft (empty: all hold)
};

/// Makes a collider for a hand and an object (the commands pass make_bullet_hand_collider).
using MakeCollider =
    std::function<std::unique_ptr<HandObjectCollider>(const HandModel&, const Mesh&)>;

/// Drafts a hand description for the URDF at `urdf_path`, to be written to `out_path` (the
/// YAML's `urdf:` is relative to its directory). Fingers are the chains below the palm that end
/// in one moving leaf; a joint closes its finger when it moves the fingertip mostly along the
/// palm normal (the thumb: towards the other fingertips; opposed digits: towards where the
/// fingertips meet), with that sign; the thumb is the finger farthest from the others (or, when
/// that is ambiguous, the one closing most against them); the palm normal is the fingers'
/// flexion direction, or for digits closing towards each other across the palm the direction
/// from their roots to where their fingertips meet; the GCP lies between the thumb tip and the
/// other fingertips with +z along the palm normal. With `make_collider` and three or more
/// digits, that GCP and four places shifted sideways from it (along its x and y by 15 % of the
/// palm width) are tried by planning spheres and cylinders of three sizes for the palm width
/// (on up to `threads` threads; the result does not depend on them); a shifted place that
/// finds clearly more force-closure grasps (1.25 times and 3 more) replaces the drafted one.
/// Without it, no planning is done.
/// @throws InputError as load_hand for the URDF, or when no finger is found.
HandDraft draft_hand_description(const std::string& urdf_path, const std::string& out_path,
                                 const HandLoadOptions& options = {},
                                 const MakeCollider& make_collider = {}, int threads = 1);

}  // namespace cordgrasp
