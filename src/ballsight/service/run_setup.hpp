#pragma once
// What a recording keeps to replay its run (docs/recording.md, "Replay"): the site, what the
// court pipeline is made of and the planner's options, as the file was begun. Kept as
// attachments: `replay/site.yml` (a site file, world/site.hpp's site_file_text),
// `replay/setup.json` (the pipeline's method, every camera's intrinsics and pose with every digit,
// the planner) and `replay/empty_court_N.png` (camera N's view of the empty court, when the
// pipeline has one).

#include <cstdint>
#include <string>
#include <vector>

#include "ballsight/pipeline/site_setup.hpp"
#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/record/mcap_format.hpp"
#include "ballsight/world/site.hpp"

namespace ballsight {

struct RunSetup {
  Site site;
  ServicePipeline pipeline;
  PlannerOptions planner;
};

/// The attachments that keep `setup`, stamped `time_ns`.
std::vector<mcap::Attachment> run_setup_attachments(const RunSetup& setup, std::int64_t time_ns);

/// The setup kept in `attachments` (a file's); throws InputError naming `where` (the file) and
/// the attachment that is missing or malformed.
RunSetup read_run_setup(const std::vector<mcap::Attachment>& attachments, const std::string& where);

}  // namespace ballsight
