// A ROS 2 node's DDS side as Fast DDS (eProsima's libfastrtps, the DDS under ROS 2's
// default middleware, rmw_fastrtps_cpp) has it, for the ROS 2 interop suite: it writes
// std_msgs/msg/String on one topic and prints what it reads on another, with ROS 2's DDS
// names (`rt/<topic>`, `std_msgs::msg::dds_::String_`) and its default topic QoS
// (reliable, volatile, keep last 10). Samples are handled as the CDR bytes they are, so
// the peer needs no generated type support.
//
//   fastdds_peer UP_TOPIC DOWN_TOPIC COUNT SECONDS
//
// Writes "fastdds <i>" for i in 0..COUNT on rt/UP_TOPIC, 10 a second, once a reader is
// matched; prints `down: <text>` for every sample read on rt/DOWN_TOPIC; exits 0 after
// COUNT writes and at least one sample read, 1 when SECONDS pass first.

#include <fastdds/dds/domain/DomainParticipant.hpp>
#include <fastdds/dds/domain/DomainParticipantFactory.hpp>
#include <fastdds/dds/publisher/DataWriter.hpp>
#include <fastdds/dds/publisher/Publisher.hpp>
#include <fastdds/dds/publisher/qos/DataWriterQos.hpp>
#include <fastdds/dds/subscriber/DataReader.hpp>
#include <fastdds/dds/subscriber/SampleInfo.hpp>
#include <fastdds/dds/subscriber/Subscriber.hpp>
#include <fastdds/dds/subscriber/qos/DataReaderQos.hpp>
#include <fastdds/dds/topic/Topic.hpp>
#include <fastdds/dds/topic/TopicDataType.hpp>
#include <fastdds/dds/topic/TypeSupport.hpp>
#include <fastdds/rtps/common/SerializedPayload.h>

#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::InstanceHandle_t;
using eprosima::fastrtps::rtps::SerializedPayload_t;

// A sample as its serialized bytes, encapsulation header first.
struct Raw {
    std::vector<uint8_t> bytes;
};

class RawType : public TopicDataType {
public:
    explicit RawType(const char* name) {
        setName(name);
        m_typeSize = 64 * 1024;
        m_isGetKeyDefined = false;
    }
    bool serialize(void* data, SerializedPayload_t* payload) override {
        auto* r = static_cast<Raw*>(data);
        if (r->bytes.size() > payload->max_size) return false;
        std::memcpy(payload->data, r->bytes.data(), r->bytes.size());
        payload->length = static_cast<uint32_t>(r->bytes.size());
        payload->encapsulation = CDR_LE;
        return true;
    }
    bool deserialize(SerializedPayload_t* payload, void* data) override {
        static_cast<Raw*>(data)->bytes.assign(payload->data, payload->data + payload->length);
        return true;
    }
    std::function<uint32_t()> getSerializedSizeProvider(void* data) override {
        return [data]() { return static_cast<uint32_t>(static_cast<Raw*>(data)->bytes.size()); };
    }
    void* createData() override { return new Raw(); }
    void deleteData(void* data) override { delete static_cast<Raw*>(data); }
    bool getKey(void*, InstanceHandle_t*, bool) override { return false; }
};

// std_msgs/msg/String in little-endian CDR: encapsulation, length with the NUL, text, NUL.
static Raw encode_string(const std::string& s) {
    Raw r;
    uint32_t n = static_cast<uint32_t>(s.size() + 1);
    r.bytes = {0x00, 0x01, 0x00, 0x00};
    for (int i = 0; i < 4; i++) r.bytes.push_back(static_cast<uint8_t>(n >> (8 * i)));
    r.bytes.insert(r.bytes.end(), s.begin(), s.end());
    r.bytes.push_back(0);
    return r;
}

static bool decode_string(const Raw& r, std::string* out) {
    if (r.bytes.size() < 8 || r.bytes[1] != 0x01) return false;  // CDR little-endian only
    uint32_t n = 0;
    for (int i = 0; i < 4; i++) n |= static_cast<uint32_t>(r.bytes[4 + i]) << (8 * i);
    if (n == 0 || 8 + n > r.bytes.size()) return false;
    out->assign(reinterpret_cast<const char*>(r.bytes.data() + 8), n - 1);
    return true;
}

int main(int argc, char** argv) {
    if (argc != 5) {
        std::fprintf(stderr, "usage: %s UP_TOPIC DOWN_TOPIC COUNT SECONDS\n", argv[0]);
        return 2;
    }
    const std::string up = std::string("rt/") + argv[1];
    const std::string down = std::string("rt/") + argv[2];
    const int count = std::atoi(argv[3]);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(std::atoi(argv[4]));
    const char* domain_env = std::getenv("ROS_DOMAIN_ID");
    const int domain = domain_env ? std::atoi(domain_env) : 0;

    DomainParticipantQos pqos;
    pqos.name("fastdds_peer");
    DomainParticipant* participant =
        DomainParticipantFactory::get_instance()->create_participant(domain, pqos);
    if (participant == nullptr) {
        std::fprintf(stderr, "could not create a participant\n");
        return 1;
    }
    TypeSupport type(new RawType("std_msgs::msg::dds_::String_"));
    type.register_type(participant);
    Topic* up_topic = participant->create_topic(up, type.get_type_name(), TOPIC_QOS_DEFAULT);
    Topic* down_topic = participant->create_topic(down, type.get_type_name(), TOPIC_QOS_DEFAULT);
    Publisher* publisher = participant->create_publisher(PUBLISHER_QOS_DEFAULT);
    Subscriber* subscriber = participant->create_subscriber(SUBSCRIBER_QOS_DEFAULT);

    // rmw's default topic QoS; data sharing off, as it is for a type of unbounded size.
    DataWriterQos wqos = DATAWRITER_QOS_DEFAULT;
    wqos.reliability().kind = RELIABLE_RELIABILITY_QOS;
    wqos.durability().kind = VOLATILE_DURABILITY_QOS;
    wqos.history().kind = KEEP_LAST_HISTORY_QOS;
    wqos.history().depth = 10;
    wqos.data_sharing().off();
    DataWriter* writer = publisher->create_datawriter(up_topic, wqos);
    DataReaderQos rqos = DATAREADER_QOS_DEFAULT;
    rqos.reliability().kind = RELIABLE_RELIABILITY_QOS;
    rqos.durability().kind = VOLATILE_DURABILITY_QOS;
    rqos.history().kind = KEEP_LAST_HISTORY_QOS;
    rqos.history().depth = 10;
    rqos.data_sharing().off();
    DataReader* reader = subscriber->create_datareader(down_topic, rqos);
    if (writer == nullptr || reader == nullptr) {
        std::fprintf(stderr, "could not create the writer or the reader\n");
        return 1;
    }
    std::printf("ready: writing %s, reading %s\n", up.c_str(), down.c_str());
    std::fflush(stdout);

    int written = 0;
    int read = 0;
    auto next_write = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() < deadline) {
        PublicationMatchedStatus matched;
        writer->get_publication_matched_status(matched);
        if (written < count && matched.current_count > 0 &&
            std::chrono::steady_clock::now() >= next_write) {
            Raw sample = encode_string("fastdds " + std::to_string(written));
            if (writer->write(&sample)) written++;
            next_write += std::chrono::milliseconds(100);
        }
        Raw got;
        SampleInfo info;
        while (reader->take_next_sample(&got, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data) continue;
            std::string text;
            if (decode_string(got, &text)) {
                std::printf("down: %s\n", text.c_str());
                read++;
            } else {
                std::printf("down: undecodable sample of %zu bytes\n", got.bytes.size());
            }
            std::fflush(stdout);
        }
        if (written >= count && read > 0) break;
        std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    std::printf("done: wrote %d, read %d\n", written, read);
    std::fflush(stdout);
    participant->delete_contained_entities();
    DomainParticipantFactory::get_instance()->delete_participant(participant);
    return (written >= count && read > 0) ? 0 : 1;
}
