// `cordgrasp hand init`: drafts a hand description from a URDF (draft_hand_description) and
// writes it. See docs/hand-description.md, "Drafting a description".
#include <algorithm>
#include <cstdio>
#include <memory>
#include <string>
#include <thread>

#include "commands.h"
#include "cordgrasp/collision/bullet_hand_collider.h"
#include "cordgrasp/core/atomic_file.h"
#include "cordgrasp/core/draft_hand_description.h"
#include "options.h"

namespace cordgrasp::cli {
namespace {

struct HandInitOptions {
  std::string urdf;
  std::string out;
  HandLoadOptions hand_load;  ///< --package-path
};

void run_hand_init(const HandInitOptions& opt) {
  std::fprintf(stderr, "hand init: drafting %s (test planning of the GCP's place: seconds)\n",
               opt.urdf.c_str());
  const auto make_collider = [](const HandModel& hand, const Mesh& object) {
    return make_bullet_hand_collider(hand, object);
  };
  const int threads = int(std::max(1u, std::thread::hardware_concurrency()));
  const HandDraft draft =
      draft_hand_description(opt.urdf, opt.out, opt.hand_load, make_collider, threads);
  write_file_atomically(opt.out, draft.yaml);
  std::printf("hand init: %s -> %s\n", opt.urdf.c_str(), opt.out.c_str());
  for (const DraftGuess& g : draft.guesses)
    std::printf("  guess %-22s %s  (confidence %.2f: %s)\n", (g.what + ":").c_str(),
                g.value.c_str(), g.confidence, g.why.c_str());
  if (draft.problems.empty()) {
    std::printf("  checks: every convention holds (docs/hand-description.md)\n");
  } else {
    for (const std::string& p : draft.problems) std::printf("  check failed: %s\n", p.c_str());
    std::printf("  edit %s where the checks fail\n", opt.out.c_str());
  }
}

}  // namespace

void add_hand_command(CLI::App& app) {
  CLI::App* hand = app.add_subcommand("hand", "Hand descriptions: `hand init` drafts one");
  hand->require_subcommand(1);
  auto opt = std::make_shared<HandInitOptions>();
  CLI::App* init = hand->add_subcommand(
      "init", "Draft a hand description (YAML) from a URDF; prints each guess and how sure");
  init->add_option("--urdf", opt->urdf, "The hand's URDF")->required()->check(CLI::ExistingFile);
  init->add_option("--out", opt->out, "Hand description to write (YAML)")->required();
  add_package_path_option(init, opt->hand_load);
  init->callback([opt]() { run_hand_init(*opt); });
}

}  // namespace cordgrasp::cli
