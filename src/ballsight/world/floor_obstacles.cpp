#include "ballsight/world/floor_obstacles.hpp"

#include <algorithm>
#include <cmath>
#include <deque>
#include <opencv2/imgproc.hpp>

#include "ballsight/core/error.hpp"

namespace ballsight {
namespace {

using ViewLists = std::vector<std::optional<std::vector<PixelDetection>>>;

/// The floor cells of `area`, row-major.
struct CellGrid {
  FieldRect area;
  double cell_m = 0.1;
  int cols = 0, rows = 0;

  CellGrid(const FieldRect& a, double cell) : area(a), cell_m(cell) {
    cols = static_cast<int>(std::ceil((area.max_m.x() - area.min_m.x()) / cell_m));
    rows = static_cast<int>(std::ceil((area.max_m.y() - area.min_m.y()) / cell_m));
  }
  std::size_t index(int col, int row) const {
    return static_cast<std::size_t>(row) * static_cast<std::size_t>(cols) +
           static_cast<std::size_t>(col);
  }
  Vec2 center(int col, int row) const { return area.min_m + cell_m * Vec2(col + 0.5, row + 0.5); }
};

/// Whether one of a camera's obstacle `views` covers `pixel` or the pixel `rise_px` above it: a
/// floor point under an object far away lies within a pixel or two of its foot in the image.
bool covered(const std::vector<const PixelDetection*>& views, const Vec2& pixel, int rise_px) {
  const int x = static_cast<int>(std::floor(pixel.x()));
  const int y0 = static_cast<int>(std::floor(pixel.y()));
  for (const int y : {y0, y0 - rise_px}) {
    for (const PixelDetection* d : views) {
      const CoveragePatch& p = d->patch;
      if (x >= p.x && y >= p.y && x < p.x + p.width && y < p.y + p.height && p.at(x, y) >= 0.5f)
        return true;
    }
  }
  return false;
}

/// Where each column of a view meets the floor: its lowest covered pixel's bottom edge, on the
/// floor.
std::vector<Vec2> feet(const FieldCamera& camera, const PixelDetection& view, int min_step_px,
                       int max_feet) {
  std::vector<Vec2> out;
  const CoveragePatch& p = view.patch;
  const int step = std::max(min_step_px, (p.width + max_feet - 1) / max_feet);
  for (int x = p.x; x < p.x + p.width; x += step) {
    for (int y = p.y + p.height - 1; y >= p.y; --y) {
      if (p.at(x, y) < 0.5f) continue;
      if (const std::optional<Vec3> floor = camera.point_at_height(Vec2(x + 0.5, y + 1.0), 0.0))
        out.push_back(floor->head<2>());
      break;
    }
  }
  return out;
}

bool in_box(const FloorBox& box, const Vec2& p) {
  const Vec2 local = box.pose.field_from_robot().inverse() * p;
  return std::abs(local.x()) <= box.half_size.x() && std::abs(local.y()) <= box.half_size.y();
}

FloorObstacle obstacle_of(const CellGrid& grid, const std::vector<std::pair<int, int>>& cells,
                          std::vector<int> cameras) {
  FloorObstacle o;
  std::vector<cv::Point2f> corners, hull;
  for (const auto& [col, row] : cells) {
    o.center_m += grid.center(col, row);
    for (const double dx : {-0.5, 0.5})
      for (const double dy : {-0.5, 0.5}) {
        const Vec2 c = grid.center(col, row) + grid.cell_m * Vec2(dx, dy);
        corners.emplace_back(static_cast<float>(c.x()), static_cast<float>(c.y()));
      }
  }
  o.center_m /= static_cast<double>(cells.size());
  cv::convexHull(corners, hull, /*clockwise=*/false);
  for (const cv::Point2f& p : hull) {
    o.outline_m.emplace_back(p.x, p.y);
    o.radius_m = std::max(o.radius_m, (o.outline_m.back() - o.center_m).norm());
  }
  std::sort(cameras.begin(), cameras.end());
  cameras.erase(std::unique(cameras.begin(), cameras.end()), cameras.end());
  o.cameras = std::move(cameras);
  return o;
}

}  // namespace

void FloorObstacleOptions::validate() const {
  const auto in = [](double v, double lo, double hi) {
    return std::isfinite(v) && v >= lo && v <= hi;
  };
  require(in(cell_m, 0.02, 0.5), "obstacles.cell_m", "must be in [0.02, 0.5] m");
  require(in(search_m, cell_m, 3.0), "obstacles.search_m", "must be in [cell_m, 3] m");
  require(min_cells >= 1, "obstacles.min_cells", "must be at least 1");
  require(in(robot_margin_m, 0.0, 2.0), "obstacles.robot_margin_m", "must be in [0, 2] m");
  require(in(ball_margin_m, 0.0, 1.0), "obstacles.ball_margin_m", "must be in [0, 1] m");
  require(column_step_px >= 1, "obstacles.column_step_px", "must be at least 1");
  require(max_feet_per_view >= 1, "obstacles.max_feet_per_view", "must be at least 1");
  require(in(ball_feet_m, 0.0, 1.0), "obstacles.ball_feet_m", "must be in [0, 1] m");
  if (net) net->validate();
}

std::vector<FloorObstacle> locate_floor_obstacles(const std::vector<FieldCamera>& cameras,
                                                  const ViewLists& detections,
                                                  const std::optional<Pose2D>& robot,
                                                  const RobotModel& robot_model,
                                                  const std::vector<FusedBall>& balls,
                                                  const FieldRect& area,
                                                  const FloorObstacleOptions& options) {
  options.validate();
  require_list_per_camera(cameras.size(), detections.size(), "floor obstacles");
  std::vector<std::vector<const PixelDetection*>> views(cameras.size());  // not copied: patches
  bool any = false;
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    if (!detections[c]) continue;
    for (const PixelDetection& d : *detections[c])
      if (d.object == ObjectClass::obstacle && d.patch.width > 0) views[c].push_back(&d);
    any = any || !views[c].empty();
  }
  if (!any) return {};

  const CellGrid grid(area, options.cell_m);
  std::vector<Vec3> eyes;
  for (const FieldCamera& camera : cameras) eyes.push_back(camera.center_in_field());
  // Occupied: every camera that sees the cell but at most one shows something there (two at
  // least); firmly so when all of them do.
  enum : std::uint8_t { kUnseen, kLooked, kOccupied, kFirm };
  std::vector<std::uint8_t> state(static_cast<std::size_t>(grid.cols) * grid.rows, kUnseen);
  std::vector<std::vector<int>> voters(state.size());  // of occupied cells
  const std::optional<FloorBox> body =
      robot ? std::optional<FloorBox>(robot_model.body(*robot, options.robot_margin_m))
            : std::nullopt;
  const auto left_out = [&](const Vec2& p) {
    if (body && in_box(*body, p)) return true;
    return std::any_of(balls.begin(), balls.end(), [&](const FusedBall& b) {
      return (b.position_m - p).norm() < options.ball_margin_m;
    });
  };
  const auto look = [&](int col, int row) {
    const std::size_t i = grid.index(col, row);
    if (state[i] != kUnseen) return;
    state[i] = kLooked;
    const Vec2 p = grid.center(col, row);
    if (left_out(p)) return;
    int seeing = 0;
    std::vector<int> votes;
    const Vec3 floor(p.x(), p.y(), 0.0);
    for (std::size_t c = 0; c < cameras.size(); ++c) {
      if (!detections[c] || (options.net && options.net->hides(eyes[c], floor))) continue;
      const std::optional<Vec2> px = cameras[c].pixel_from_field(floor);
      if (!px || px->x() < 0.0 || px->y() < 0.0 || px->x() >= cameras[c].camera.width() ||
          px->y() >= cameras[c].camera.height())
        continue;
      ++seeing;
      if (covered(views[c], *px, options.foot_rise_px)) votes.push_back(static_cast<int>(c));
    }
    const int n = static_cast<int>(votes.size());
    if (n >= 2 && n >= seeing - 1) {
      state[i] = n == seeing ? kFirm : kOccupied;
      voters[i] = std::move(votes);
    }
  };
  const int reach = static_cast<int>(std::ceil(options.search_m / options.cell_m));
  for (std::size_t c = 0; c < cameras.size(); ++c) {
    for (const PixelDetection* view : views[c]) {
      for (const Vec2& foot :
           feet(cameras[c], *view, options.column_step_px, options.max_feet_per_view)) {
        // The feet of the robot's and the balls' own views are not looked round.
        if (!area.contains(foot) || (body && in_box(*body, foot)) ||
            std::any_of(balls.begin(), balls.end(), [&](const FusedBall& b) {
              return (b.position_m - foot).norm() < options.ball_feet_m;
            })) {
          continue;
        }
        const int col0 = static_cast<int>((foot.x() - area.min_m.x()) / options.cell_m);
        const int row0 = static_cast<int>((foot.y() - area.min_m.y()) / options.cell_m);
        for (int row = std::max(0, row0 - reach); row <= std::min(grid.rows - 1, row0 + reach);
             ++row)
          for (int col = std::max(0, col0 - reach); col <= std::min(grid.cols - 1, col0 + reach);
               ++col)
            if ((grid.center(col, row) - foot).norm() <= options.search_m) look(col, row);
      }
    }
  }

  // Occupied cells that touch (8-neighbours), one obstacle each: its footprint the firm cells
  // when there are enough of them (the others are mostly the floor behind it that two cameras'
  // views share), else all (a camera missed it: it stands behind the net from there, or wears the
  // floor's colour).
  const auto occupied = [&](int col, int row) { return state[grid.index(col, row)] >= kOccupied; };
  std::vector<FloorObstacle> out;
  for (int row = 0; row < grid.rows; ++row) {
    for (int col = 0; col < grid.cols; ++col) {
      if (!occupied(col, row)) continue;
      std::vector<std::pair<int, int>> cells, firm;
      std::vector<int> cameras_seen;
      std::deque<std::pair<int, int>> open;
      const auto take = [&](int c, int r) {
        if (state[grid.index(c, r)] == kFirm) firm.emplace_back(c, r);
        state[grid.index(c, r)] = kLooked;
        open.emplace_back(c, r);
      };
      take(col, row);
      while (!open.empty()) {
        const auto [c, r] = open.front();
        open.pop_front();
        cells.emplace_back(c, r);
        const std::vector<int>& v = voters[grid.index(c, r)];
        cameras_seen.insert(cameras_seen.end(), v.begin(), v.end());
        for (int dr = -1; dr <= 1; ++dr)
          for (int dc = -1; dc <= 1; ++dc) {
            const int nc = c + dc, nr = r + dr;
            if (nc >= 0 && nr >= 0 && nc < grid.cols && nr < grid.rows && occupied(nc, nr))
              take(nc, nr);
          }
      }
      if (static_cast<int>(cells.size()) < options.min_cells) continue;
      const bool firm_enough = static_cast<int>(firm.size()) >= options.min_cells;
      out.push_back(obstacle_of(grid, firm_enough ? firm : cells, std::move(cameras_seen)));
    }
  }
  return out;
}

}  // namespace ballsight
