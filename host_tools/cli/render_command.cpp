// spanlight render SCENE.json --backend fixed|float --out FILE.png [knobs]
#include <cstdio>
#include <map>
#include <string>

#include "cli/commands.hpp"
#include "compare/compare.hpp"
#include "float_model/float_model.hpp"
#include "prepare/render_fixed.hpp"
#include "scene/scene.hpp"

namespace spanlight::cli {
namespace {

struct RenderArgs {
  std::string scene;
  std::string backend = "fixed";
  std::string out;
  int span = 16;
  int tolerance_log2 = 3;
  int table_bits = 8;
  int newton = 1;
  int depth_bits = 24;
  std::string format = "rgb888";
  bool fused = false;
};

int span_log2_of(int span) {
  for (int k = 0; k <= 6; ++k)
    if ((1 << k) == span) return k;
  return -1;
}

int run_render(const RenderArgs& a) {
  scene::Scene scene;
  try {
    scene = scene::load_scene(a.scene);
  } catch (const scene::SceneError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_bad_input;
  }
  std::vector<std::uint8_t> rgb;
  if (a.backend == "float") {
    rgb = float_model::render_float(scene).rgb;
  } else {
    prepare::FixedOptions options;
    options.format = a.format == "rgb565" ? PixelFormat::rgb565 : PixelFormat::rgb888;
    options.table_bits = a.table_bits;
    options.newton_steps = a.newton;
    options.precision.span_log2 = static_cast<std::uint8_t>(span_log2_of(a.span));
    options.precision.span_tolerance_log2 = static_cast<std::uint8_t>(a.tolerance_log2);
    options.precision.depth_bits = static_cast<std::uint8_t>(a.depth_bits);
    options.precision.fused = a.fused;
    std::unique_ptr<prepare::PreparedStorage> prepared;
    try {
      prepared = prepare::prepare_scene(scene);
    } catch (const prepare::PrepareError& e) {
      std::fprintf(stderr, "%s: %s\n", a.scene.c_str(), e.what());
      return exit_bad_input;
    }
    rgb = prepare::render_fixed(*prepared, options).rgb;
  }
  std::string error;
  if (!compare::write_png_atomically(a.out, scene.width, scene.height, rgb, &error)) {
    std::fprintf(stderr, "%s: cannot write: %s\n", a.out.c_str(), error.c_str());
    return exit_bad_input;
  }
  return exit_ok;
}

}  // namespace

Command add_render_command(CLI::App& app) {
  auto args = std::make_shared<RenderArgs>();
  CLI::App* cmd = app.add_subcommand("render", "render a scene to a PNG with the fixed pipeline or the float model");
  cmd->add_option("scene", args->scene, "scene file (JSON, spec: docs/scene-format.md)")->required();
  cmd->add_option("--backend", args->backend, "fixed (the firmware pipeline) or float (the double-precision model)")
      ->check(CLI::IsMember({"fixed", "float"}));
  cmd->add_option("--out", args->out, "output PNG")->required();
  cmd->add_option("--span", args->span, "pixels between exact perspective divides (1..64, power of two)")
      ->check(CLI::IsMember({1, 2, 4, 8, 16, 32, 64}));
  cmd->add_option("--tolerance", args->tolerance_log2,
                  "shorten segments that would drift more than 2^-N texel from the exact value (0: never)")
      ->check(CLI::Range(0, 10));
  cmd->add_option("--table-bits", args->table_bits, "reciprocal table index bits")->check(CLI::IsMember({6, 8, 10, 12}));
  cmd->add_option("--newton", args->newton, "Newton-Raphson steps after the table")->check(CLI::IsMember({0, 1, 2}));
  cmd->add_option("--depth-bits", args->depth_bits, "depth buffer and shadow map bits")->check(CLI::IsMember({16, 24}));
  cmd->add_option("--format", args->format, "framebuffer format")->check(CLI::IsMember({"rgb888", "rgb565"}));
  cmd->add_flag("--fused", args->fused, "one fused pass instead of the paper's multipass (same picture)");
  return [args] { return run_render(*args); };
}

}  // namespace spanlight::cli
