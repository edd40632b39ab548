// spanlight render SCENE.json --backend fixed|float --out FILE.png [knobs]
#include <cstdio>
#include <string>

#include "cli/commands.hpp"
#include "cli/knobs.hpp"
#include "cli/load.hpp"
#include "prepare/render_fixed.hpp"
#include "compare/compare.hpp"
#include "float_model/float_model.hpp"

namespace spanlight::cli {
namespace {

struct RenderArgs {
  std::string scene;
  std::string backend = "fixed";
  std::string out;
  Knobs knobs;
};

int run_render(const RenderArgs& a) {
  const std::optional<scene::Scene> scene = load_or_report(a.scene);
  if (!scene) return exit_bad_input;
  std::vector<std::uint8_t> rgb;
  if (a.backend == "float") {
    rgb = float_model::render_float(*scene).rgb;
  } else {
    const auto prepared = prepare_or_report(*scene);
    if (!prepared) return exit_bad_input;
    rgb = prepare::render_fixed(*prepared, a.knobs).rgb;
  }
  std::string error;
  if (!compare::write_png_atomically(a.out, scene->width, scene->height, rgb, &error)) {
    std::fprintf(stderr, "%s: cannot write: %s\n", a.out.c_str(), error.c_str());
    return exit_bad_input;
  }
  return exit_ok;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "render a scene to a PNG with the fixed pipeline or the float model");
  cmd->add_option("scene", args->scene, "scene file (JSON, see docs/scene-format.md)")->required();
  cmd->add_option("--backend", args->backend, "fixed (the firmware pipeline) or float (the double-precision model)")
      ->check(CLI::IsMember({"fixed", "float"}));
  cmd->add_option("--out", args->out, "output PNG")->required();
  add_knob_options(*cmd, args->knobs);
  return [args] { return run_render(*args); };
}

}  // namespace spanlight::cli
