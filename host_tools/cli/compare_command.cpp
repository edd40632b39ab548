// spanlight compare A.png B.png [--diff heat.png] [--json]
#include <cstdio>
#include <string>

#include "cli/commands.hpp"
#include "compare/compare.hpp"
#include "io/atomic_write.hpp"

namespace spanlight::cli {
namespace {

struct CompareArgs {
  std::string a, b, diff;
  bool json = false;
};

int run_compare(const CompareArgs& args) {
  const io::RunInputs inputs{args.a, args.b};
  if (!args.diff.empty()) io::check_output_file(args.diff, "--diff", inputs);
  compare::CompareResult result;
  try {
    result = compare::compare_images(args.a, args.b);
    if (!args.diff.empty()) {
      const io::Rgb8Image heat = compare::heat_map(args.a, args.b);
      io::write_file_atomically(args.diff, compare::png_bytes({heat.width, heat.height, heat.rgb}), "--diff", inputs);
    }
  } catch (const compare::CompareError& e) {
    std::fprintf(stderr, "%s\n", e.what());
    return exit_bad_input;
  }
  std::printf("%s\n", args.json ? compare::to_json(result).c_str() : compare::to_text(result).c_str());
  return exit_ok;
}

}  // namespace

Command add_compare_command(CLI::App& app) {
  auto args = std::make_shared<CompareArgs>();
  CLI::App* cmd = app.add_subcommand("compare", "PSNR and error in 8-bit levels between two images");
  cmd->add_option("a", args->a, "first image")->required();
  cmd->add_option("b", args->b, "second image (the reference)")->required();
  cmd->add_option("--diff", args->diff, "write a heat map of the differences (PNG; never over either image)");
  cmd->add_flag("--json", args->json, "print JSON instead of text");
  return [args] { return run_compare(*args); };
}

}  // namespace spanlight::cli
