#pragma once
// The mirror's rim in an omni image: the edge of the bright disc the mirror fills, against the
// dark housing around it. Its centre is a first guess of the image centre the polar samples are
// taken around (the omnivision paper's calibration page asks the user for that centre).

#include <opencv2/core.hpp>
#include <optional>

#include "ballsight/core/geometry.hpp"

namespace ballsight {

struct MirrorRim {
  Vec2 center_px = Vec2::Zero();
  double radius_px = 0.0;
  double rms_px = 0.0;    // of the rim points about the circle
  double coverage = 0.0;  // share of the circle's length seen inside the image, [0, 1]
};

struct MirrorRimOptions {
  double min_coverage = 0.3;  // less of the rim in view: no suggestion
  double max_rms_px = 3.0;    // a rim less round than this: no suggestion
};

/// The rim of the largest bright region of `bgr` (Otsu's threshold on the blurred grey image),
/// a circle fitted to its outline away from the image border (Kasa's algebraic fit, then the
/// points within 3 px of it refitted), or nullopt when no round rim is in view (a mirror that
/// fills the whole image, a dark frame).
std::optional<MirrorRim> find_mirror_rim(const cv::Mat& bgr, const MirrorRimOptions& options = {});

}  // namespace ballsight
