// spanlight bake SCENE.json --out DIR [knobs]: C++ sources for a firmware build.
#include <cstdio>
#include <string>

#include "analyze/knob_config.hpp"
#include "bake/bake.hpp"
#include "cli/commands.hpp"
#include "cli/knobs.hpp"
#include "cli/load.hpp"
#include "sweep/filter_override.hpp"

namespace spanlight::cli {
namespace {

struct BakeArgs {
  std::string scene;
  std::string out;
  std::string config;  // `spanlight analyze --write-config` output; replaces the knob options
  KnobArgs knobs;
};

int run_bake(const BakeArgs& a) {
  std::optional<scene::Scene> scene = load_or_report(a.scene);
  if (!scene) return exit_bad_input;
  prepare::FixedOptions options = to_fixed_options(a.knobs);
  if (!a.config.empty()) {  // read errors throw: main reports them and exits 2
    const analyze::KnobConfig config = analyze::read_knob_config(a.config);
    options = sweep::to_fixed_options(config.knobs, config.format);
    scene = sweep::with_filter(*scene, config.knobs.filter);
  }
  const auto prepared = prepare_or_report(*scene);
  if (!prepared) return exit_bad_input;
  try {
    bake::write_baked_scene(*prepared, options, scene->name, a.out);
  } catch (const std::exception& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_bad_input;
  }
  const bake::SceneFeatures f = bake::features_of(prepared->scene);
  std::printf("baked %s into %s: %d projector(s), shadows %s%s, bilinear %s\n", scene->name.c_str(), a.out.c_str(),
              f.projectors, f.shadows ? "on" : "off", f.pcf ? " (pcf2x2)" : "", f.bilinear ? "on" : "off");
  return exit_ok;
}

}  // namespace

Command add_bake_command(CLI::App& app) {
  auto args = std::make_shared<BakeArgs>();
  CLI::App* cmd = app.add_subcommand("bake", "write a scene as C++ sources (baked_scene.cpp, baked_config.hpp) for firmware");
  cmd->add_option("scene", args->scene, "scene file")->required();
  cmd->add_option("--out", args->out, "output folder")->required();
  add_knob_options(*cmd, args->knobs);
  CLI::Option* config = cmd->add_option("--config", args->config, "knobs from a JSON file (spanlight analyze --write-config)")
                            ->check(CLI::ExistingFile);
  for (const char* knob : {"--span", "--tolerance", "--table-bits", "--newton", "--depth-bits", "--format", "--fused"})
    config->excludes(cmd->get_option(knob));
  return [args] { return run_bake(*args); };
}

}  // namespace spanlight::cli
