// `ballsight omni inspect`: what a lookup table says about itself and where it cannot be trusted.

#include <iostream>
#include <memory>
#include <string>

#include "ballsight/calib/lut_inspect.hpp"
#include "ballsight/camera/image_file.hpp"
#include "ballsight/eval/plot_inputs.hpp"
#include "ballsight/viz/lut_plot.hpp"
#include "commands.hpp"

namespace ballsight::app {

namespace {

struct InspectArgs {
  std::string file;
  std::string format = "auto";
  bool json = false;
  std::string plot;
  double drop_tolerance_cm = LutInspectOptions{}.drop_tolerance_cm;
};

void run_inspect(const InspectArgs& args) {
  LutInspectOptions options;
  options.drop_tolerance_cm = args.drop_tolerance_cm;
  const InspectedLut lut = read_lut_for_inspection(args.file, lut_format_from_string(args.format));
  const LutInspection inspection = inspect_lut(lut, options);
  if (!args.plot.empty()) {
    write_png_atomic(args.plot, plot_lut_figure(lut_figure_input(lut, inspection)));
  }
  if (args.json) {
    std::cout << to_json(inspection).dump(2) << "\n";
  } else {
    std::cout << format_report(inspection);
  }
}

}  // namespace

void add_omni_inspect_command(CLI::App& omni) {
  auto args = std::make_shared<InspectArgs>();
  CLI::App* cmd = omni.add_subcommand(
      "inspect",
      "Report a lookup table's first written radius, monotonic range, spread between directions "
      "and holes");
  cmd->add_option("FILE", args->file, "Lookup table: ballsight ground map or iris px2cm")
      ->required();
  cmd->add_option("--format", args->format, "Table format (default: detect)")
      ->check(CLI::IsMember({"auto", "ballsight", "iris-px2cm"}));
  cmd->add_flag("--json", args->json, "Print the report as JSON");
  cmd->add_option("--plot", args->plot,
                  "Write a PNG: distance vs radius for several directions and a heat map");
  cmd->add_option("--drop-tolerance-cm", args->drop_tolerance_cm,
                  "A drop of more than this below the running maximum ends the monotonic range")
      ->check(CLI::NonNegativeNumber);
  cmd->callback([args] { run_inspect(*args); });
}

}  // namespace ballsight::app
