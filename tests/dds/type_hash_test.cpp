#include "ballsight/dds/type_hash.hpp"

#include <gtest/gtest.h>

#include "ballsight/dds/message_types.hpp"

namespace ballsight::dds {
namespace {

// The hashes ROS 2 Jazzy's generated code carries (rosidl_generator_c's `*__TYPE_HASH`, e.g.
// micro-ROS/micro_ros_arduino pose_stamped__struct.h, diagnostic_msgs'
// detail/diagnostic_array__struct.h): ballsight's implementation must give the same.
TEST(TypeHash, MatchesTheHashesRos2Generates) {
  EXPECT_EQ(message_type_hash("geometry_msgs/msg/PoseStamped"),
            "RIHS01_10f3786d7d40fd2b54367835614bff85d4ad3b5dab62bf8bca0cc232d73b4cd8");
  EXPECT_EQ(message_type_hash("nav_msgs/msg/Path"),
            "RIHS01_1957a5bb3cee5da65c4e52e52b65a93df227efce4c20f8458b36e73066ca334b");
  EXPECT_EQ(message_type_hash("diagnostic_msgs/msg/DiagnosticArray"),
            "RIHS01_5a8a36efb05fb25070fa0fb3810290c0e6cd4862b54a8fb975a1ee8dc55a333e");
  EXPECT_EQ(message_type_hash("builtin_interfaces/msg/Time"),
            "RIHS01_b106235e25a4c5ed35098aa0a61a3ee9c9b18d197f398b0e4206cea9acf9c197");
}

TEST(TypeHash, ChangesWithAFieldAndRefusesAnUnknownType) {
  const std::vector<TypeDescription> a{
      {"p/msg/A", {{"x", FieldType::float64, FieldShape::single, 0, ""}}}};
  const std::vector<TypeDescription> b{
      {"p/msg/A", {{"y", FieldType::float64, FieldShape::single, 0, ""}}}};
  const std::vector<TypeDescription> c{
      {"p/msg/A", {{"x", FieldType::float32, FieldShape::single, 0, ""}}}};
  EXPECT_NE(ros_type_hash("p/msg/A", a), ros_type_hash("p/msg/A", b));
  EXPECT_NE(ros_type_hash("p/msg/A", a), ros_type_hash("p/msg/A", c));
  EXPECT_THROW(message_type_hash("geometry_msgs/msg/Twist"), std::logic_error);
  const std::vector<TypeDescription> dangling{
      {"p/msg/B", {{"a", FieldType::nested, FieldShape::single, 0, "p/msg/Missing"}}}};
  EXPECT_THROW(ros_type_hash("p/msg/B", dangling), std::logic_error);
}

}  // namespace
}  // namespace ballsight::dds
