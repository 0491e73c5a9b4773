#include "ballsight/dds/type_hash.hpp"

#include <openssl/sha.h>

#include <algorithm>
#include <cstdio>
#include <set>
#include <stdexcept>

namespace ballsight::dds {
namespace {

// Python's json.dumps(ensure_ascii=True) of a name: the names here are ASCII identifiers.
std::string quoted(const std::string& s) {
  return "\"" + s + "\"";
}

std::string field_json(const FieldDescription& f) {
  const int type_id = static_cast<int>(f.type) + static_cast<int>(f.shape);
  return "{\"name\": " + quoted(f.name) + ", \"type\": {\"type_id\": " + std::to_string(type_id) +
         ", \"capacity\": " + std::to_string(f.capacity) +
         ", \"string_capacity\": 0, \"nested_type_name\": " + quoted(f.nested_type) + "}}";
}

std::string type_json(const TypeDescription& t) {
  std::string fields;
  for (const FieldDescription& f : t.fields) fields += (fields.empty() ? "" : ", ") + field_json(f);
  return "{\"type_name\": " + quoted(t.name) + ", \"fields\": [" + fields + "]}";
}

const TypeDescription& find_type(const std::string& name,
                                 const std::vector<TypeDescription>& types) {
  const auto it = std::find_if(types.begin(), types.end(),
                               [&](const TypeDescription& t) { return t.name == name; });
  if (it == types.end()) throw std::logic_error("type hash: no description of " + name);
  return *it;
}

void collect_references(const TypeDescription& type, const std::vector<TypeDescription>& types,
                        std::set<std::string>& names) {
  for (const FieldDescription& f : type.fields) {
    if (f.nested_type.empty() || !names.insert(f.nested_type).second) continue;
    collect_references(find_type(f.nested_type, types), types, names);
  }
}

}  // namespace

std::string ros_type_hash(const std::string& type_name, const std::vector<TypeDescription>& types) {
  const TypeDescription& type = find_type(type_name, types);
  std::set<std::string> referenced;  // sorted, as rosidl sorts them
  collect_references(type, types, referenced);
  std::string references;
  for (const std::string& name : referenced)
    references += (references.empty() ? "" : ", ") + type_json(find_type(name, types));
  const std::string json = "{\"type_description\": " + type_json(type) +
                           ", \"referenced_type_descriptions\": [" + references + "]}";
  unsigned char digest[SHA256_DIGEST_LENGTH];
  SHA256(reinterpret_cast<const unsigned char*>(json.data()), json.size(), digest);
  std::string hex = "RIHS01_";
  char byte[3];
  for (const unsigned char b : digest) {
    std::snprintf(byte, sizeof byte, "%02x", b);
    hex += byte;
  }
  return hex;
}

}  // namespace ballsight::dds
