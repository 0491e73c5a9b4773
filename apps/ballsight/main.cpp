// ballsight: the command line. Thin: every subcommand parses options and calls the library.

#include <CLI/CLI.hpp>
#include <exception>
#include <iostream>
#include <string>

#include "ballsight/core/error.hpp"
#include "commands.hpp"

int main(int argc, char** argv) {
  CLI::App app{"ballsight: vision for ball-collecting and ball-playing robots"};
  app.require_subcommand(1);
  app.set_version_flag("--version", "ballsight 0.1.0");
  // One line on bad options, like every other input error.
  app.failure_message([](const CLI::App*, const CLI::Error& e) {
    return std::string("ballsight: error: ") + e.what() + " (see --help)\n";
  });

  CLI::App* sim = app.add_subcommand("sim", "Render simulated scenes with their ground truth");
  sim->require_subcommand(1);
  ballsight::app::add_sim_omni_command(*sim);
  ballsight::app::add_sim_court_command(*sim);
  ballsight::app::add_sim_rings_command(*sim);

  CLI::App* omni = app.add_subcommand(
      "omni", "Omnidirectional camera: calibration, lookup tables, ball localisation");
  omni->require_subcommand(1);
  ballsight::app::add_omni_fit_commands(*omni);
  ballsight::app::add_omni_inspect_command(*omni);
  ballsight::app::add_omni_locate_command(*omni);
  ballsight::app::add_omni_markers_command(*omni);
  ballsight::app::add_omni_rings_command(*omni);

  CLI::App* eval = app.add_subcommand("eval", "Experiments: ballsight against the papers' methods");
  eval->require_subcommand(1);
  ballsight::app::add_eval_commands(*eval);
  ballsight::app::add_eval_court_command(*eval);
  ballsight::app::add_eval_plan_command(*eval);
  ballsight::app::add_eval_loop_command(*eval);
  ballsight::app::add_eval_tsplib_command(*eval);
  ballsight::app::add_eval_replay_command(*eval);
  ballsight::app::add_eval_tennis_command(*eval);
  ballsight::app::add_eval_nodes_command(*eval);
  ballsight::app::add_demo_command(app);

  CLI::App* calibrate = app.add_subcommand("calibrate", "Camera calibration from chessboards");
  calibrate->require_subcommand(1);
  ballsight::app::add_calibrate_camera_command(*calibrate);

  CLI::App* court =
      app.add_subcommand("court", "Fixed cameras around a tennis court: calibration and tracking");
  court->require_subcommand(1);
  ballsight::app::add_court_calibrate_command(*court);
  ballsight::app::add_court_run_command(*court);
  ballsight::app::add_detect_commands(app);
  ballsight::app::add_plan_command(app);
  ballsight::app::add_serve_command(app);
  ballsight::app::add_record_commands(app);
  ballsight::app::add_robot_command(app);
  ballsight::app::add_node_commands(app);
  ballsight::app::add_omni_node_command(app);

  try {
    app.parse(argc, argv);
  } catch (const CLI::CallForHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForAllHelp& e) {
    return app.exit(e);
  } catch (const CLI::CallForVersion& e) {
    return app.exit(e);
  } catch (const CLI::ParseError& e) {
    app.exit(e);
    return 2;
  } catch (const ballsight::InputError& e) {
    std::cerr << "ballsight: error: " << e.what() << "\n";
    return 2;
  } catch (const std::exception& e) {
    std::cerr << "ballsight: internal error: " << e.what() << "\n";
    return 3;
  }
  return 0;
}
