// fastdds_listener: subscribes with Fast DDS, as a ROS 2 node on rmw_fastrtps would, to the
// topics a ballsight court writes with Cyclone DDS (robot_pose, balls, route under a namespace)
// and prints every sample as one JSON line on stdout. Exits 0 once it has N samples of each
// topic, 1 if some topic has fewer after the timeout (naming them on stderr), 2 on a usage error.
// The participant stays on loopback: UDPv4 on 127.0.0.1 only, no shared memory, no multicast.

#include <fastdds/rtps/transport/UDPv4TransportDescriptor.h>
#include <fastrtps/utils/IPLocator.h>

#include <algorithm>
#include <array>
#include <charconv>
#include <chrono>
#include <condition_variable>
#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/DataReaderListener.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <functional>
#include <iostream>
#include <memory>
#include <mutex>
#include <nlohmann/json.hpp>
#include <optional>
#include <string>
#include <string_view>
#include <variant>

#include "ros_typesPubSubTypes.h"

namespace {

namespace fdds = eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::IPLocator;
using eprosima::fastrtps::rtps::Locator_t;
using Json = nlohmann::ordered_json;
using Clock = std::chrono::steady_clock;

constexpr std::string_view kUsage =
    "usage: fastdds_listener --namespace NS --domain D --count N --timeout-s T\n"
    "  subscribes on loopback to rt/NS/robot_pose, rt/NS/balls and rt/NS/route (ROS 2 default\n"
    "  QoS, XCDR1) and prints each sample as a JSON line; exits 0 once each topic has N samples,\n"
    "  1 if some has fewer after T seconds\n";

struct Options {
  std::string ns;
  int domain = 0;
  int count = 1;
  double timeout_s = 30.0;
};

template <typename T>
std::optional<T> parse_number(std::string_view text) {
  T value{};
  const auto [end, error] = std::from_chars(text.data(), text.data() + text.size(), value);
  if (error != std::errc() || end != text.data() + text.size()) return std::nullopt;
  return value;
}

// The options, or a message saying what is wrong with them.
std::variant<Options, std::string> parse_options(int argc, char** argv) {
  Options options;
  bool has_namespace = false;
  for (int k = 1; k < argc; k += 2) {
    const std::string_view flag = argv[k];
    if (k + 1 == argc) return std::string(flag) + " needs a value";
    const std::string_view value = argv[k + 1];
    if (flag == "--namespace") {
      has_namespace = true;
      options.ns = value.starts_with('/') ? value.substr(1) : value;
    } else if (flag == "--domain") {
      const std::optional<int> domain = parse_number<int>(value);
      if (!domain || *domain < 0 || *domain > 232) return "--domain must be 0 to 232";
      options.domain = *domain;
    } else if (flag == "--count") {
      const std::optional<int> count = parse_number<int>(value);
      if (!count || *count < 1) return "--count must be a whole number of at least 1";
      options.count = *count;
    } else if (flag == "--timeout-s") {
      const std::optional<double> timeout = parse_number<double>(value);
      if (!timeout || !(*timeout > 0.0)) return "--timeout-s must be a positive number";
      options.timeout_s = *timeout;
    } else {
      return "unknown option " + std::string(flag);
    }
  }
  if (!has_namespace) return "--namespace is required (ballsight's --namespace)";
  return options;
}

// The participant's QoS: UDPv4 on 127.0.0.1 only (builtin transports off, so no shared memory),
// discovery by unicast only (no multicast locator is added once the metatraffic unicast list is
// set), announced to the first 32 participants' ports on 127.0.0.1 (Cyclone's, too).
fdds::DomainParticipantQos loopback_participant_qos() {
  fdds::DomainParticipantQos qos;
  qos.name("fastdds_listener");
  auto udp = std::make_shared<eprosima::fastdds::rtps::UDPv4TransportDescriptor>();
  udp->interfaceWhiteList.emplace_back("127.0.0.1");
  udp->maxInitialPeersRange = 32;
  qos.transport().user_transports.push_back(udp);
  qos.transport().use_builtin_transports = false;
  Locator_t localhost;  // port 0: Fast DDS fills in the domain's ports
  IPLocator::setIPv4(localhost, 127, 0, 0, 1);
  qos.wire_protocol().builtin.metatrafficUnicastLocatorList.push_back(localhost);
  qos.wire_protocol().builtin.initialPeersList.push_back(localhost);
  qos.wire_protocol().default_unicast_locator_list.push_back(localhost);
  return qos;
}

// ROS 2's default QoS (rmw_qos_profile_default), readers accepting XCDR1 only as Jazzy's
// rmw_fastrtps readers do.
fdds::DataReaderQos ros_default_reader_qos() {
  fdds::DataReaderQos qos = fdds::DATAREADER_QOS_DEFAULT;
  qos.reliability().kind = fdds::RELIABLE_RELIABILITY_QOS;
  qos.durability().kind = fdds::VOLATILE_DURABILITY_QOS;
  qos.history().kind = fdds::KEEP_LAST_HISTORY_QOS;
  qos.history().depth = 10;
  qos.type_consistency().representation.m_value = {fdds::XCDR_DATA_REPRESENTATION};
  qos.data_sharing().off();
  return qos;
}

Json header_json(const std_msgs::msg::Header& header) {
  return {{"frame_id", header.frame_id()},
          {"sec", header.stamp().sec()},
          {"nanosec", header.stamp().nanosec()}};
}

Json robot_pose_json(const geometry_msgs::msg::PoseStamped& message) {
  Json json = header_json(message.header());
  const geometry_msgs::msg::Point& p = message.pose().position();
  const geometry_msgs::msg::Quaternion& q = message.pose().orientation();
  json.update({{"x", p.x()}, {"y", p.y()}, {"z", p.z()}});
  json.update({{"qx", q.x()}, {"qy", q.y()}, {"qz", q.z()}, {"qw", q.w()}});
  return json;
}

Json balls_json(const geometry_msgs::msg::PoseArray& message) {
  Json json = header_json(message.header());
  json["poses"] = Json::array();
  for (const geometry_msgs::msg::Pose& pose : message.poses()) {
    const geometry_msgs::msg::Point& p = pose.position();
    json["poses"].push_back({p.x(), p.y(), p.z()});
  }
  return json;
}

Json route_json(const nav_msgs::msg::Path& message) {
  Json json = header_json(message.header());
  json["poses"] = Json::array();
  for (const geometry_msgs::msg::PoseStamped& stamped : message.poses()) {
    const geometry_msgs::msg::Pose& pose = stamped.pose();
    json["poses"].push_back(
        {pose.position().x(), pose.position().y(), pose.orientation().z(), pose.orientation().w()});
  }
  return json;
}

// A reader's next valid sample as JSON (its message's fields), or nothing once none is left.
using TakeJson = std::function<std::optional<Json>(fdds::DataReader&)>;

template <typename Message>
TakeJson take_json(Json (*to_json)(const Message&)) {
  return [to_json](fdds::DataReader& reader) -> std::optional<Json> {
    Message message;
    fdds::SampleInfo info;
    while (reader.take_next_sample(&message, &info) == ReturnCode_t::RETCODE_OK)
      if (info.valid_data) return to_json(message);
    return std::nullopt;
  };
}

// What the readers share: stdout, their counts and the main thread's wake-up.
struct Progress {
  std::mutex mutex;
  std::condition_variable changed;
  Clock::time_point start = Clock::now();
};

// One topic's reader callbacks: each sample as a JSON line on stdout, matches and refusals on
// stderr.
class TopicListener : public fdds::DataReaderListener {
 public:
  TopicListener(std::string topic, TakeJson take, Progress& progress)
      : topic_(std::move(topic)), take_(std::move(take)), progress_(progress) {}

  const std::string& topic() const { return topic_; }
  int received() const { return received_; }  // with progress.mutex held

  void on_data_available(fdds::DataReader* reader) override {
    while (const std::optional<Json> fields = take_(*reader)) {
      Json line = {{"topic", topic_}, {"type", reader->get_topicdescription()->get_type_name()}};
      line.update(*fields);
      {
        const std::lock_guard lock(progress_.mutex);
        std::cout << line.dump() << std::endl;
        ++received_;
      }
      progress_.changed.notify_one();
    }
  }

  void on_subscription_matched(fdds::DataReader* reader,
                               const fdds::SubscriptionMatchedStatus& status) override {
    const std::chrono::duration<double> elapsed = Clock::now() - progress_.start;
    std::cerr << "fastdds_listener: " << reader->get_topicdescription()->get_name()
              << (status.current_count_change > 0 ? " matched" : " unmatched") << " a writer after "
              << elapsed.count() << " s\n";
  }

  void on_requested_incompatible_qos(fdds::DataReader* reader,
                                     const fdds::RequestedIncompatibleQosStatus& status) override {
    std::cerr << "fastdds_listener: " << reader->get_topicdescription()->get_name()
              << ": a writer's QoS is incompatible (policy id " << status.last_policy_id << ")\n";
  }

 private:
  std::string topic_;
  TakeJson take_;
  Progress& progress_;
  int received_ = 0;  // guarded by progress_.mutex
};

// Creates the topic `rt/<ns>/<listener's topic>` of `type` and its reader; false if it cannot.
bool subscribe(fdds::DomainParticipant& participant, fdds::Subscriber& subscriber,
               const std::string& ns, fdds::TypeSupport type, TopicListener& listener) {
  if (type.register_type(&participant) != ReturnCode_t::RETCODE_OK) return false;
  const std::string name = "rt/" + (ns.empty() ? "" : ns + "/") + listener.topic();
  fdds::Topic* topic =
      participant.create_topic(name, type.get_type_name(), fdds::TOPIC_QOS_DEFAULT);
  return topic && subscriber.create_datareader(topic, ros_default_reader_qos(), &listener);
}

int run(const Options& options) {
  Progress progress;
  std::array<TopicListener, 3> listeners{
      TopicListener("robot_pose", take_json(robot_pose_json), progress),
      TopicListener("balls", take_json(balls_json), progress),
      TopicListener("route", take_json(route_json), progress)};
  const std::array<fdds::TypeSupport, 3> types{
      fdds::TypeSupport(new geometry_msgs::msg::PoseStampedPubSubType()),
      fdds::TypeSupport(new geometry_msgs::msg::PoseArrayPubSubType()),
      fdds::TypeSupport(new nav_msgs::msg::PathPubSubType())};

  fdds::DomainParticipantFactory& factory = *fdds::DomainParticipantFactory::get_instance();
  fdds::DomainParticipant* participant =
      factory.create_participant(options.domain, loopback_participant_qos());
  if (!participant) {
    std::cerr << "fastdds_listener: no participant on domain " << options.domain << "\n";
    return 1;
  }
  fdds::Subscriber* subscriber = participant->create_subscriber(fdds::SUBSCRIBER_QOS_DEFAULT);
  bool subscribed = subscriber != nullptr;
  for (std::size_t k = 0; k < listeners.size() && subscribed; ++k)
    subscribed = subscribe(*participant, *subscriber, options.ns, types[k], listeners[k]);

  std::string missing;
  if (subscribed) {
    std::unique_lock lock(progress.mutex);
    progress.changed.wait_for(lock, std::chrono::duration<double>(options.timeout_s), [&] {
      return std::ranges::all_of(listeners, [&](const TopicListener& listener) {
        return listener.received() >= options.count;
      });
    });
    for (const TopicListener& listener : listeners) {
      if (listener.received() < options.count)
        missing += " " + listener.topic() + " (" + std::to_string(listener.received()) + " of " +
                   std::to_string(options.count) + ")";
    }
  }
  participant->delete_contained_entities();  // the readers go before their listeners
  factory.delete_participant(participant);
  if (!subscribed) {
    std::cerr << "fastdds_listener: could not create the topics and readers\n";
    return 1;
  }
  if (!missing.empty()) {
    std::cerr << "fastdds_listener: after " << options.timeout_s
              << " s, too few samples on:" << missing << "\n";
    return 1;
  }
  return 0;
}

}  // namespace

int main(int argc, char** argv) {
  const std::variant<Options, std::string> options = parse_options(argc, argv);
  if (const std::string* error = std::get_if<std::string>(&options)) {
    std::cerr << "fastdds_listener: " << *error << "\n" << kUsage;
    return 2;
  }
  return run(std::get<Options>(options));
}
