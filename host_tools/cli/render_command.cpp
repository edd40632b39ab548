// spanlight render SCENE.json --backend fixed|float --out FILE.png [knobs]
// spanlight render SCENE.json --animation A.json --backend fixed|float|both --out DIR [knobs] (render_animation.hpp)
#include <cstdio>
#include <string>

#include "cli/accuracy_warning.hpp"
#include "cli/commands.hpp"
#include "cli/knobs.hpp"
#include "cli/load.hpp"
#include "cli/render_animation.hpp"
#include "prepare/render_fixed.hpp"
#include "compare/compare.hpp"
#include "float_model/float_model.hpp"
#include "io/atomic_write.hpp"

namespace spanlight::cli {
namespace {

struct RenderArgs {
  std::string scene;
  std::string backend = "fixed";
  std::string out;
  std::string animation;
  bool force = false;
  Knobs knobs;
};

int run_render(const RenderArgs& a) {
  if (!a.animation.empty()) return run_render_animation({a.scene, a.animation, a.backend, a.out, a.knobs, a.force});
  if (a.backend == "both") {
    std::fprintf(stderr, "%s: --backend: expected fixed or float without --animation, got both\n", a.scene.c_str());
    return exit_bad_input;
  }
  if (a.force) {
    std::fprintf(stderr, "%s: --force: expected only with --animation (a folder of frames)\n", a.scene.c_str());
    return exit_bad_input;
  }
  const std::optional<scene::Scene> scene = load_or_report(a.scene);
  if (!scene) return exit_bad_input;
  const io::RunInputs inputs = inputs_of(*scene);
  io::check_output_file(a.out, "--out", inputs);  // before rendering; write_file_atomically checks again
  std::vector<std::uint8_t> rgb;
  if (a.backend == "float") {
    rgb = float_model::render_float(*scene).rgb;
  } else {
    const auto prepared = prepare_or_report(*scene);
    if (!prepared) return exit_bad_input;
    warn_if_inaccurate(a.knobs);
    rgb = prepare::render_fixed(*prepared, a.knobs).rgb;
  }
  io::write_file_atomically(a.out, compare::png_bytes({scene->width, scene->height, rgb}), "--out", inputs);
  return exit_ok;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "render a scene to a PNG with the fixed pipeline or the float model");
  cmd->add_option("scene", args->scene, "scene file (JSON, see docs/scene-format.md)")->required();
  cmd->add_option("--backend", args->backend,
                  "fixed (the firmware pipeline), float (the double-precision model), or both (with --animation)")
      ->check(CLI::IsMember({"fixed", "float", "both"}));
  cmd->add_option("--out", args->out,
                  "output PNG: a new file or a regular one to replace (never a device, a folder or one of the "
                  "scene's own files); with --animation, a folder as `bake` takes it")
      ->required();
  cmd->add_option("--animation", args->animation,
                  "render every frame of this animation (docs/animation-format.md) into --out/<backend>/frame_NNNN.png")
      ->type_name("FILE");
  cmd->add_flag("--force", args->force, "with --animation: write into --out even when it holds other files");
  add_knob_options(*cmd, args->knobs);
  return [args] { return run_render(*args); };
}

}  // namespace spanlight::cli
