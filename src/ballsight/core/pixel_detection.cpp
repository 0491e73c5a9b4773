#include "ballsight/core/pixel_detection.hpp"

namespace ballsight {

std::string_view object_class_name(ObjectClass object) {
  switch (object) {
    case ObjectClass::ball:
      return "ball";
    case ObjectClass::robot_front_marker:
      return "robot_front_marker";
    case ObjectClass::robot_back_marker:
      return "robot_back_marker";
    case ObjectClass::obstacle:
      return "obstacle";
  }
  return "unknown";
}

}  // namespace ballsight
