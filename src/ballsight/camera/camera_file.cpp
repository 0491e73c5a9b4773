#include "ballsight/camera/camera_file.hpp"

#include <yaml-cpp/yaml.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <opencv2/core/persistence.hpp>
#include <vector>

#include "ballsight/core/error.hpp"
#include "ballsight/core/file_io.hpp"

namespace ballsight {

namespace {

// Reads typed values from the top level of a parsed file; every error names the file and key.
class KeyReader {
 public:
  KeyReader(const cv::FileNode& root, const std::string& name) : root_(root), name_(name) {}

  bool has(const char* key) const { return !root_[key].empty(); }

  [[noreturn]] void fail(const char* key, const std::string& what) const {
    throw InputError(name_ + ": key '" + key + "' " + what);
  }

  cv::FileNode node(const char* key) const {
    cv::FileNode n = root_[key];
    if (n.empty()) fail(key, "missing");
    return n;
  }

  int integer(const char* key) const {
    const cv::FileNode n = node(key);
    if (!n.isInt()) fail(key, "expected an integer");
    return static_cast<int>(n);
  }

  double real(const char* key) const {
    const cv::FileNode n = node(key);
    if (!n.isInt() && !n.isReal()) fail(key, "expected a number");
    const double value = static_cast<double>(n);
    if (!std::isfinite(value)) fail(key, "expected a finite number");
    return value;
  }

  std::string text(const char* key) const {
    const cv::FileNode n = node(key);
    if (!n.isString()) fail(key, "expected a string");
    return static_cast<std::string>(n);
  }

  // A matrix written as {rows, cols, data: [...]}: OpenCV's !!opencv-matrix and ROS's layout alike.
  std::vector<double> matrix(const char* key, int* rows_out = nullptr,
                             int* cols_out = nullptr) const {
    const cv::FileNode n = node(key);
    const std::string expected = "expected a matrix {rows, cols, data: [numbers]}";
    if (!n.isMap()) fail(key, expected);
    const cv::FileNode rows = n["rows"], cols = n["cols"], data = n["data"];
    if (!rows.isInt() || !cols.isInt() || !data.isSeq()) fail(key, expected);
    const int r = static_cast<int>(rows), c = static_cast<int>(cols);
    if (r < 1 || c < 1 ||
        static_cast<std::size_t>(r) * static_cast<std::size_t>(c) != data.size()) {
      fail(key, "has " + std::to_string(data.size()) + " values for " + std::to_string(r) + "x" +
                    std::to_string(c));
    }
    std::vector<double> values;
    for (const cv::FileNode& v : data) {
      if (!v.isInt() && !v.isReal()) fail(key, expected);
      values.push_back(static_cast<double>(v));
      if (!std::isfinite(values.back())) fail(key, "has a value that is not finite");
    }
    if (rows_out != nullptr) *rows_out = r;
    if (cols_out != nullptr) *cols_out = c;
    return values;
  }

  Vec3 vec3(const char* key) const {
    const std::vector<double> v = matrix(key);
    if (v.size() != 3) fail(key, "expected 3 values, got " + std::to_string(v.size()));
    return {v[0], v[1], v[2]};
  }

 private:
  cv::FileNode root_;
  const std::string& name_;
};

PinholeParams read_intrinsics(const KeyReader& keys, std::size_t required_distortion_count) {
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
std::size_t ros_distortion_count(const KeyReader& keys) {
  const std::string model = keys.text("distortion_model");
  if (model == "plumb_bob") return 5;
  if (model == "rational_polynomial") return 8;
  keys.fail("distortion_model", "expected plumb_bob or rational_polynomial, got '" + model + "'");
}

std::optional<CameraExtrinsics> read_extrinsics(const KeyReader& keys) {
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

// OpenCV 4.6 puts a YAML parse error's "(line): what" where the function name belongs;
// `added_lines` were prepended to the user's text.
std::string parse_error_text(const cv::Exception& e, int added_lines) {
  if (e.code == cv::Error::StsParseError && e.func.rfind("(", 0) == 0) {
    const std::size_t close = e.func.find("): ");
    if (close != std::string::npos) {
      const int line = std::atoi(e.func.substr(1, close - 1).c_str()) - added_lines;
      return "line " + std::to_string(line) + ": " + e.func.substr(close + 3);
    }
  }
  return e.err;
}

// OpenCV 4.6's YAML reader never returns on some malformed text (fuzzing found two:
// docs/RESULTS.md, "Fuzzing"): the text must be YAML, by yaml-cpp, before OpenCV reads it. That
// refuses the first; the second (a line less indented than the mapping before it) yaml-cpp accepts,
// and it still hangs OpenCV: reading the keys with yaml-cpp instead of OpenCV is the cure, not done
// yet. `body`: the text without OpenCV's own directive ("%YAML:1.0"), which is not YAML's.
void require_yaml(std::string_view body, const std::string& name) {
  try {
    YAML::Load(std::string(body));
  } catch (const YAML::Exception& e) {
    throw InputError(name + ": not a readable YAML file (line " + std::to_string(e.mark.line + 1) +
                     ": " + e.msg + ")");
  }
}

cv::Mat column(const std::vector<double>& values) {
  return cv::Mat(values, true).reshape(1, static_cast<int>(values.size()));
}

}  // namespace

CameraFile parse_camera_file(std::string_view text, const std::string& name) {
  // OpenCV recognises YAML in memory by its directive; ROS files have none.
  const bool has_directive = text.substr(0, 5) == "%YAML";
  require_yaml(has_directive ? text.substr(std::min(text.find('\n'), text.size())) : text, name);
  const std::string yaml = has_directive ? std::string(text) : "%YAML:1.0\n" + std::string(text);
  cv::FileStorage storage;
  try {
    storage.open(yaml,
                 cv::FileStorage::READ | cv::FileStorage::MEMORY | cv::FileStorage::FORMAT_YAML);
  } catch (const cv::Exception& e) {
    throw InputError(name + ": not a readable YAML file (" +
                     parse_error_text(e, has_directive ? 0 : 1) + ")");
  }
  require(storage.isOpened() && storage.root().isMap(), name, "not a YAML map of calibration keys");
  const KeyReader keys(storage.root(), name);

  CameraFile file;
  const bool ros = keys.has("distortion_model");
  file.format = ros ? CameraFileFormat::ros_camera_info : CameraFileFormat::opencv;
  CameraCalibration& c = file.calibration;
  c.intrinsics = read_intrinsics(keys, ros ? ros_distortion_count(keys) : 0);
  try {
    PinholeCamera checked(c.intrinsics);
  } catch (const InputError& e) {
    throw InputError(name + ": key 'distortion_coefficients' " + e.what());
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
