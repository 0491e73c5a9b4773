#include "ballsight/dds/domain.hpp"

#include <cstdlib>
#include <stdexcept>
#include <string_view>

#include "ballsight/core/error.hpp"

namespace ballsight::dds {
namespace {

std::string environment(const char* name) {
  const char* value = std::getenv(name);
  return value ? value : "";
}

bool is_name_token(std::string_view token) {
  if (token.empty() || (token[0] >= '0' && token[0] <= '9')) return false;
  for (const char c : token) {
    const bool ok =
        (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
    if (!ok) return false;
  }
  return true;
}

}  // namespace

void DomainOptions::validate() const {
  if (domain) require(*domain >= 0 && *domain <= 232, "--domain", "must be 0 to 232 (DDS's range)");
  std::string_view rest = ns;
  while (!rest.empty()) {  // tokens of letters, digits and '_' between single slashes
    const std::size_t slash = rest.find('/');
    require(is_name_token(rest.substr(0, slash)), "--namespace",
            "'" + ns +
                "' is not a ROS 2 namespace (tokens of letters, digits and _ between "
                "slashes, each starting with a letter or _)");
    rest = slash == std::string_view::npos ? "" : rest.substr(slash + 1);
    require(slash == std::string_view::npos || !rest.empty(), "--namespace",
            "'" + ns + "' ends with a slash");
  }
}

int domain_id(const DomainOptions& options) {
  if (options.domain) return *options.domain;
  const std::string text = environment("ROS_DOMAIN_ID");
  if (text.empty()) return 0;
  char* end = nullptr;
  const long id = std::strtol(text.c_str(), &end, 10);
  require(*end == '\0' && id >= 0 && id <= 232, "ROS_DOMAIN_ID",
          "'" + text + "' is not a domain id (0 to 232)");
  return static_cast<int>(id);
}

bool loopback_only(const DomainOptions& options) {
  return options.loopback || environment("ROS_AUTOMATIC_DISCOVERY_RANGE") == "LOCALHOST" ||
         environment("ROS_LOCALHOST_ONLY") == "1";
}

std::string loopback_config() {
  // What Jazzy's rmw_cyclonedds generates for ROS_AUTOMATIC_DISCOVERY_RANGE=LOCALHOST
  // (rmw_node.cpp), with shared memory off as well.
  return "<CycloneDDS><Domain Id=\"any\"><General><Interfaces>"
         "<NetworkInterface address=\"127.0.0.1\"/></Interfaces>"
         "<AllowMulticast>false</AllowMulticast></General>"
         "<Discovery><ParticipantIndex>auto</ParticipantIndex>"
         "<MaxAutoParticipantIndex>32</MaxAutoParticipantIndex>"
         "<Peers><Peer address=\"127.0.0.1\"/></Peers></Discovery>"
         "<SharedMemory><Enable>false</Enable></SharedMemory></Domain></CycloneDDS>";
}

std::string ros_topic_name(const std::string& ns, const std::string& name) {
  return ns.empty() ? "rt/" + name : "rt/" + ns + "/" + name;
}

dds_return_t check_dds(dds_return_t result, const std::string& what) {
  if (result < 0) throw std::runtime_error(what + ": " + dds_strretcode(result));
  return result;
}

Participant::Participant(const DomainOptions& options) : ns_(options.ns) {
  options.validate();
  const auto id = static_cast<dds_domainid_t>(domain_id(options));
  if (loopback_only(options)) {
    // The loopback settings first; the user's CYCLONEDDS_URI after them overrides them.
    std::string config = loopback_config();
    if (const std::string uri = environment("CYCLONEDDS_URI"); !uri.empty()) config += "," + uri;
    // Another participant of this process may have made the domain already (with the same
    // settings): the domain then lives as long as the process, shared by its participants.
    const dds_entity_t domain = dds_create_domain(id, config.c_str());
    if (domain != DDS_RETCODE_PRECONDITION_NOT_MET)
      check_dds(domain, "DDS domain " + std::to_string(id));
  }
  participant_ = check_dds(dds_create_participant(id, nullptr, nullptr),
                           "DDS participant on domain " + std::to_string(id));
}

Participant::~Participant() {
  dds_delete(participant_);
}

}  // namespace ballsight::dds
