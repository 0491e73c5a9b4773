#pragma once
// Cameras the camera tests share: a wide HD pinhole with strong barrel distortion, and a unified
// (mirror) camera of any xi with a mild lens.

#include "ballsight/camera/pinhole.hpp"
#include "ballsight/camera/unified.hpp"

namespace ballsight::test {

inline PinholeParams wide_hd_camera() {
  PinholeParams p;
  p.width = 1280;
  p.height = 720;
  p.fx = 900.0;
  p.fy = 905.0;
  p.cx = 644.0;
  p.cy = 356.0;
  p.distortion = {-0.32, 0.12, 0.0008, -0.0005, -0.02, 0, 0, 0};
  return p;
}

inline UnifiedParams mirror_camera(double xi) {
  UnifiedParams p;
  p.width = 640;
  p.height = 480;
  p.xi = xi;
  p.fx = 128.0;
  p.fy = 130.0;
  p.cx = 322.0;
  p.cy = 237.0;
  p.k1 = -0.05;
  p.k2 = 0.01;
  p.p1 = 0.001;
  p.p2 = -0.0005;
  return p;
}

}  // namespace ballsight::test
