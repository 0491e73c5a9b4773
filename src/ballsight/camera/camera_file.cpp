#include "ballsight/camera/camera_file.hpp"

#include <algorithm>
#include <cmath>
#include <opencv2/core/persistence.hpp>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"
#include "ballsight/core/yaml_reader.hpp"

namespace ballsight {

namespace {

// Reads typed values from the top level of a parsed file; every error names the file, the line
// and the key. Keys nobody asks for (ROS's projection_matrix, OpenCV's calibration_time) are
// allowed: camera files come from other tools.
class KeyReader {
 public:
  explicit KeyReader(YamlMap root) : root_(std::move(root)) {}

  bool has(const char* key) { return root_.find(key).has_value(); }
  [[noreturn]] void fail(const char* key, const std::string& what) { root_.at(key).fail(what); }
  int integer(const char* key) { return root_.at(key).integer(); }
  double real(const char* key) { return root_.at(key).number(); }
  std::string text(const char* key) { return root_.at(key).text(); }

  // A matrix written as {rows, cols, data: [...]}: OpenCV's !!opencv-matrix and ROS's layout alike.
  std::vector<double> matrix(const char* key, int* rows_out = nullptr, int* cols_out = nullptr) {
    const YamlValue value = root_.at(key);
    if (!value.is_map()) value.fail("expected a matrix {rows, cols, data: [numbers]}");
    YamlMap m = value.map();
    const int r = m.at("rows").integer(), c = m.at("cols").integer();
    const YamlValue data = m.at("data");
    if (!data.is_list()) data.fail("expected a list of numbers");
    if (r < 1 || c < 1 ||
        static_cast<std::size_t>(r) * static_cast<std::size_t>(c) != data.node().size()) {
      value.fail("has " + std::to_string(data.node().size()) + " values for " + std::to_string(r) +
                 "x" + std::to_string(c));
    }
    if (rows_out != nullptr) *rows_out = r;
    if (cols_out != nullptr) *cols_out = c;
    return data.numbers(data.node().size());
  }

  Vec3 vec3(const char* key) {
    const std::vector<double> v = matrix(key);
    if (v.size() != 3) fail(key, "expected 3 values, got " + std::to_string(v.size()));
    return {v[0], v[1], v[2]};
  }

 private:
  YamlMap root_;
};

PinholeParams read_intrinsics(KeyReader& keys, std::size_t required_distortion_count) {
  PinholeParams p;
  p.width = keys.integer("image_width");
  p.height = keys.integer("image_height");
  if (p.width <= 0) keys.fail("image_width", "must be positive");
  if (p.height <= 0) keys.fail("image_height", "must be positive");

  int rows = 0, cols = 0;
  const std::vector<double> k = keys.matrix("camera_matrix", &rows, &cols);
  if (rows != 3 || cols != 3) keys.fail("camera_matrix", "expected a 3x3 matrix");
  if (k[1] != 0.0 || k[3] != 0.0 || k[6] != 0.0 || k[7] != 0.0 || k[8] != 1.0) {
    keys.fail("camera_matrix", "expected [fx 0 cx; 0 fy cy; 0 0 1]");
  }
  p.fx = k[0];
  p.fy = k[4];
  p.cx = k[2];
  p.cy = k[5];
  if (!(p.fx > 0.0 && p.fy > 0.0)) keys.fail("camera_matrix", "focal lengths must be positive");

  const std::vector<double> d = keys.matrix("distortion_coefficients");
  const bool count_ok = required_distortion_count != 0
                            ? d.size() == required_distortion_count
                            : (d.size() == 4 || d.size() == 5 || d.size() == 8);
  if (!count_ok) {
    keys.fail("distortion_coefficients",
              "expected " +
                  (required_distortion_count != 0 ? std::to_string(required_distortion_count)
                                                  : std::string("4, 5 or 8")) +
                  " values, got " + std::to_string(d.size()));
  }
  for (std::size_t i = 0; i < d.size(); ++i) p.distortion[i] = d[i];
  return p;
}

// ROS camera_info: plumb_bob is k1 k2 t1 t2 k3, rational_polynomial k1 k2 t1 t2 k3 k4 k5 k6,
// both in OpenCV's order.
std::size_t ros_distortion_count(KeyReader& keys) {
  const std::string model = keys.text("distortion_model");
  if (model == "plumb_bob") return 5;
  if (model == "rational_polynomial") return 8;
  keys.fail("distortion_model", "expected plumb_bob or rational_polynomial, got '" + model + "'");
}

std::optional<CameraExtrinsics> read_extrinsics(KeyReader& keys) {
  if (!keys.has("rvec") && !keys.has("tvec")) return std::nullopt;
  CameraExtrinsics e;
  e.camera_from_field = Rigid3::from_rvec_tvec(keys.vec3("rvec"), keys.vec3("tvec"));
  if (keys.has("extrinsics_reprojection_error")) {
    e.reprojection_error_px = keys.real("extrinsics_reprojection_error");
  }
  if (keys.has("extrinsics_reference_count")) {
    e.reference_count = keys.integer("extrinsics_reference_count");
  }
  return e;
}

cv::Mat column(const std::vector<double>& values) {
  return cv::Mat(values, true).reshape(1, static_cast<int>(values.size()));
}

}  // namespace

CameraFile parse_camera_file(std::string_view text, const std::string& name) {
  // Read with yaml-cpp, not OpenCV: OpenCV 4.6's reader never returns on some malformed text
  // (fuzzing found two: docs/RESULTS.md, "Fuzzing"). OpenCV's own directive ("%YAML:1.0") is not
  // YAML's: it is dropped, its line kept so that lines count as in the file.
  const bool has_directive = text.substr(0, 5) == "%YAML";
  KeyReader keys(YamlMap::parse(
      has_directive ? text.substr(std::min(text.find('\n'), text.size())) : text, name));

  CameraFile file;
  const bool ros = keys.has("distortion_model");
  file.format = ros ? CameraFileFormat::ros_camera_info : CameraFileFormat::opencv;
  CameraCalibration& c = file.calibration;
  c.intrinsics = read_intrinsics(keys, ros ? ros_distortion_count(keys) : 0);
  try {
    PinholeCamera checked(c.intrinsics);
  } catch (const InputError& e) {
    keys.fail("distortion_coefficients", e.what());
  }
  if (keys.has("avg_reprojection_error")) {
    c.avg_reprojection_error_px = keys.real("avg_reprojection_error");
  }
  c.extrinsics = read_extrinsics(keys);
  return file;
}

CameraCalibration read_camera_file(const std::filesystem::path& path) {
  return parse_camera_file(read_file(path, kMaxDocumentBytes), path.string()).calibration;
}

std::string camera_file_text(const CameraCalibration& calibration) {
  const PinholeParams& p = calibration.intrinsics;
  cv::FileStorage out(
      ".yml", cv::FileStorage::WRITE | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  out.writeComment("ballsight camera calibration (OpenCV key names; docs/site-file.md)");
  out << "image_width" << p.width << "image_height" << p.height;
  out << "camera_matrix" << cv::Mat(cv::Matx33d(p.fx, 0, p.cx, 0, p.fy, p.cy, 0, 0, 1));
  const bool rational = p.distortion[5] != 0.0 || p.distortion[6] != 0.0 || p.distortion[7] != 0.0;
  out << "distortion_coefficients"
      << column(
             std::vector<double>(p.distortion.begin(), p.distortion.begin() + (rational ? 8 : 5)));
  if (calibration.avg_reprojection_error_px) {
    out << "avg_reprojection_error" << *calibration.avg_reprojection_error_px;
  }
  if (const auto& e = calibration.extrinsics) {
    out.writeComment(
        "camera_from_field: p_in_camera = R(rvec) * p_in_field + tvec (OpenCV axis-angle, metres)");
    const Vec3 rvec = e->camera_from_field.rvec();
    const Vec3& tvec = e->camera_from_field.translation;
    out << "rvec" << column({rvec.x(), rvec.y(), rvec.z()});
    out << "tvec" << column({tvec.x(), tvec.y(), tvec.z()});
    out << "extrinsics_reprojection_error" << e->reprojection_error_px;
    out << "extrinsics_reference_count" << e->reference_count;
  }
  return out.releaseAndGetString();
}

void write_camera_file(const std::filesystem::path& path, const CameraCalibration& calibration) {
  write_file_atomic(path, camera_file_text(calibration));
}

}  // namespace ballsight
