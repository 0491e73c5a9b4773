#include "ballsight/dds/topic_io.hpp"

#include <dds/ddsi/ddsi_serdata.h>

#include <memory>

namespace ballsight::dds {

dds_entity_t make_endpoint(const Participant& participant, const dds_topic_descriptor_t& type,
                           const std::string& name, const std::string& ros_name,
                           const TopicQos& qos, bool writer) {
  const std::string topic_name = ros_topic_name(participant.ns(), name);
  const dds_entity_t topic =
      check_dds(dds_create_topic(participant.handle(), &type, topic_name.c_str(), nullptr, nullptr),
                "DDS topic " + topic_name);
  const std::unique_ptr<dds_qos_t, decltype(&dds_delete_qos)> q(dds_create_qos(), &dds_delete_qos);
  dds_qset_reliability(q.get(), DDS_RELIABILITY_RELIABLE, DDS_SECS(1));
  dds_qset_durability(
      q.get(), qos.transient_local ? DDS_DURABILITY_TRANSIENT_LOCAL : DDS_DURABILITY_VOLATILE);
  dds_qset_history(q.get(), DDS_HISTORY_KEEP_LAST, qos.depth);
  // Cyclone keeps what a late joiner gets by the durability service's history, not the writer's.
  if (writer && qos.transient_local)
    dds_qset_durability_service(q.get(), 0, DDS_HISTORY_KEEP_LAST,
                                qos.late_joiners > 0 ? qos.late_joiners : qos.depth,
                                DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED, DDS_LENGTH_UNLIMITED);
  dds_data_representation_id_t xcdr1 = DDS_DATA_REPRESENTATION_XCDR1;
  dds_qset_data_representation(q.get(), 1, &xcdr1);
  const std::string user_data = "typehash=" + message_type_hash(ros_name) + ";";
  dds_qset_userdata(q.get(), user_data.data(), user_data.size());
  const dds_entity_t endpoint =
      writer ? dds_create_writer(participant.handle(), topic, q.get(), nullptr)
             : dds_create_reader(participant.handle(), topic, q.get(), nullptr);
  return check_dds(endpoint,
                   std::string("DDS ") + (writer ? "writer" : "reader") + " of " + topic_name);
}

std::vector<std::vector<std::uint8_t>> take_cdr(dds_entity_t reader) {
  std::vector<std::vector<std::uint8_t>> samples;
  for (;;) {
    ddsi_serdata* data = nullptr;
    dds_sample_info_t info;
    if (check_dds(dds_takecdr(reader, &data, 1, &info, DDS_ANY_STATE), "DDS take") == 0)
      return samples;
    if (info.valid_data) {
      std::vector<std::uint8_t>& bytes = samples.emplace_back(ddsi_serdata_size(data));
      ddsi_serdata_to_ser(data, 0, bytes.size(), bytes.data());
    }
    ddsi_serdata_unref(data);
  }
}

WaitSet::WaitSet(const Participant& participant)
    : waitset_(check_dds(dds_create_waitset(participant.handle()), "DDS wait set")) {}

WaitSet::~WaitSet() {
  dds_delete(waitset_);
}

void WaitSet::attach(dds_entity_t condition) {
  check_dds(dds_waitset_attach(waitset_, condition, 0), "DDS wait set");
}

bool WaitSet::wait(std::chrono::nanoseconds timeout) {
  return check_dds(dds_waitset_wait(waitset_, nullptr, 0, timeout.count()), "DDS wait") > 0;
}

int matched_count(dds_entity_t endpoint, bool writer) {
  if (writer) {
    dds_publication_matched_status_t status;
    check_dds(dds_get_publication_matched_status(endpoint, &status), "DDS matched readers");
    return static_cast<int>(status.current_count);
  }
  dds_subscription_matched_status_t status;
  check_dds(dds_get_subscription_matched_status(endpoint, &status), "DDS matched writers");
  return static_cast<int>(status.current_count);
}

}  // namespace ballsight::dds
