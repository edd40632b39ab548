// spanlight bake SCENE.json --out DIR [knobs]: C++ sources for a firmware build.
#include <cstdio>
#include <string>

#include "bake/bake.hpp"
#include "cli/accuracy_warning.hpp"
#include "cli/commands.hpp"
#include "cli/knobs.hpp"
#include "cli/load.hpp"
#include "spanlight/scene_features.hpp"

namespace spanlight::cli {
namespace {

struct BakeArgs {
  std::string scene;
  std::string out;
  Knobs knobs;
  bool force = false;
};

int run_bake(const BakeArgs& a) {
  const std::optional<scene::Scene> scene = load_or_report(a.scene);
  if (!scene) return exit_bad_input;
  io::OutputFolder out(a.out, "--out", a.force, inputs_of(*scene));  // checked before anything is prepared
  warn_if_inaccurate(a.knobs);
  const auto prepared = prepare_or_report(*scene);
  if (!prepared) return exit_bad_input;
  bake::write_baked_scene(*prepared, a.knobs, scene->name, out);
  const Features f = features_of(prepared->scene, a.knobs);
  std::printf("baked %s into %s: %d projector(s), shadows %s%s, filters%s%s, %s\n", scene->name.c_str(), a.out.c_str(),
              int(f.max_projectors), f.shadows ? "on" : "off", f.pcf ? " (pcf2x2)" : "", f.nearest ? " nearest" : "",
              f.bilinear ? " bilinear" : "", f.fused ? "fused" : "multipass");
  return exit_ok;
}

}  // namespace

Command add_bake_command(CLI::App& app) {
  auto args = std::make_shared<BakeArgs>();
  CLI::App* cmd = app.add_subcommand("bake", "write a scene as C++ sources (baked_scene.cpp, baked_config.hpp) for firmware");
  cmd->add_option("scene", args->scene, "scene file")->required();
  cmd->add_option("--out", args->out, "output folder: new, empty, or holding only what spanlight wrote there")->required();
  cmd->add_flag("--force", args->force, "write into --out even when it holds other files (none is removed)");
  add_knob_options(*cmd, args->knobs);
  return [args] { return run_bake(*args); };
}

}  // namespace spanlight::cli
