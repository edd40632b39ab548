// spanlight: render, compare, bake, sweep, analyze and cost from one binary.
#include <cstdio>
#include <exception>
#include <map>
#include <string>

#include "cli/commands.hpp"
#include "io/output_check.hpp"
#include "io/read_file.hpp"

int main(int argc, char** argv) {
  CLI::App app{"spanlight: fixed-point projective texturing, shadows and multipass lighting (Segal et al. '92)"};
  app.require_subcommand(1);
  std::map<std::string, spanlight::cli::Command> commands{
      {"render", spanlight::cli::add_render_command(app)},
      {"compare", spanlight::cli::add_compare_command(app)},
      {"bake", spanlight::cli::add_bake_command(app)},
      {"sweep", spanlight::cli::add_sweep_command(app)},
      {"analyze", spanlight::cli::add_analyze_command(app)},
      {"cost", spanlight::cli::add_cost_command(app)},
  };
  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return spanlight::cli::exit_bad_input;  // every usage error is bad input
  }
  for (auto& [name, run] : commands) {
    if (app.got_subcommand(name)) {
      try {
        return run();
      } catch (const spanlight::io::OutputError& e) {  // "FILE: OPTION: expected ...": the message is the whole story
        std::fprintf(stderr, "%s\n", e.what());
        return spanlight::cli::exit_bad_input;
      } catch (const spanlight::io::ReadError& e) {  // "FILE: expected ..."
        std::fprintf(stderr, "%s\n", e.what());
        return spanlight::cli::exit_bad_input;
      } catch (const std::exception& e) {
        std::fprintf(stderr, "spanlight %s: error: %s\n", name.c_str(), e.what());
        return spanlight::cli::exit_bad_input;
      }
    }
  }
  return spanlight::cli::exit_bad_input;
}
