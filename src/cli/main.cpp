// gloss-cli: the headless renderer (docs/spec/scene-and-cli.md). main is the only place that turns
// errors into messages and exit codes: 0 success, 2 bad input or usage, 1 any other failure.
// Every failure prints exactly one line on stderr that starts with "error:".
#include <algorithm>
#include <exception>
#include <iostream>
#include <string>
#include <vector>

#include <CLI/CLI.hpp>

#include "base/error.h"
#include "base/text/printable_text.h"
#include "base/text/text_distance.h"
#include "base/version.h"
#include "cli/commands.h"

namespace {

// Messages can span lines (nlohmann, CLI11); the contract is one line, and no control character
// of the input (a file name given on the command line) reaches the terminal.
int report_error(std::string message, int status) {
  std::replace(message.begin(), message.end(), '\n', ' ');
  while (!message.empty() && message.back() == ' ') message.pop_back();
  std::cerr << "error: " << gloss::printable_text(message) << "\n";
  return status;
}

// "FILE: " for the file argument CLI11 had read before a usage error, so the message names it.
std::string parsed_file(const CLI::App& app) {
  for (const CLI::App* sub : app.get_subcommands()) {
    for (const CLI::Option* option : sub->get_options()) {
      if (option->get_positional() && option->count() > 0) {
        return option->as<std::string>() + ": ";
      }
    }
  }
  return "";
}

}  // namespace

int main(int argc, char** argv) {
  // Setup: the subcommands, in the order --help lists them.
  CLI::App app{"gloss-cli: renders gloss scene files (Phong / Blinn-Phong) without a window"};
  app.set_version_flag("--version", std::string("gloss-cli ") + gloss::gloss_version());
  app.require_subcommand(1);
  gloss::add_render_command(app);
  gloss::add_presets_command(app);
  gloss::add_bench_command(app);
  gloss::add_tradeoff_command(app);
  gloss::add_fit_command(app);
  gloss::add_export_commands(app);

  // A first word that names no command: CLI11 would say only "A subcommand is required".
  if (argc > 1 && argv[1][0] != '-') {
    std::vector<std::string> commands;
    for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
    if (std::find(commands.begin(), commands.end(), argv[1]) == commands.end()) {
      // A suggestion only within two edits ("rendr"): "frobnicate" is no misspelt "fit".
      std::vector<std::string> nearest = gloss::nearest_words(argv[1], commands, 1);
      if (!nearest.empty() && gloss::edit_distance(argv[1], nearest[0]) > 2) nearest.clear();
      return report_error(std::string("unknown command '") + argv[1] + "'" +
                              gloss::did_you_mean(nearest) + "; gloss-cli --help lists them",
                          2);
    }
  }

  // Run: the chosen subcommand's callback runs inside parse.
  try {
    app.parse(argc, argv);
  } catch (const CLI::ParseError& error) {
    // --help and --version arrive as "errors" with exit code 0; CLI11 prints them.
    if (error.get_exit_code() == 0) return app.exit(error);
    return report_error(parsed_file(app) + error.what(), 2);
  } catch (const gloss::InputError& error) {
    return report_error(error.what(), 2);
  } catch (const gloss::RuntimeFailure& error) {
    return report_error(error.what(), 1);
  } catch (const std::exception& error) {
    return report_error(error.what(), 1);
  }
  return 0;
}
