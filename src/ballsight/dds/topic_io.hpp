#pragma once
// Typed DDS writers and readers with ROS 2's QoS (rmw_qos_profile_default: reliable, volatile,
// keep last 10; transient-local for the latest route and world so that late joiners get them),
// XCDR1 and the type hash in USER_DATA, as a ROS 2 Jazzy endpoint has them.

#include <chrono>
#include <cstdint>
#include <string>
#include <vector>

#include "ballsight/dds/domain.hpp"
#include "ballsight/dds/message_types.hpp"

namespace ballsight::dds {

struct TopicQos {
  bool transient_local = false;  // late joiners get the last samples (`late_joiners`)
  int depth = 10;                // keep last
  int late_joiners = 0;          // a writer's samples kept for late joiners (0: `depth`)
};

/// A reader or writer of the ROS 2 topic `name` (under the participant's namespace) of ROS 2
/// type `ros_name`. Throws std::runtime_error when DDS refuses.
dds_entity_t make_endpoint(const Participant& participant, const dds_topic_descriptor_t& type,
                           const std::string& name, const std::string& ros_name,
                           const TopicQos& qos, bool writer);
/// Takes every sample of `reader` as serialized bytes (Reader::take_serialized).
std::vector<std::vector<std::uint8_t>> take_cdr(dds_entity_t reader);
/// Readers (of a writer) or writers (of a reader) matched now.
int matched_count(dds_entity_t endpoint, bool writer);

/// Waits for any of several readers at once (their condition()).
class WaitSet {
 public:
  explicit WaitSet(const Participant& participant);
  ~WaitSet();
  WaitSet(const WaitSet&) = delete;
  WaitSet& operator=(const WaitSet&) = delete;

  void attach(dds_entity_t condition);
  /// Waits until a condition attached is triggered or `timeout` passed; whether one is.
  bool wait(std::chrono::nanoseconds timeout);

 private:
  dds_entity_t waitset_;
};

template <class Msg>
class Writer {
 public:
  Writer(const Participant& participant, const std::string& name, const TopicQos& qos = {})
      : writer_(make_endpoint(participant, MessageType<Msg>::descriptor(), name,
                              MessageType<Msg>::ros_name, qos, true)) {}
  ~Writer() { dds_delete(writer_); }
  Writer(const Writer&) = delete;
  Writer& operator=(const Writer&) = delete;

  /// Throws std::runtime_error when DDS refuses.
  void write(const Msg& message) { check_dds(dds_write(writer_, &message), "DDS write"); }
  int matched_readers() const { return matched_count(writer_, true); }

 private:
  dds_entity_t writer_;
};

template <class Msg>
class Reader {
 public:
  Reader(const Participant& participant, const std::string& name, const TopicQos& qos = {})
      : reader_(make_endpoint(participant, MessageType<Msg>::descriptor(), name,
                              MessageType<Msg>::ros_name, qos, false)),
        condition_(check_dds(dds_create_readcondition(reader_, DDS_ANY_STATE), "DDS condition")),
        waitset_(participant) {
    waitset_.attach(condition_);
  }
  ~Reader() { dds_delete(reader_); }
  Reader(const Reader&) = delete;
  Reader& operator=(const Reader&) = delete;

  /// Waits until a sample is there to take or `timeout` passed; whether one is.
  bool wait(std::chrono::nanoseconds timeout) { return waitset_.wait(timeout); }
  /// Calls `visit(const Msg&)` for every sample received and not taken yet, oldest first (the
  /// message is DDS's: copy what you keep); how many.
  template <class Visit>
  int take(Visit&& visit) {
    constexpr int kBatch = 16;
    int taken = 0;
    for (;;) {
      void* samples[kBatch] = {};
      dds_sample_info_t infos[kBatch];
      const int n = check_dds(dds_take(reader_, samples, infos, kBatch, kBatch), "DDS take");
      for (int k = 0; k < n; ++k) {
        if (infos[k].valid_data) {
          visit(*static_cast<const Msg*>(samples[k]));
          ++taken;
        }
      }
      if (n > 0) dds_return_loan(reader_, samples, n);
      if (n < kBatch) return taken;
    }
  }
  /// The samples not taken yet as the bytes that crossed the wire (encapsulation header and
  /// XCDR1 body), oldest first.
  std::vector<std::vector<std::uint8_t>> take_serialized() { return take_cdr(reader_); }
  int matched_writers() const { return matched_count(reader_, false); }
  /// Triggered while a sample is there to take (to wait on several readers at once).
  dds_entity_t condition() const { return condition_; }

 private:
  dds_entity_t reader_;
  dds_entity_t condition_;
  WaitSet waitset_;
};

}  // namespace ballsight::dds
