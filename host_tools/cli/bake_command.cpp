// spanlight bake SCENE.json --out DIR [--depfile FILE] [--animation A.json] [knobs | --config FILE]: C++ sources for a firmware build.
#include <cstdio>
#include <filesystem>
#include <stdexcept>
#include <string>
#include <vector>

#include "analyze/knob_config.hpp"
#include "bake/bake.hpp"
#include "bake/depfile.hpp"
#include "cli/accuracy_warning.hpp"
#include "cli/animation_load.hpp"
#include "cli/commands.hpp"
#include "cli/knobs.hpp"
#include "cli/load.hpp"
#include "io/atomic_write.hpp"
#include "scene/scene_files.hpp"
#include "sweep/filter_override.hpp"
#include "spanlight/scene_features.hpp"

namespace spanlight::cli {
namespace {

struct BakeArgs {
  std::string scene;
  std::string out;
  std::string depfile;  // where to list the files the bake read, for the build that runs it
  std::string config;   // `spanlight analyze --write-config` output; replaces the knob options
  std::string animation;
  Knobs knobs;
  bool force = false;
};

int run_bake(const BakeArgs& args) {
  BakeArgs a = args;
  std::optional<scene::Scene> scene = load_or_report(a.scene);
  if (!scene) return exit_bad_input;
  io::RunInputs inputs = inputs_of(*scene);
  if (!a.config.empty()) {  // read errors throw "FILE: FIELD: expected ...": main reports them and exits 2
    const sweep::GridPoint point = analyze::read_knob_config(a.config);
    a.knobs = point.knobs;
    scene = sweep::with_filter(*scene, point.filter);
    inputs.add(a.config);
  }
  std::optional<scene::Animation> loaded;
  if (!a.animation.empty()) {
    loaded = load_animation_or_report(a.animation, *scene);
    if (!loaded) return exit_bad_input;
    inputs.add(std::filesystem::path(a.animation));
  }
  io::OutputFolder out(a.out, "--out", a.force, inputs);  // checked before anything is prepared
  warn_if_inaccurate(a.knobs);
  const auto prepared = prepare_or_report(*scene);
  if (!prepared) return exit_bad_input;
  std::unique_ptr<prepare::PreparedAnimation> animation;
  if (loaded) {
    animation = prepare_animation_or_report(*loaded, *scene, *prepared);
    if (!animation) return exit_bad_input;
  }
  std::string depfile_text;  // made before anything is written: a bad name leaves no output
  const std::filesystem::path outputs[2] = {out.path() / bake::baked_scene_file, out.path() / bake::baked_config_file};
  if (!a.depfile.empty()) {
    std::vector<std::filesystem::path> files_read = scene::files_read(*scene);
    if (!a.config.empty()) files_read.emplace_back(a.config);  // editing the config bakes again
    if (animation) files_read.push_back(animation->source.file);
    const std::string refusal = bake::depfile_refusal(a.depfile, files_read, {outputs[0], outputs[1]});
    if (!refusal.empty()) {
      std::fprintf(stderr, "%s: --depfile: %s\n", a.depfile.c_str(), refusal.c_str());
      return exit_bad_input;
    }
    try {
      depfile_text = bake::depfile_text({outputs[0], outputs[1]}, files_read);
    } catch (const std::invalid_argument& e) {
      std::fprintf(stderr, "%s\n", e.what());
      return exit_bad_input;
    }
  }
  bake::write_baked_scene(*prepared, a.knobs, scene->name, out, animation.get());
  if (!a.depfile.empty()) {
    // Inside --out it is one of the bake's own files (listed in the folder's manifest, so the
    // next bake accepts the folder); elsewhere a file of its own.
    const std::filesystem::path inside = std::filesystem::path(a.depfile).lexically_normal().lexically_relative(out.path().lexically_normal());
    if (!inside.empty() && *inside.begin() != "..") out.write(inside, depfile_text);
    else io::write_file_atomically(a.depfile, depfile_text, "--depfile", inputs);
  }
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
  cmd->add_option("scene", args->scene, "scene file (JSON, see docs/scene-format.md)")->required();
  cmd->add_option("--out", args->out, "output folder: new, empty, or holding only what spanlight wrote there")->required();
  cmd->add_flag("--force", args->force, "write into --out even when it holds other files (none is removed)");
  cmd->add_option("--depfile", args->depfile,
                  "also write FILE: a Makefile-syntax rule naming the scene and every file it read, for the build")
      ->type_name("FILE");
  cmd->add_option("--animation", args->animation,
                  "also bake this animation (docs/animation-format.md) as baked::animation for scene_pose_at_frame")
      ->type_name("FILE");
  add_knob_options(*cmd, args->knobs);
  CLI::Option* config = cmd->add_option("--config", args->config,
                                        "knobs and texture filter from a JSON file (spanlight analyze --write-config)")
                            ->type_name("FILE");
  for (const std::string& knob : knob_option_names()) config->excludes(cmd->get_option(knob));
  return [args] { return run_bake(*args); };
}

}  // namespace spanlight::cli
