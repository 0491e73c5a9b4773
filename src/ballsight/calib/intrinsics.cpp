#include "ballsight/calib/intrinsics.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <numeric>
#include <opencv2/calib3d.hpp>

#include "ballsight/core/error.hpp"
#include "ballsight/core/statistics.hpp"

namespace ballsight {

void IntrinsicsOptions::validate() const {
  require(min_views >= 3, "min_views", "must be at least 3");
  require(std::isfinite(outlier_factor) && outlier_factor > 1.0, "outlier_factor",
          "must be greater than 1");
  require(std::isfinite(outlier_min_px) && outlier_min_px >= 0.0, "outlier_min_px",
          "must be non-negative");
  require(folds >= 2, "folds", "must be at least 2");
  require(std::isfinite(k3_min_gain) && k3_min_gain >= 0.0 && k3_min_gain < 1.0, "k3_min_gain",
          "must be in [0, 1)");
}

namespace {

// Sum of squared reprojection errors of a board view posed by PnP under the given intrinsics;
// infinite when PnP finds no pose (the intrinsics cannot explain the view at all).
double board_squared_error(const std::vector<cv::Point3f>& object,
                           const std::vector<cv::Point2f>& corners, const cv::Mat& camera_matrix,
                           const cv::Mat& distortion) {
  cv::Mat rvec, tvec;
  if (!cv::solvePnP(object, corners, camera_matrix, distortion, rvec, tvec, false,
                    cv::SOLVEPNP_IPPE))
    return std::numeric_limits<double>::infinity();
  cv::solvePnPRefineLM(object, corners, camera_matrix, distortion, rvec, tvec);
  std::vector<cv::Point2f> projected;
  cv::projectPoints(object, rvec, tvec, camera_matrix, distortion, projected);
  double sum = 0.0;
  for (std::size_t k = 0; k < corners.size(); ++k) {
    const cv::Point2f d = projected[k] - corners[k];
    sum += static_cast<double>(d.dot(d));
  }
  return sum;
}

struct Fit {
  cv::Mat camera_matrix;
  cv::Mat distortion;  // 1x5: k1 k2 p1 p2 k3
  double rms_px = 0.0;
  std::vector<double> view_rms_px;  // per view of the fit, in the order given
};

class Calibrator {
 public:
  Calibrator(const std::vector<ChessboardView>& views, const ChessboardPattern& pattern,
             cv::Size image_size)
      : views_(views), object_(pattern.object_points()), size_(image_size) {}

  // cv::calibrateCamera on the views `used`; with `guess`, starts from it (k3 from 0).
  Fit fit(const std::vector<std::size_t>& used, bool k3_free, const Fit* guess) const {
    std::vector<std::vector<cv::Point3f>> objects(used.size(), object_);
    std::vector<std::vector<cv::Point2f>> images;
    for (std::size_t i : used) images.push_back(views_[i].corners);
    Fit f;
    int flags = k3_free ? 0 : cv::CALIB_FIX_K3;
    if (guess != nullptr) {
      f.camera_matrix = guess->camera_matrix.clone();
      f.distortion = guess->distortion.clone();
      flags |= cv::CALIB_USE_INTRINSIC_GUESS;
    }
    std::vector<cv::Mat> rvecs, tvecs;
    cv::Mat std_intrinsics, std_extrinsics, view_errors;
    try {
      f.rms_px = cv::calibrateCamera(
          objects, images, size_, f.camera_matrix, f.distortion, rvecs, tvecs, std_intrinsics,
          std_extrinsics, view_errors, flags,
          cv::TermCriteria(cv::TermCriteria::COUNT + cv::TermCriteria::EPS, 200, 1e-12));
    } catch (const cv::Exception& e) {
      throw InputError("calibration failed (OpenCV: " + e.err + ")");
    }
    f.distortion = f.distortion.reshape(1, 1).colRange(0, 5).clone();
    for (int i = 0; i < view_errors.rows; ++i) f.view_rms_px.push_back(view_errors.at<double>(i));
    return f;
  }

  double view_squared_error(std::size_t i, const Fit& fit) const {
    return board_squared_error(object_, views_[i].corners, fit.camera_matrix, fit.distortion);
  }

  double view_rms(std::size_t i, const Fit& fit) const {
    return std::sqrt(view_squared_error(i, fit) / static_cast<double>(object_.size()));
  }

  // Held-out rms over `used` by k-fold cross-validation, for k3 fixed and free.
  std::pair<double, double> heldout_rms(const std::vector<std::size_t>& used, int folds) const {
    double fixed_sum = 0.0, free_sum = 0.0;
    std::size_t count = 0;
    for (int fold = 0; fold < folds; ++fold) {
      std::vector<std::size_t> train, test;
      for (std::size_t k = 0; k < used.size(); ++k) {
        (static_cast<int>(k % static_cast<std::size_t>(folds)) == fold ? test : train)
            .push_back(used[k]);
      }
      const Fit fixed = fit(train, false, nullptr);
      const Fit free = fit(train, true, &fixed);
      for (std::size_t i : test) {
        fixed_sum += view_squared_error(i, fixed);
        free_sum += view_squared_error(i, free);
        count += object_.size();
      }
    }
    return {std::sqrt(fixed_sum / static_cast<double>(count)),
            std::sqrt(free_sum / static_cast<double>(count))};
  }

 private:
  const std::vector<ChessboardView>& views_;
  std::vector<cv::Point3f> object_;
  cv::Size size_;
};

}  // namespace

double view_rms_px(const ChessboardView& view, const ChessboardPattern& pattern,
                   const PinholeCamera& camera) {
  const std::vector<cv::Point3f> object = pattern.object_points();
  require(view.corners.size() == object.size(), view.name,
          "expected " + std::to_string(object.size()) + " corners");
  return std::sqrt(board_squared_error(object, view.corners, cv::Mat(camera.camera_matrix()),
                                       camera.distortion_coefficients()) /
                   static_cast<double>(object.size()));
}

IntrinsicsResult calibrate_intrinsics(const std::vector<ChessboardView>& views,
                                      const ChessboardPattern& pattern, cv::Size image_size,
                                      const IntrinsicsOptions& options) {
  pattern.validate();
  options.validate();
  const std::size_t min_views = static_cast<std::size_t>(options.min_views);
  require(views.size() >= min_views, "calibration",
          "the board was found in " + std::to_string(views.size()) + " image(s), at least " +
              std::to_string(min_views) + " are needed");
  for (const ChessboardView& v : views) {
    require(v.corners.size() == pattern.object_points().size(), v.name,
            "expected " + std::to_string(pattern.object_points().size()) + " corners");
  }
  const Calibrator calibrator(views, pattern, image_size);

  // Drop the worst view while it stands out from the median, recalibrating each time.
  std::vector<std::size_t> used(views.size());
  std::iota(used.begin(), used.end(), 0);
  Fit fixed = calibrator.fit(used, false, nullptr);
  while (used.size() > min_views) {
    const auto worst = std::max_element(fixed.view_rms_px.begin(), fixed.view_rms_px.end());
    const double threshold =
        std::max(options.outlier_factor * median(fixed.view_rms_px), options.outlier_min_px);
    if (*worst <= threshold) break;
    used.erase(used.begin() + (worst - fixed.view_rms_px.begin()));
    fixed = calibrator.fit(used, false, nullptr);
  }

  IntrinsicsResult result;
  Fit chosen = fixed;
  if (used.size() >= min_views + 1) {
    const int folds = std::min(options.folds, static_cast<int>(used.size()));
    const auto [heldout_fixed, heldout_free] = calibrator.heldout_rms(used, folds);
    result.heldout_rms_fixed_k3_px = heldout_fixed;
    result.heldout_rms_free_k3_px = heldout_free;
    if (heldout_free < (1.0 - options.k3_min_gain) * heldout_fixed) {
      const Fit free = calibrator.fit(used, true, &fixed);
      if (free.rms_px <= fixed.rms_px) {  // never accept a worse minimum
        chosen = free;
        result.k3_free = true;
      }
    }
  }

  result.camera =
      PinholeCamera::from_opencv(cv::Matx33d(chosen.camera_matrix), chosen.distortion, image_size)
          .params();
  result.rms_px = chosen.rms_px;
  std::size_t next_used = 0;
  for (std::size_t i = 0; i < views.size(); ++i) {
    const bool is_used = next_used < used.size() && used[next_used] == i;
    result.views.push_back(
        {views[i].name, is_used ? chosen.view_rms_px[next_used] : calibrator.view_rms(i, chosen),
         !is_used});
    if (is_used) ++next_used;
  }
  return result;
}

}  // namespace ballsight
