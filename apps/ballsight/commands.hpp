#pragma once
// Each subcommand group registers itself on the top-level app; the commands stay thin: parse
// options into the library's option structs, call the library, print the result.

#include <CLI/CLI.hpp>

namespace ballsight::app {

// Registrations, one per command file (apps/ballsight/<name>_command.cpp).

/// `sim omni`: omnidirectional-camera scenes with their truth (on the `sim` subcommand).
void add_sim_omni_command(CLI::App& sim);
/// `omni inspect` (omni_inspect_command.cpp), registered on the `omni` group.
void add_omni_inspect_command(CLI::App& omni);
/// `sim court` on the `sim` subcommand (sim_court_command.cpp).
void add_sim_court_command(CLI::App& sim);
/// `sim rings`: the ring image of calibration from one spin (sim_rings_command.cpp).
void add_sim_rings_command(CLI::App& sim);

/// `demo`: the main job on built-in simulated data (demo_command.cpp).
void add_demo_command(CLI::App& app);

/// `omni fit` and `omni predict` (omni_fit_command.cpp), registered on the `omni` group.
void add_omni_fit_commands(CLI::App& omni);
/// `omni locate` (omni_locate_command.cpp).
void add_omni_locate_command(CLI::App& omni);
/// `omni markers`: calibration samples from the markers of one frame (omni_markers_command.cpp).
void add_omni_markers_command(CLI::App& omni);
/// `omni rings`: calibration samples from the rings of one spin (omni_rings_command.cpp).
void add_omni_rings_command(CLI::App& omni);

/// `eval omni` (eval_command.cpp), registered on the `eval` group.
void add_eval_commands(CLI::App& eval);
/// `calibrate camera` (calibrate_command.cpp), registered on the `calibrate` group.
void add_calibrate_camera_command(CLI::App& calibrate);
/// `court calibrate` (court_calibrate_command.cpp), registered on the `court` group.
void add_court_calibrate_command(CLI::App& court);
/// `court run` (court_command.cpp), registered on the `court` group.
void add_court_run_command(CLI::App& court);
/// `eval court` (eval_court_command.cpp), registered on the `eval` group.
void add_eval_court_command(CLI::App& eval);
/// `serve`: the navigation service (serve_command.cpp).
void add_serve_command(CLI::App& app);
/// `ballsight record info`.
void add_record_commands(CLI::App& app);
/// `robot`: the simulated collector's controller (robot_command.cpp).
void add_robot_command(CLI::App& app);
/// `plan`: the collection route of one world model (plan_command.cpp).
void add_plan_command(CLI::App& app);
/// `eval plan` (eval_plan_command.cpp), registered on the `eval` group.
void add_eval_plan_command(CLI::App& eval);
/// `eval loop` (eval_loop_command.cpp), registered on the `eval` group.
void add_eval_loop_command(CLI::App& eval);
/// `eval tsplib` (eval_tsplib_command.cpp), registered on the `eval` group.
void add_eval_tsplib_command(CLI::App& eval);
/// `eval replay` (eval_replay_command.cpp), registered on the `eval` group.
void add_eval_replay_command(CLI::App& eval);
/// `eval detect-real` and `eval tennis-sim` (eval_tennis_command.cpp), registered on the `eval`
/// group.
void add_eval_tennis_command(CLI::App& eval);
/// `eval nodes` (eval_nodes_command.cpp), registered on the `eval` group.
void add_eval_nodes_command(CLI::App& eval);
/// `camera-node` and `court-node`: the court on DDS (node_commands.cpp).
void add_node_commands(CLI::App& app);
/// `omni-node`: a robot's omni camera on DDS (omni_node_command.cpp).
void add_omni_node_command(CLI::App& app);
/// `detect balls` and `colours learn` (detect_balls_command.cpp), with `detect fit`.
void add_detect_commands(CLI::App& app);
/// `detect fit` (detect_fit_command.cpp), registered on the `detect` group.
void add_detect_fit_command(CLI::App& detect);
/// `detect patches` (detect_patches_command.cpp), registered on the `detect` group.
void add_detect_patches_command(CLI::App& detect);

}  // namespace ballsight::app
