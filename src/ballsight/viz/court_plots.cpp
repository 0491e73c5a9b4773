#include "ballsight/viz/court_plots.hpp"

#include <cmath>
#include <opencv2/imgproc.hpp>

#include "ballsight/viz/chart.hpp"

namespace ballsight {

namespace {

cv::Point to_point(const Vec2& p) {
  return {static_cast<int>(std::lround(p.x())), static_cast<int>(std::lround(p.y()))};
}

const cv::Scalar kMistakeColour(200, 0, 200);  // magenta

}  // namespace

cv::Mat draw_detection_overlay(const cv::Mat& frame, const std::vector<Vec2>& truth_px,
                               const std::vector<DetectionLayer>& layers,
                               const std::vector<Vec2>& missed_px, const std::string& title) {
  cv::Mat image = frame.clone();
  for (const Vec2& p : truth_px)
    cv::circle(image, to_point(p), 9, cv::Scalar::all(255), 1, cv::LINE_AA);
  std::vector<LegendEntry> legend{{"true ball (seen)", cv::Scalar::all(255)}};
  for (size_t i = 0; i < layers.size(); ++i) {
    const DetectionLayer& layer = layers[i];
    const int size = 5 + 2 * static_cast<int>(i);
    for (const PixelDetection& d : layer.detections) {
      const cv::Point c = to_point(d.center_px);
      const int r = std::max(size, static_cast<int>(std::lround(d.radius_px)) + size - 3);
      if (d.object == ObjectClass::ball) {
        cv::circle(image, c, r, layer.colour, 1, cv::LINE_AA);
      } else {
        cv::rectangle(image, c - cv::Point(r, r), c + cv::Point(r, r), layer.colour, 1,
                      cv::LINE_AA);
      }
    }
    legend.push_back({layer.label, layer.colour});
  }
  for (const Vec2& p : missed_px) {
    cv::circle(image, to_point(p), 14, kMistakeColour, 2, cv::LINE_AA);
    draw_text(image, "M", to_point(p) + cv::Point(14, -10), 0.5, kMistakeColour);
  }
  if (!missed_px.empty()) legend.push_back({"missed by ballsight", kMistakeColour});
  cv::rectangle(image, {0, 0, image.cols, 28}, cv::Scalar::all(255), cv::FILLED);
  draw_text(image, title, {10, 20}, 0.55);
  draw_legend(image, {10, 40}, legend);
  return image;
}

namespace {

// Draws the court area, cameras, truth and layers into `image`.
void draw_map(cv::Mat& image, const MapView& px, const CourtFloor& floor,
              const std::vector<Vec3>& cameras, const std::vector<TrueBallMark>& truth,
              const Pose2D& robot_truth, const std::vector<WorldLayer>& layers) {
  draw_court_floor(image, px, floor);
  for (const Vec3& c : cameras)
    cv::drawMarker(image, px(c.head<2>()), cv::Scalar(40, 40, 40), cv::MARKER_TRIANGLE_UP, 14, 2);
  const double scale = px.pixels_per_m / 40.0;  // marks grow with the zoom
  const auto draw_robot = [&](const Pose2D& pose, const cv::Scalar& colour, int thickness) {
    const Vec2 forward(std::cos(pose.heading_rad), std::sin(pose.heading_rad));
    cv::arrowedLine(image, px(pose.position), px(pose.position + 0.8 * forward), colour, thickness,
                    cv::LINE_AA, 0, 0.25);
  };
  // The true robot's body (the simulator's 0.60 x 0.45 m box) and heading.
  std::vector<cv::Point> body;
  for (const Vec2& corner :
       {Vec2(0.3, 0.225), Vec2(-0.3, 0.225), Vec2(-0.3, -0.225), Vec2(0.3, -0.225)})
    body.push_back(px(robot_truth.field_from_robot() * corner));
  cv::polylines(image, body, true, cv::Scalar(20, 20, 20), 1, cv::LINE_AA);
  for (const TrueBallMark& t : truth)
    cv::circle(image, px(t.position_m),
               static_cast<int>(std::lround(std::max(4.0, 0.0335 * px.pixels_per_m))),
               t.seen ? cv::Scalar(20, 20, 20) : cv::Scalar(150, 150, 150), 1, cv::LINE_AA);
  draw_robot(robot_truth, cv::Scalar(20, 20, 20), 3);
  for (size_t i = 0; i < layers.size(); ++i) {
    const WorldLayer& layer = layers[i];
    for (const CollectionSite& site : layer.world.sites) {
      if (site.balls.size() < 2) continue;
      const double r = std::max(0.5 * site.diameter_m + 0.12, 0.15) * px.pixels_per_m;
      cv::circle(image, px(site.center_m), static_cast<int>(r), layer.colour, 1, cv::LINE_AA);
    }
    const int marker = i == 0 ? cv::MARKER_TILTED_CROSS : cv::MARKER_CROSS;
    for (const FusedBall& ball : layer.world.balls)
      cv::drawMarker(image, px(ball.position_m), layer.colour, marker,
                     static_cast<int>(std::lround(7 * std::sqrt(scale))), 1, cv::LINE_AA);
    if (layer.world.robot) draw_robot(layer.world.robot->pose, layer.colour, 1);
    for (const MistakeMark& mistake : layer.mistakes) {
      const cv::Point2d at = px(mistake.position_m);
      cv::circle(image, at, static_cast<int>(std::lround(12 * std::sqrt(scale))), kMistakeColour, 2,
                 cv::LINE_AA);
      draw_text(image, std::string(1, mistake.letter),
                to_point(Vec2(at.x + 14 * std::sqrt(scale), at.y - 6)), 0.5, kMistakeColour);
    }
  }
}

}  // namespace

cv::Mat draw_field_map(const CourtFloor& floor, const std::vector<Vec3>& cameras,
                       const std::vector<TrueBallMark>& truth, const Pose2D& robot_truth,
                       const std::vector<WorldLayer>& layers, const std::string& title,
                       double pixels_per_m) {
  const double margin_m = 1.5;
  const Vec2 half = 0.5 * (floor.surround.max_m - floor.surround.min_m) + Vec2(margin_m, margin_m);
  std::vector<LegendEntry> legend{
      {"true balls and robot (grey: seen by no camera)", cv::Scalar(20, 20, 20)}};
  for (const WorldLayer& layer : layers) {
    legend.push_back({layer.label, layer.colour});
    if (!layer.mistakes.empty())
      legend.push_back({layer.label.substr(0, layer.label.find(' ')) +
                            "'s mistakes: M missed, D duplicate, F false positive",
                        kMistakeColour});
  }
  const int top = 36 + 22 * static_cast<int>(legend.size());  // title and legend
  const int width = static_cast<int>(std::lround(2 * half.x() * pixels_per_m));
  const int map_height = static_cast<int>(std::lround(2 * half.y() * pixels_per_m));
  const double zoom = 5.0 * pixels_per_m;  // the inset below the map
  const int height = top + map_height + static_cast<int>(2.0 * zoom) + 20;
  cv::Mat image(height, width, CV_8UC3, cv::Scalar(235, 235, 235));
  draw_map(image, {Vec2(-half.x(), half.y()), pixels_per_m, {0.0, static_cast<double>(top)}}, floor,
           cameras, truth, robot_truth, layers);

  // Inset below the map: 3 x 2 m around the true robot, five times larger, where it hides balls.
  const cv::Rect inset((width - static_cast<int>(3.0 * zoom)) / 2, top + map_height + 10,
                       static_cast<int>(3.0 * zoom), static_cast<int>(2.0 * zoom));
  cv::Mat area = image(inset);
  area.setTo(cv::Scalar(235, 235, 235));
  draw_map(area, {robot_truth.position + Vec2(-1.5, 1.0), zoom, {0.0, 0.0}}, floor, cameras, truth,
           robot_truth, layers);
  cv::rectangle(image, inset, cv::Scalar(30, 30, 30), 2);
  draw_text(image, "3 x 2 m around the robot", {inset.x + 6, inset.br().y - 8}, 0.5,
            cv::Scalar(255, 255, 255));

  cv::rectangle(image, {0, 0, image.cols, top}, cv::Scalar::all(255), cv::FILLED);
  draw_text(image, title, {10, 24}, 0.6);
  draw_legend(image, {10, 32}, legend);
  return image;
}

}  // namespace ballsight
