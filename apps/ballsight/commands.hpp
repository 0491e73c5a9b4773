#pragma once
// Each subcommand group registers itself on the top-level app; the commands stay thin: parse
// options into the library's option structs, call the library, print the result.

#include <CLI/CLI.hpp>

namespace ballsight::app {

void add_sim_omni_command(CLI::App& sim);
void add_sim_court_command(CLI::App& sim);
void add_demo_command(CLI::App& app);

}  // namespace ballsight::app
