#include "cli/render_animation.hpp"

#include <cstdio>
#include <string>
#include <vector>

#include "cli/accuracy_warning.hpp"
#include "cli/animation_load.hpp"
#include "cli/commands.hpp"
#include "cli/load.hpp"
#include "compare/compare.hpp"
#include "float_model/float_model.hpp"
#include "io/output_folder.hpp"
#include "prepare/render_fixed.hpp"

namespace spanlight::cli {
namespace {

std::string frame_file(const char* backend, std::uint32_t frame) {
  char name[32];
  std::snprintf(name, sizeof name, "%s/frame_%04u.png", backend, static_cast<unsigned>(frame));
  return name;
}

}  // namespace

int run_render_animation(const AnimationRender& a) {
  const std::optional<scene::Scene> scene = load_or_report(a.scene);
  if (!scene) return exit_bad_input;
  const std::optional<scene::Animation> loaded = load_animation_or_report(a.animation, *scene);
  if (!loaded) return exit_bad_input;
  const auto prepared = prepare_or_report(*scene);
  if (!prepared) return exit_bad_input;
  const auto animation = prepare_animation_or_report(*loaded, *scene, *prepared);
  if (!animation) return exit_bad_input;
  io::RunInputs inputs = inputs_of(*scene);
  inputs.add(animation->source.file);
  io::OutputFolder out(a.out, "--out", a.force, inputs);

  const bool fixed = a.backend != "float", floating = a.backend != "fixed";
  if (fixed) warn_if_inaccurate(a.knobs);
  prepare::PosedMatrices matrices(prepared->scene);
  std::string csv = "frame,psnr_db\n";
  double worst_db = INFINITY;
  std::uint32_t worst_frame = 0;
  for (std::uint32_t k = 0; k < animation->animation.frame_count; ++k) {
    std::vector<std::uint8_t> fixed_rgb, float_rgb;
    if (fixed) {
      // check_every_frame built these already: a failure here is a bug, not input.
      const PoseResult pose = prepare::pose_frame(prepared->scene, animation->animation, k, matrices);
      if (!pose.ok()) throw std::logic_error("frame " + std::to_string(k) + ": the pose failed after it passed its check");
      fixed_rgb = prepare::render_fixed(*prepared, matrices.storage().matrices(), a.knobs).rgb;
      out.write(frame_file("fixed", k), compare::png_bytes({scene->width, scene->height, fixed_rgb}));
    }
    if (floating) {
      float_rgb = float_model::render_float(scene::scene_at_frame(*scene, animation->source, k)).rgb;
      out.write(frame_file("float", k), compare::png_bytes({scene->width, scene->height, float_rgb}));
    }
    if (fixed && floating) {
      const double db = compare::compare_images(compare::Rgb8View{scene->width, scene->height, fixed_rgb},
                                                compare::Rgb8View{scene->width, scene->height, float_rgb})
                            .psnr_db;
      std::printf("frame %04u: PSNR fixed vs float %s dB\n", static_cast<unsigned>(k), compare::psnr_text(db).c_str());
      csv += std::to_string(k) + "," + compare::psnr_text(db) + "\n";
      if (k == 0 || db < worst_db) {
        worst_db = db;
        worst_frame = k;
      }
    }
  }
  if (fixed) out.remove_earlier_files_under("fixed");
  if (floating) out.remove_earlier_files_under("float");
  if (fixed && floating) {
    out.write("compare/psnr.csv", csv);
    std::printf("worst frame %04u: PSNR %s dB\n", static_cast<unsigned>(worst_frame), compare::psnr_text(worst_db).c_str());
  }
  std::printf("rendered %u frame(s) of %s into %s\n", static_cast<unsigned>(animation->animation.frame_count),
              scene->name.c_str(), a.out.c_str());
  return exit_ok;
}

}  // namespace spanlight::cli
