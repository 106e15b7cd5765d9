// A ROS 2 node's DDS side as Fast DDS (eProsima's libfastrtps, the DDS under ROS 2's
// default middleware, rmw_fastrtps_cpp) has it, for the ROS 2 interop suite, with ROS 2's
// DDS names (`rt/<topic>`, `rq/<service>Request`, `pkg::msg::dds_::T_`) and rmw's default
// QoS (reliable, volatile, keep last 10). Samples are handled as the CDR bytes they are,
// so the peer needs no generated type support.
//
//   fastdds_peer topics UP_TOPIC DOWN_TOPIC COUNT SECONDS [PAD]
//     Writes std_msgs/msg/String "fastdds <i>" for i in 0..COUNT on rt/UP_TOPIC, 10 a
//     second, once a reader is matched; odd ones followed by a space and PAD x's (large
//     samples go out in DDS fragments); prints `down: <text>` for every sample read on
//     rt/DOWN_TOPIC; exits 0 after COUNT writes and at least one sample read.
//   fastdds_peer server SERVICE SECONDS
//     Serves example_interfaces/srv/AddTwoInts on SERVICE as rmw_fastrtps does: the reply
//     carries, as its related sample identity, the request's sequence number with the
//     client's reply reader GUID (the request's related sample identity) or else the
//     request writer's. Prints `served: A + B = SUM` per request; runs until SECONDS.
//   fastdds_peer action ACTION SECONDS
//     Serves example_interfaces/action/Fibonacci on ACTION: its send_goal, get_result and
//     cancel_goal services in the mapping above, feedback on rt/ACTION/_action/feedback,
//     one step per 0.1 s (int32 wrap-around, as the example does). Prints `goal: ORDER`,
//     `succeeded`, `canceled`; runs until SECONDS.
//   fastdds_peer action-client ACTION ORDER SECONDS
//     Sends a Fibonacci goal of ORDER to ACTION in the mapping above, asks for its result,
//     counts its feedback; prints `accepted: 0|1`, `feedback: N` and
//     `result: status=S sequence=A,B,...`; exits 0 once the result came.
//   fastdds_peer client SERVICE SECONDS
//     Calls std_srvs/srv/Trigger on SERVICE as rmw_fastrtps does (the request names its
//     reply reader; the reply is the one whose related sample identity has the request's
//     sequence number), once the server is matched, again every 2 s until answered.
//     Prints `reply: success=<0|1> message=<text>`; exits 0 once answered.
// The writing and calling modes exit 1 when SECONDS pass first; the servers run until then.

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
#include <fastdds/rtps/common/WriteParams.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>
#include <thread>
#include <vector>

using namespace eprosima::fastdds::dds;
using eprosima::fastrtps::rtps::GUID_t;
using eprosima::fastrtps::rtps::InstanceHandle_t;
using eprosima::fastrtps::rtps::SampleIdentity;
using eprosima::fastrtps::rtps::WriteParams;
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

// A participant on ROS_DOMAIN_ID with writers and readers of raw samples.
struct Node {
    DomainParticipant* participant = nullptr;
    Publisher* publisher = nullptr;
    Subscriber* subscriber = nullptr;

    bool open() {
        const char* domain_env = std::getenv("ROS_DOMAIN_ID");
        const int domain = domain_env ? std::atoi(domain_env) : 0;
        DomainParticipantQos pqos;
        pqos.name("fastdds_peer");
        participant = DomainParticipantFactory::get_instance()->create_participant(domain, pqos);
        if (participant == nullptr) {
            std::fprintf(stderr, "could not create a participant\n");
            return false;
        }
        publisher = participant->create_publisher(PUBLISHER_QOS_DEFAULT);
        subscriber = participant->create_subscriber(SUBSCRIBER_QOS_DEFAULT);
        return publisher != nullptr && subscriber != nullptr;
    }

    Topic* topic(const std::string& name, const char* type_name) {
        TypeSupport type(new RawType(type_name));
        type.register_type(participant);
        return participant->create_topic(name, type_name, TOPIC_QOS_DEFAULT);
    }

    // rmw's default QoS; data sharing off, as rmw has it for types of unbounded size.
    template <typename Qos>
    static Qos rmw_default(Qos q) {
        q.reliability().kind = RELIABLE_RELIABILITY_QOS;
        q.durability().kind = VOLATILE_DURABILITY_QOS;
        q.history().kind = KEEP_LAST_HISTORY_QOS;
        q.history().depth = 10;
        q.data_sharing().off();
        return q;
    }

    DataWriter* writer(const std::string& name, const char* type_name) {
        Topic* t = topic(name, type_name);
        return t ? publisher->create_datawriter(t, rmw_default(DATAWRITER_QOS_DEFAULT)) : nullptr;
    }

    DataReader* reader(const std::string& name, const char* type_name) {
        Topic* t = topic(name, type_name);
        return t ? subscriber->create_datareader(t, rmw_default(DATAREADER_QOS_DEFAULT)) : nullptr;
    }

    ~Node() {
        if (participant != nullptr) {
            participant->delete_contained_entities();
            DomainParticipantFactory::get_instance()->delete_participant(participant);
        }
    }
};

static int64_t read_i64(const std::vector<uint8_t>& b, size_t at) {
    int64_t v = 0;
    for (int i = 0; i < 8; i++) v |= static_cast<int64_t>(b[at + i]) << (8 * i);
    return v;
}

static bool matched(DataWriter* w) {
    PublicationMatchedStatus s;
    w->get_publication_matched_status(s);
    return s.current_count > 0;
}

static void put_i32(std::vector<uint8_t>* b, int32_t v) {
    for (int i = 0; i < 4; i++) b->push_back(static_cast<uint8_t>(static_cast<uint32_t>(v) >> (8 * i)));
}

// A reply in the rmw_fastrtps mapping: to the request's sequence number, named by the
// client's reply reader when the request gave one.
static bool reply_to(DataWriter* w, const SampleInfo& request, Raw* reply) {
    WriteParams params;
    params.related_sample_identity(request.sample_identity);
    if (request.related_sample_identity.writer_guid() != GUID_t::unknown()) {
        params.related_sample_identity().writer_guid() = request.related_sample_identity.writer_guid();
    }
    return w->write(reply, params);
}

static int server(char** argv) {
    const std::string service = argv[2];
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(std::atoi(argv[3]));
    Node node;
    if (!node.open()) return 1;
    DataReader* requests =
        node.reader("rq/" + service + "Request", "example_interfaces::srv::dds_::AddTwoInts_Request_");
    DataWriter* replies =
        node.writer("rr/" + service + "Reply", "example_interfaces::srv::dds_::AddTwoInts_Response_");
    if (requests == nullptr || replies == nullptr) return 1;
    std::printf("ready: serving %s\n", service.c_str());
    std::fflush(stdout);
    while (std::chrono::steady_clock::now() < deadline) {
        Raw got;
        SampleInfo info;
        while (requests->take_next_sample(&got, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || got.bytes.size() < 4 + 16) continue;
            const int64_t a = read_i64(got.bytes, 4), b = read_i64(got.bytes, 12);
            Raw reply;
            reply.bytes = {0x00, 0x01, 0x00, 0x00};
            const int64_t sum = a + b;
            for (int i = 0; i < 8; i++) reply.bytes.push_back(static_cast<uint8_t>(sum >> (8 * i)));
            const bool ok = reply_to(replies, info, &reply);
            std::printf("served: %lld + %lld = %lld%s\n", static_cast<long long>(a),
                        static_cast<long long>(b), static_cast<long long>(sum),
                        ok ? "" : " (reply not written)");
            std::fflush(stdout);
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return 0;
}

struct FibGoal {
    std::vector<uint8_t> uuid;
    int order = 0;
    std::vector<int32_t> seq{0, 1};
    int8_t status = 2;  // EXECUTING; 4 SUCCEEDED, 5 CANCELED
    std::vector<SampleInfo> waiting;  // get_result requests to answer when it ends
};

static int action(char** argv) {
    const std::string name = std::string(argv[2]) + "/_action/";
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(std::atoi(argv[3]));
    Node node;
    if (!node.open()) return 1;
    const std::string t = "example_interfaces::action::dds_::Fibonacci_";
    DataReader* goal_rq = node.reader("rq/" + name + "send_goalRequest", (t + "SendGoal_Request_").c_str());
    DataWriter* goal_rr = node.writer("rr/" + name + "send_goalReply", (t + "SendGoal_Response_").c_str());
    DataReader* result_rq = node.reader("rq/" + name + "get_resultRequest", (t + "GetResult_Request_").c_str());
    DataWriter* result_rr = node.writer("rr/" + name + "get_resultReply", (t + "GetResult_Response_").c_str());
    DataReader* cancel_rq =
        node.reader("rq/" + name + "cancel_goalRequest", "action_msgs::srv::dds_::CancelGoal_Request_");
    DataWriter* cancel_rr =
        node.writer("rr/" + name + "cancel_goalReply", "action_msgs::srv::dds_::CancelGoal_Response_");
    DataWriter* feedback = node.writer("rt/" + name + "feedback", (t + "FeedbackMessage_").c_str());
    if (!goal_rq || !goal_rr || !result_rq || !result_rr || !cancel_rq || !cancel_rr || !feedback) return 1;
    std::printf("ready: action %s\n", argv[2]);
    std::fflush(stdout);
    std::vector<FibGoal> goals;
    // {int8 status, int32[] sequence}
    auto answer = [&](const FibGoal& g, const SampleInfo& request) {
        Raw r;
        r.bytes = {0x00, 0x01, 0x00, 0x00, static_cast<uint8_t>(g.status), 0, 0, 0};
        put_i32(&r.bytes, static_cast<int32_t>(g.seq.size()));
        for (int32_t v : g.seq) put_i32(&r.bytes, v);
        reply_to(result_rr, request, &r);
    };
    auto find = [&](const std::vector<uint8_t>& b) -> FibGoal* {
        if (b.size() < 20) return nullptr;
        for (FibGoal& g : goals)
            if (std::equal(g.uuid.begin(), g.uuid.end(), b.begin() + 4)) return &g;
        return nullptr;
    };
    auto end = [&](FibGoal& g, int8_t status) {
        g.status = status;
        for (const SampleInfo& w : g.waiting) answer(g, w);
        g.waiting.clear();
        std::printf("%s\n", status == 4 ? "succeeded" : "canceled");
        std::fflush(stdout);
    };
    auto next_step = std::chrono::steady_clock::now();
    while (std::chrono::steady_clock::now() < deadline) {
        Raw got;
        SampleInfo info;
        // send_goal: {uuid[16], int32 order} -> {bool accepted, Time stamp}
        while (goal_rq->take_next_sample(&got, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data || got.bytes.size() < 24) continue;
            FibGoal g;
            g.uuid.assign(got.bytes.begin() + 4, got.bytes.begin() + 20);
            int32_t order = 0;
            for (int i = 0; i < 4; i++) order |= static_cast<int32_t>(got.bytes[20 + i]) << (8 * i);
            g.order = order;
            goals.push_back(g);
            Raw r;
            r.bytes = {0x00, 0x01, 0x00, 0x00, 1, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0, 0};
            reply_to(goal_rr, info, &r);
            std::printf("goal: %d\n", g.order);
            std::fflush(stdout);
        }
        // get_result: {uuid[16]}
        while (result_rq->take_next_sample(&got, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data) continue;
            if (FibGoal* g = find(got.bytes)) {
                if (g->status == 2) g->waiting.push_back(info);
                else answer(*g, info);
            }
        }
        // cancel_goal: {GoalInfo {uuid[16], Time stamp}} -> {int8 return_code, GoalInfo[]}
        while (cancel_rq->take_next_sample(&got, &info) == ReturnCode_t::RETCODE_OK) {
            if (!info.valid_data) continue;
            Raw r;
            r.bytes = {0x00, 0x01, 0x00, 0x00};
            FibGoal* g = find(got.bytes);
            if (g != nullptr && g->status == 2) {
                r.bytes.insert(r.bytes.end(), {0, 0, 0, 0});  // ERROR_NONE, padding
                put_i32(&r.bytes, 1);
                r.bytes.insert(r.bytes.end(), g->uuid.begin(), g->uuid.end());
                put_i32(&r.bytes, 0);
                put_i32(&r.bytes, 0);
                end(*g, 5);
            } else {
                r.bytes.insert(r.bytes.end(), {2, 0, 0, 0});  // ERROR_UNKNOWN_GOAL_ID
                put_i32(&r.bytes, 0);
            }
            reply_to(cancel_rr, info, &r);
        }
        if (std::chrono::steady_clock::now() >= next_step) {
            next_step += std::chrono::milliseconds(100);
            for (FibGoal& g : goals) {
                if (g.status != 2) continue;
                if (static_cast<int>(g.seq.size()) > g.order) {
                    end(g, 4);
                    continue;
                }
                const size_t n = g.seq.size();
                g.seq.push_back(static_cast<int32_t>(static_cast<uint32_t>(g.seq[n - 1]) +
                                                     static_cast<uint32_t>(g.seq[n - 2])));
                // {uuid[16], int32[] sequence}
                Raw f;
                f.bytes = {0x00, 0x01, 0x00, 0x00};
                f.bytes.insert(f.bytes.end(), g.uuid.begin(), g.uuid.end());
                put_i32(&f.bytes, static_cast<int32_t>(g.seq.size()));
                for (int32_t v : g.seq) put_i32(&f.bytes, v);
                feedback->write(&f);
            }
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(5));
    }
    return 0;
}

// One request in the rmw_fastrtps mapping, and its reply (empty after `deadline`).
struct Call {
    DataWriter* requests;
    DataReader* replies;

    bool ready() {
        SubscriptionMatchedStatus r;
        replies->get_subscription_matched_status(r);
        return matched(requests) && r.current_count > 0;
    }

    Raw call(Raw* request, std::chrono::steady_clock::time_point deadline) {
        WriteParams params;
        params.related_sample_identity().writer_guid() = replies->guid();
        if (!requests->write(request, params)) return Raw();
        const SampleIdentity sent = params.sample_identity();
        while (std::chrono::steady_clock::now() < deadline) {
            Raw got;
            SampleInfo info;
            while (replies->take_next_sample(&got, &info) == ReturnCode_t::RETCODE_OK) {
                if (info.valid_data &&
                    info.related_sample_identity.sequence_number() == sent.sequence_number() &&
                    info.related_sample_identity.writer_guid() == replies->guid())
                    return got;
            }
            std::this_thread::sleep_for(std::chrono::milliseconds(5));
        }
        return Raw();
    }
};

static int action_client(char** argv) {
    const std::string name = std::string(argv[2]) + "/_action/";
    const int32_t order = std::atoi(argv[3]);
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(std::atoi(argv[4]));
    Node node;
    if (!node.open()) return 1;
    const std::string t = "example_interfaces::action::dds_::Fibonacci_";
    Call send_goal{node.writer("rq/" + name + "send_goalRequest", (t + "SendGoal_Request_").c_str()),
                   node.reader("rr/" + name + "send_goalReply", (t + "SendGoal_Response_").c_str())};
    Call get_result{node.writer("rq/" + name + "get_resultRequest", (t + "GetResult_Request_").c_str()),
                    node.reader("rr/" + name + "get_resultReply", (t + "GetResult_Response_").c_str())};
    DataReader* feedback = node.reader("rt/" + name + "feedback", (t + "FeedbackMessage_").c_str());
    if (!send_goal.requests || !send_goal.replies || !get_result.requests || !get_result.replies || !feedback)
        return 1;
    std::vector<uint8_t> uuid;
    for (int i = 0; i < 16; i++) uuid.push_back(static_cast<uint8_t>(0xa0 + i));
    while (!(send_goal.ready() && get_result.ready())) {
        if (std::chrono::steady_clock::now() >= deadline) {
            std::printf("the action's services were not matched\n");
            return 1;
        }
        std::this_thread::sleep_for(std::chrono::milliseconds(20));
    }
    // {uuid[16], int32 order} -> {bool accepted, Time stamp}
    Raw goal;
    goal.bytes = {0x00, 0x01, 0x00, 0x00};
    goal.bytes.insert(goal.bytes.end(), uuid.begin(), uuid.end());
    put_i32(&goal.bytes, order);
    Raw accepted = send_goal.call(&goal, deadline);
    std::printf("accepted: %d\n", accepted.bytes.size() > 4 ? accepted.bytes[4] : -1);
    std::fflush(stdout);
    if (accepted.bytes.size() <= 4 || accepted.bytes[4] != 1) return 1;
    // {uuid[16]} -> {int8 status, int32[] sequence}; feedback counted meanwhile.
    Raw ask;
    ask.bytes = {0x00, 0x01, 0x00, 0x00};
    ask.bytes.insert(ask.bytes.end(), uuid.begin(), uuid.end());
    Raw result = get_result.call(&ask, deadline);
    int feedbacks = 0;
    Raw got;
    SampleInfo info;
    while (feedback->take_next_sample(&got, &info) == ReturnCode_t::RETCODE_OK) {
        if (info.valid_data && got.bytes.size() >= 20 &&
            std::equal(uuid.begin(), uuid.end(), got.bytes.begin() + 4))
            feedbacks++;
    }
    std::printf("feedback: %d\n", feedbacks);
    if (result.bytes.size() < 12) {
        std::printf("no result\n");
        return 1;
    }
    uint32_t n = 0;
    for (int i = 0; i < 4; i++) n |= static_cast<uint32_t>(result.bytes[8 + i]) << (8 * i);
    std::string seq;
    for (uint32_t i = 0; i < n && 12 + 4 * (i + 1) <= result.bytes.size(); i++) {
        int32_t v = 0;
        for (int k = 0; k < 4; k++) v |= static_cast<int32_t>(result.bytes[12 + 4 * i + k]) << (8 * k);
        seq += (i ? "," : "") + std::to_string(v);
    }
    std::printf("result: status=%d sequence=%s\n", static_cast<int8_t>(result.bytes[4]), seq.c_str());
    std::fflush(stdout);
    return 0;
}

static int client(char** argv) {
    const std::string service = argv[2];
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(std::atoi(argv[3]));
    Node node;
    if (!node.open()) return 1;
    Call trigger{node.writer("rq/" + service + "Request", "std_srvs::srv::dds_::Trigger_Request_"),
                 node.reader("rr/" + service + "Reply", "std_srvs::srv::dds_::Trigger_Response_")};
    if (trigger.requests == nullptr || trigger.replies == nullptr) return 1;
    std::printf("ready: calling %s\n", service.c_str());
    std::fflush(stdout);
    while (std::chrono::steady_clock::now() < deadline) {
        if (!trigger.ready()) {
            std::this_thread::sleep_for(std::chrono::milliseconds(20));
            continue;
        }
        // std_srvs/srv/Trigger's empty request: ROS 2's one-byte placeholder member.
        Raw request;
        request.bytes = {0x00, 0x01, 0x00, 0x00, 0x00};
        Raw got = trigger.call(&request, std::min(deadline, std::chrono::steady_clock::now() +
                                                                std::chrono::seconds(2)));
        if (got.bytes.empty()) continue;  // asked again every 2 s
        // bool success; string message (at 4: its length, then the text and a NUL).
        std::string message;
        if (got.bytes.size() >= 12) {
            uint32_t n = 0;
            for (int i = 0; i < 4; i++) n |= static_cast<uint32_t>(got.bytes[8 + i]) << (8 * i);
            if (n > 0 && 12 + n <= got.bytes.size())
                message.assign(reinterpret_cast<const char*>(got.bytes.data() + 12), n - 1);
        }
        std::printf("reply: success=%d message=%s\n", got.bytes.size() > 4 ? got.bytes[4] : -1,
                    message.c_str());
        std::fflush(stdout);
        return 0;
    }
    std::printf("no reply\n");
    return 1;
}

static int topics(int argc, char** argv) {
    const std::string up = std::string("rt/") + argv[2];
    const std::string down = std::string("rt/") + argv[3];
    const int count = std::atoi(argv[4]);
    const size_t pad = argc > 6 ? std::strtoul(argv[6], nullptr, 10) : 0;
    const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(std::atoi(argv[5]));
    Node node;
    if (!node.open()) return 1;
    DataWriter* writer = node.writer(up, "std_msgs::msg::dds_::String_");
    DataReader* reader = node.reader(down, "std_msgs::msg::dds_::String_");
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
            std::string text = "fastdds " + std::to_string(written);
            if (written % 2 == 1 && pad > 0) text += " " + std::string(pad, 'x');
            Raw sample = encode_string(text);
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
    return (written >= count && read > 0) ? 0 : 1;
}

int main(int argc, char** argv) {
    const std::string mode = argc > 1 ? argv[1] : "";
    if (mode == "topics" && (argc == 6 || argc == 7)) return topics(argc, argv);
    if (mode == "server" && argc == 4) return server(argv);
    if (mode == "client" && argc == 4) return client(argv);
    if (mode == "action" && argc == 4) return action(argv);
    if (mode == "action-client" && argc == 5) return action_client(argv);
    std::fprintf(stderr,
                 "usage: %s topics UP_TOPIC DOWN_TOPIC COUNT SECONDS [PAD] | server SERVICE SECONDS"
                 " | client SERVICE SECONDS | action ACTION SECONDS"
                 " | action-client ACTION ORDER SECONDS\n",
                 argv[0]);
    return 2;
}
