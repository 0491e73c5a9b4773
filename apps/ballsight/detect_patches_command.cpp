// `ballsight detect patches`: the ball candidates of labelled photos as patches with their
// truth, for training and scoring a verifier offline (scripts/train_ball_verifier.py): a NumPy
// file of the patches and a CSV of what each one is.
#include <algorithm>
#include <cstdint>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

#include "ballsight/core/enum_names.hpp"
#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/detect/ball_patches.hpp"
#include "ballsight/detect/photo_ball_fit.hpp"
#include "ballsight/eval/tennis_sim.hpp"
#include "commands.hpp"

namespace ballsight::app {

namespace {

struct PatchArgs {
  std::string data = "../shared/data";
  std::vector<std::string> sources;
  int sim_scenes = 0;
  std::uint64_t sim_seed = 1;
  std::string out;
};

// A NumPy .npy file (format 1.0) of `count` uint8 patches of kBallPatchSize^2 x 3 (BGR).
std::string npy_header(std::size_t count) {
  std::string dict = "{'descr': '|u1', 'fortran_order': False, 'shape': (" + std::to_string(count) +
                     ", " + std::to_string(kBallPatchSize) + ", " + std::to_string(kBallPatchSize) +
                     ", 3), }";
  // Magic (6), version (2) and length (2), then the dictionary padded to a multiple of 64 with
  // spaces and a newline.
  const std::size_t unpadded = 10 + dict.size() + 1;
  dict.append((64 - unpadded % 64) % 64, ' ');
  dict += '\n';
  std::string header("\x93NUMPY\x01\x00", 8);
  header += static_cast<char>(dict.size() & 0xff);
  header += static_cast<char>(dict.size() >> 8);
  return header + dict;
}

constexpr EnumNames<CandidateTruth, 3> kTruthNames{{{CandidateTruth::ball, "ball"},
                                                    {CandidateTruth::not_ball, "not_ball"},
                                                    {CandidateTruth::unknown, "unknown"}}};

void run_patches(const PatchArgs& args) {
  std::vector<LabelledPhotos> photos =
      args.sources.empty()
          ? std::vector<LabelledPhotos>{}
          : read_photo_sources(std::filesystem::path(args.data) / "real" / "tennis", args.sources,
                               "--source")
                .named;
  if (args.sim_scenes > 0)
    photos.push_back(simulated_fitting_photos(args.sim_scenes, args.sim_seed));
  require(!photos.empty(), "detect patches", "give --source or --sim-scenes");

  std::string pixels;
  std::ostringstream csv;
  csv << "source,image,x_px,y_px,radius_px,response,truth\n";
  std::size_t count = 0;
  for (const LabelledPhotos& source : photos) {
    for (std::size_t i = 0; i < source.images.size(); ++i) {
      const std::vector<BallCandidate> candidates = find_ball_candidates(source.images[i]);
      const std::vector<CandidateTruth> truth =
          candidate_truth(candidates, source.labels[i], source.ignored_in(i));
      for (std::size_t k = 0; k < candidates.size(); ++k) {
        const cv::Mat patch = ball_patch(source.images[i], candidates[k]);
        pixels.append(reinterpret_cast<const char*>(patch.data), patch.total() * 3);
        const BallCandidate& c = candidates[k];
        csv << source.source << ",\"" << source.files[i] << "\"," << c.center_px.x() << ","
            << c.center_px.y() << "," << c.radius_px << "," << c.response << ","
            << enum_name(kTruthNames, truth[k]) << "\n";
        ++count;
      }
    }
  }
  write_file_atomic(args.out + ".npy", npy_header(count) + pixels);
  write_file_atomic(args.out + ".csv", csv.str());
  std::cout << count << " patches -> " << args.out << ".npy, " << args.out << ".csv\n";
}

}  // namespace

void add_detect_patches_command(CLI::App& detect) {
  auto args = std::make_shared<PatchArgs>();
  CLI::App* cmd = detect.add_subcommand(
      "patches",
      "Write the ball candidates of labelled photos (real sources under real/tennis of a data "
      "folder, the court simulator's frames) as patches (OUT.npy, uint8 N x 32 x 32 x 3, BGR) "
      "with their truth (OUT.csv: ball, not_ball or unknown), to train a verifier on");
  cmd->add_option("--data", args->data, "The data folder")->capture_default_str();
  cmd->add_option("--source", args->sources, "A real source to take patches of (repeatable)")
      ->type_name("NAME");
  cmd->add_option("--sim-scenes", args->sim_scenes,
                  "Scenes of the court simulator to take patches of (1920x1080, four cameras "
                  "each, with distractors)")
      ->check(CLI::Range(0, 1000))
      ->capture_default_str();
  cmd->add_option("--sim-seed", args->sim_seed, "The simulated scenes' seed")
      ->capture_default_str();
  cmd->add_option("--out", args->out, "Prefix of the two files to write")->required();
  cmd->callback([args] { run_patches(*args); });
}

}  // namespace ballsight::app
