#pragma once
// The colours the court simulator paints its objects with (BGR albedo), and the violet a site
// uses where the usual colour is lost in its floor (set_court_surface, sim/tennis_court.hpp).

#include <opencv2/core.hpp>

namespace ballsight::sim {

inline const cv::Vec3b kTennisBallBgr{45, 250, 225};  // fluorescent yellow
inline const cv::Vec3b kPinkMarkerBgr{180, 80, 255};  // the robot's front marker, hue 326 deg
inline const cv::Vec3b kBlueMarkerBgr{220, 80, 30};   // its back marker, hue 224 deg
/// Hue 272 deg: reference balls on red and wooden courts, the back marker on a blue one.
inline const cv::Vec3b kVioletBgr{230, 40, 140};

}  // namespace ballsight::sim
