// SPDX-License-Identifier: MIT
// rastrules check SCENE.json --driver NAME: one scene, the outputs of a campaign.
// Implements: FUZZ.REPORT (the command line)

#include "cli.hpp"
#include "fuzz_options.hpp"
#include "rastrules/fuzzer/fuzzer.hpp"

namespace rastrules::cli {

int run_check(const Args& args) {
  int status = kExitBadInput;
  auto o = parse_fuzz_options(args, true, false, status);
  if (!o)
    return status;
  o->settings.cases = 1;
  o->settings.progress = false;
  // rule: DRIVER.VALUES
  // Pipeline scenes too: their coverage, and the values of drivers that report them.
  auto loaded = load_scene(o->scene_path);
  if (!loaded)
    return kExitBadInput;
  auto d = open_driver_or_report(o->settings.driver_name);
  if (!d)
    return kExitBadInput;
  if (const std::string why = d->unsupported(loaded->scene); !why.empty()) {
    return error(o->settings.driver_name + " cannot draw this scene: " + why);
  }
  fuzzer::Summary s = fuzzer::run_check(*d, loaded->scene, o->settings);
  return finish_campaign(*o, *d, s);
}

} // namespace rastrules::cli
