#pragma once
// Strict reading of a YAML file a user keeps (yaml-cpp: the site file, camera calibration files):
// every value is reached by its dotted key ("cameras[1].source.file"), typed on the way, and every
// error reads "<file>:<line>: key '<key>' <what was expected>". A map must be closed with finish(),
// which rejects keys nobody asked for, so a typo never passes silently.

#include <yaml-cpp/yaml.h>

#include <optional>
#include <set>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

namespace ballsight {

class YamlMap;

/// One value of the file with its key and line.
class YamlValue {
 public:
  YamlValue(YAML::Node node, std::string file, std::string key);

  const std::string& key() const { return key_; }
  const std::string& file() const { return file_; }
  const YAML::Node& node() const { return node_; }
  int line() const;  // 1-based
  bool is_map() const { return node_.IsMap(); }
  bool is_list() const { return node_.IsSequence(); }

  /// Throws InputError "<file>:<line>: key '<key>' <what>".
  [[noreturn]] void fail(const std::string& what) const;

  double number() const;
  int integer() const;
  bool flag() const;         // true or false
  std::string text() const;  // a non-empty string
  /// A list of exactly `count` numbers.
  std::vector<double> numbers(std::size_t count) const;
  /// A list of exactly `count` integers, each in [lo, hi].
  std::vector<int> integers(std::size_t count, int lo, int hi) const;
  YamlMap map() const;
  std::vector<YamlValue> list() const;

 private:
  YAML::Node node_;
  std::string file_;
  std::string key_;
};

/// A YAML map whose keys are looked up one by one.
class YamlMap {
 public:
  /// Parses `text`, which must hold a map at the top; `file` names it in messages.
  static YamlMap parse(std::string_view text, const std::string& file);

  explicit YamlMap(const YamlValue& value);

  /// The value at `key`; throws "<file>:<line>: key '<key>' missing" when absent.
  YamlValue at(const std::string& key);
  /// The value at `key`, or nullopt when absent.
  std::optional<YamlValue> find(const std::string& key);
  /// Every entry in file order (all count as asked for).
  std::vector<std::pair<std::string, YamlValue>> entries();
  /// Throws "<file>:<line>: unknown key '<key>' (expected one of: ...)" for a key not asked for,
  /// and "<file>:<line>: key '<key>' appears twice" for a repeated key.
  void finish() const;

  const YamlValue& value() const { return value_; }

 private:
  std::string child_key(const std::string& key) const;
  [[noreturn]] void fail_at(const YAML::Node& key_node, const std::string& key,
                            const std::string& what) const;

  YamlValue value_;
  std::set<std::string> asked_;
  std::vector<std::string> asked_in_order_;
};

}  // namespace ballsight
