#pragma once
// The court service's values as Foxglove messages in JSON (https://docs.foxglove.dev/docs/
// visualization/message-schemas): the court and the balls as foxglove.SceneUpdate, the robot as
// foxglove.PoseInFrame, the route as foxglove.PosesInFrame, a camera's frame as
// foxglove.CompressedImage and its detections as foxglove.ImageAnnotations, each with the JSON
// Schema of the fields ballsight fills. Used live (net/foxglove.hpp, the WebSocket bridge) and in
// recordings (service/run_recorder.hpp). Positions in the "court" frame: metres, origin at the
// court's centre.

#include <cstdint>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

#include "ballsight/core/pixel_detection.hpp"
#include "ballsight/core/site_court.hpp"
#include "ballsight/plan/planning_problem.hpp"
#include "ballsight/world/world_model.hpp"

namespace ballsight::foxglove {

/// The frame every pose is in.
inline constexpr const char* kCourtFrame = "court";

nlohmann::json scene_update_schema();
nlohmann::json pose_in_frame_schema();
nlohmann::json poses_in_frame_schema();
nlohmann::json compressed_image_schema();
nlohmann::json image_annotations_schema();
/// ballsight.NavigationUpdate (service/navigation_json.hpp).
nlohmann::json navigation_update_schema();

/// {"sec", "nsec"} of a time in ns.
nlohmann::json stamp(std::int64_t time_ns);

/// The court's lines, its fenced area and the net.
nlohmann::json court_scene(const SiteCourt& court, std::int64_t time_ns);
/// The world's balls as spheres of the ball's size.
nlohmann::json balls_scene(const WorldModel& world, double ball_radius_m, std::int64_t time_ns);
/// The robot's pose; nothing when the world has no robot.
std::optional<nlohmann::json> robot_pose(const WorldModel& world, std::int64_t time_ns);
/// The route's waypoints, each heading to the next.
nlohmann::json route_poses(const Route& route, std::int64_t time_ns);
/// A frame of camera `frame_id` encoded as `format` ("jpeg" or "png"; its bytes base64 in "data",
/// as Foxglove's JSON encoding carries bytes).
nlohmann::json compressed_image(std::string_view bytes, std::string_view format,
                                const std::string& frame_id, std::int64_t time_ns);
/// A circle per detection (balls yellow, the robot's markers red and blue, obstacles grey), in
/// Foxglove's image coordinates (origin at the top-left pixel's corner).
nlohmann::json image_annotations(const std::vector<PixelDetection>& detections,
                                 std::int64_t time_ns);

}  // namespace ballsight::foxglove
