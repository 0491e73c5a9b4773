#include "ballsight/core/yaml_reader.hpp"

#include <cmath>

#include "ballsight/core/error.hpp"

namespace ballsight {

YamlValue::YamlValue(YAML::Node node, std::string file, std::string key)
    : node_(std::move(node)), file_(std::move(file)), key_(std::move(key)) {}

int YamlValue::line() const {
  return node_.Mark().line + 1;
}

void YamlValue::fail(const std::string& what) const {
  throw InputError(file_ + ":" + std::to_string(line()) + ": key '" + key_ + "' " + what);
}

double YamlValue::number() const {
  double value = 0.0;
  if (!node_.IsScalar() || !YAML::convert<double>::decode(node_, value) || !std::isfinite(value)) {
    fail("expected a number");
  }
  return value;
}

int YamlValue::integer() const {
  int value = 0;
  if (!node_.IsScalar() || !YAML::convert<int>::decode(node_, value)) fail("expected an integer");
  return value;
}

bool YamlValue::flag() const {
  bool value = false;
  if (!node_.IsScalar() || !YAML::convert<bool>::decode(node_, value))
    fail("expected true or false");
  return value;
}

std::string YamlValue::text() const {
  if (!node_.IsScalar() || node_.Scalar().empty()) fail("expected a string");
  return node_.Scalar();
}

std::vector<double> YamlValue::numbers(std::size_t count) const {
  const std::string expected = "expected a list of " + std::to_string(count) + " numbers";
  if (!node_.IsSequence() || node_.size() != count) fail(expected);
  std::vector<double> values;
  for (const YAML::Node& item : node_) {
    double v = 0.0;
    if (!item.IsScalar() || !YAML::convert<double>::decode(item, v) || !std::isfinite(v)) {
      fail(expected);
    }
    values.push_back(v);
  }
  return values;
}

std::vector<int> YamlValue::integers(std::size_t count, int lo, int hi) const {
  const std::string expected = "expected a list of " + std::to_string(count) + " integers in [" +
                               std::to_string(lo) + ", " + std::to_string(hi) + "]";
  if (!node_.IsSequence() || node_.size() != count) fail(expected);
  std::vector<int> values;
  for (const YAML::Node& item : node_) {
    int v = 0;
    if (!item.IsScalar() || !YAML::convert<int>::decode(item, v) || v < lo || v > hi) {
      fail(expected);
    }
    values.push_back(v);
  }
  return values;
}

YamlMap YamlValue::map() const {
  return YamlMap(*this);
}

std::vector<YamlValue> YamlValue::list() const {
  if (!node_.IsSequence()) fail("expected a list");
  std::vector<YamlValue> items;
  for (std::size_t i = 0; i < node_.size(); ++i) {
    items.emplace_back(node_[i], file_, key_ + "[" + std::to_string(i) + "]");
  }
  return items;
}

YamlMap YamlMap::parse(std::string_view text, const std::string& file) {
  YAML::Node root;
  try {
    root = YAML::Load(std::string(text));
  } catch (const YAML::Exception& e) {
    throw InputError(file + ":" + std::to_string(e.mark.line + 1) + ":" +
                     std::to_string(e.mark.column + 1) + ": not valid YAML: " + e.msg);
  }
  if (!root.IsMap()) {
    throw InputError(file + ":1: expected a YAML map of keys at the top of the file");
  }
  return YamlMap(YamlValue(root, file, ""));
}

YamlMap::YamlMap(const YamlValue& value) : value_(value) {
  if (!value.is_map()) value.fail("expected a map of keys");
}

std::string YamlMap::child_key(const std::string& key) const {
  return value_.key().empty() ? key : value_.key() + "." + key;
}

void YamlMap::fail_at(const YAML::Node& key_node, const std::string& key,
                      const std::string& what) const {
  YamlValue(key_node, value_.file(), child_key(key)).fail(what);
}

std::optional<YamlValue> YamlMap::find(const std::string& key) {
  if (asked_.insert(key).second) asked_in_order_.push_back(key);
  const YAML::Node& map = value_.node();
  const YAML::Node child = map[key];
  if (!child.IsDefined()) return std::nullopt;
  return YamlValue(child, value_.file(), child_key(key));
}

YamlValue YamlMap::at(const std::string& key) {
  std::optional<YamlValue> found = find(key);
  if (!found) {
    throw InputError(value_.file() + ":" + std::to_string(value_.line()) + ": key '" +
                     child_key(key) + "' missing");
  }
  return *found;
}

std::vector<std::pair<std::string, YamlValue>> YamlMap::entries() {
  std::vector<std::pair<std::string, YamlValue>> out;
  for (const auto& kv : value_.node()) {
    if (!kv.first.IsScalar()) fail_at(kv.first, "?", "expected a plain key");
    const std::string key = kv.first.Scalar();
    if (asked_.insert(key).second) asked_in_order_.push_back(key);
    out.emplace_back(key, YamlValue(kv.second, value_.file(), child_key(key)));
  }
  return out;
}

void YamlMap::finish() const {
  std::set<std::string> seen;
  for (const auto& kv : value_.node()) {
    const std::string key = kv.first.IsScalar() ? kv.first.Scalar() : "?";
    if (!seen.insert(key).second) fail_at(kv.first, key, "appears twice");
    if (asked_.count(key) != 0) continue;
    std::string known;
    for (const std::string& k : asked_in_order_) known += (known.empty() ? "" : ", ") + k;
    throw InputError(value_.file() + ":" + std::to_string(kv.first.Mark().line + 1) +
                     ": unknown key '" + child_key(key) + "' (expected one of: " + known + ")");
  }
}

}  // namespace ballsight
