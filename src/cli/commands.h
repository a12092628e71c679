#pragma once
// gloss-cli's subcommands, one file each; main adds them in the order --help lists them. Each
// subcommand's callback does the work and throws InputError (bad input, exit 2) or
// RuntimeFailure (exit 1); main reports them.
#include <CLI/CLI.hpp>

namespace gloss {

void add_render_command(CLI::App& app);    // render_command.cpp
void add_presets_command(CLI::App& app);   // presets_command.cpp
void add_bench_command(CLI::App& app);     // bench_command.cpp
void add_tradeoff_command(CLI::App& app);  // tradeoff_command.cpp
void add_fit_command(CLI::App& app);       // fit_command.cpp
void add_export_commands(CLI::App& app);   // export_command.cpp: export-gltf, export-threejs

}  // namespace gloss
