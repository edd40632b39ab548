// The `spanlight` subcommands. Each registers its options on the app and
// returns the exit status when run: 0 success, 1 a failed check, 2 bad input.
#pragma once

#include <functional>

#include <CLI/CLI.hpp>

namespace spanlight::cli {

using Command = std::function<int()>;

inline constexpr int exit_ok = 0;
inline constexpr int exit_bad_input = 2;

Command add_render_command(CLI::App& app);
Command add_compare_command(CLI::App& app);
Command add_bake_command(CLI::App& app);
Command add_sweep_command(CLI::App& app);
Command add_analyze_command(CLI::App& app);
Command add_cost_command(CLI::App& app);

}  // namespace spanlight::cli
