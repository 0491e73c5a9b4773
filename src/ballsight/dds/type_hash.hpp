#pragma once
// ROS 2's type hash (REP-2011, "RIHS01_<sha256 hex>") from a message's type description: what a
// ROS 2 Jazzy node expects in an endpoint's USER_DATA ("typehash=RIHS01_...;"), else it logs a
// warning per endpoint (research note net-web.md §1). The algorithm of ros2/rosidl
// `rosidl_generator_type_description/__init__.py::calculate_type_hash`: the JSON of the type's
// fields and of every type it refers to (sorted by name, default values left out, separators
// ", " and ": "), hashed with SHA-256.

#include <string>
#include <vector>

namespace ballsight::dds {

/// rosidl's field type ids (type_description_interfaces/msg/FieldType.msg).
enum class FieldType : int {
  nested = 1,
  uint8 = 3,
  int32 = 6,
  uint32 = 7,
  uint64 = 9,
  float32 = 10,
  float64 = 11,
  boolean = 15,
  byte = 16,
  string = 17,
};

/// How a field repeats its type: once, a fixed array, or an unbounded sequence.
enum class FieldShape : int { single = 0, array = 48, sequence = 144 };

struct FieldDescription {
  std::string name;
  FieldType type = FieldType::float64;
  FieldShape shape = FieldShape::single;
  int capacity = 0;         // array length
  std::string nested_type;  // "pkg/msg/Name" of a nested field
};

struct TypeDescription {
  std::string name;  // "pkg/msg/Name"
  std::vector<FieldDescription> fields;
};

/// The hash of `type_name` given the descriptions of it and every type it refers to (others in
/// `types` are ignored). Throws std::logic_error when a referenced type is missing.
std::string ros_type_hash(const std::string& type_name, const std::vector<TypeDescription>& types);

}  // namespace ballsight::dds
