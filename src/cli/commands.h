#pragma once
// gloss-cli's subcommands. Each lives in its own file (render_command.cpp, presets_command.cpp,
// bench_command.cpp, tradeoff_command.cpp ...) and exposes one function that adds its subcommand
// to the app. A command file registers that function at namespace scope,
//
//   [[maybe_unused]] const bool registered = gloss::register_command(30, add_bench_command);
//
// so that adding a command needs no edit of main.cpp. The subcommand's callback does the work;
// it throws InputError (bad input, exit 2) or RuntimeFailure (exit 1), and main reports them.
#include <vector>

#include <CLI/CLI.hpp>

namespace gloss {

// The version --version prints and PNGs carry in their "Software" chunk.
inline constexpr const char* kGlossVersion = "0.1.0";

using AddCommand = void (*)(CLI::App& app);

// Records add for main; order sorts the subcommands in --help (render 10, presets 20).
// Returns true so that it can initialise a namespace-scope constant.
bool register_command(int order, AddCommand add);

// The registered commands' functions, sorted by order.
std::vector<AddCommand> registered_commands();

void add_render_command(CLI::App& app);
void add_presets_command(CLI::App& app);

}  // namespace gloss
