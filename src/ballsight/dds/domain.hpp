#pragma once
// A DDS participant the way a ROS 2 node makes one: the domain from `--domain` or ROS_DOMAIN_ID
// (0 without either), the middleware's own configuration (CYCLONEDDS_URI) honoured, and, when
// asked (`--loopback`, or ROS 2's ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST / ROS_LOCALHOST_ONLY=1),
// confined to 127.0.0.1 with multicast off, as Jazzy's rmw_cyclonedds configures LOCALHOST
// (research note net-web.md §1). Topic names under a namespace as ROS 2 maps them: `/ns/name` is
// the DDS topic `rt/ns/name`.

#include <dds/dds.h>

#include <optional>
#include <string>

namespace ballsight::dds {

struct DomainOptions {
  std::optional<int> domain;  // nullopt: ROS_DOMAIN_ID, else 0
  bool loopback = false;      // also when the environment asks for ROS 2's LOCALHOST range
  std::string ns;             // ROS 2 namespace without slashes at its ends ("court1"; "": none)

  /// Throws InputError naming the first invalid field (domain 0-232, namespace tokens).
  void validate() const;
};

/// The domain id `options` and the environment give (ROS_DOMAIN_ID read here).
int domain_id(const DomainOptions& options);
/// Whether `options` or the environment confine DDS to this machine.
bool loopback_only(const DomainOptions& options);
/// The Cyclone DDS configuration (XML) that confines a participant to 127.0.0.1, no multicast.
std::string loopback_config();

/// "rt/<ns>/<name>" (or "rt/<name>" without a namespace).
std::string ros_topic_name(const std::string& ns, const std::string& name);

/// A DDS domain participant; deleting it deletes every entity it made.
class Participant {
 public:
  /// Throws InputError when the options are invalid, std::runtime_error when DDS refuses.
  explicit Participant(const DomainOptions& options);
  ~Participant();
  Participant(const Participant&) = delete;
  Participant& operator=(const Participant&) = delete;

  dds_entity_t handle() const { return participant_; }
  const std::string& ns() const { return ns_; }

 private:
  dds_entity_t participant_ = 0;
  std::string ns_;
};

/// Throws std::runtime_error("<what>: <DDS's reason>") when `result` is a DDS error code.
dds_return_t check_dds(dds_return_t result, const std::string& what);

}  // namespace ballsight::dds
