"""What a ROS 2 node does on DDS, with Cyclone DDS's Python binding: topics, services in
rmw_cyclonedds' request/reply mapping, and the Fibonacci action (server and client).

Names: topic `/scan` is DDS topic `rt/scan`; service `/add_two_ints` is the request
topic `rq/add_two_intsRequest` and the reply topic `rr/add_two_intsReply`; action
`/fibonacci` is the services `/fibonacci/_action/{send_goal,get_result,cancel_goal}` and
the topics `/fibonacci/_action/{feedback,status}`.
"""
import os
import random
import threading
import time
import traceback

from cyclonedds.core import InstanceState, ReadCondition, SampleState, ViewState, WaitSet
from cyclonedds.domain import DomainParticipant
from cyclonedds.pub import DataWriter
from cyclonedds.sub import DataReader
from cyclonedds.topic import Topic

import ros2_types as T


def domain_id():
    return int(os.environ.get("ROS_DOMAIN_ID", "0"))


def now():
    t = time.time_ns()
    return T.Time(sec=t // 1_000_000_000, nanosec=t % 1_000_000_000)


class Node:
    """One DDS participant, like one ROS 2 context. Samples are handed to the readers'
    callbacks on one thread of the node's own, which waits on a waitset (as rmw's
    executors do), so callbacks must not block for long.

    Not Cyclone listeners: a listener runs Python on Cyclone's receive thread, and the
    binding's `write` keeps the GIL while Cyclone delivers to a reader in the same
    process. A write delivered locally to a reader whose listener the receive thread is
    entering at that moment then waits for that listener, which waits for the GIL:
    both threads stop for good, the receive socket fills, and every remote writer's
    samples to this process are dropped from then on."""

    def __init__(self):
        self.dp = DomainParticipant(domain_id())
        self.topics = {}
        self.waitset = WaitSet(self.dp)
        self.readers = []  # (DataReader, ReadCondition, on_sample)
        self.lock = threading.Lock()
        threading.Thread(target=self._dispatch, daemon=True).start()

    def topic(self, name, cls):
        if name not in self.topics:
            self.topics[name] = Topic(self.dp, name, cls)
        return self.topics[name]

    def writer(self, name, cls, qos=T.DEFAULT_QOS):
        return DataWriter(self.dp, self.topic(name, cls), qos=qos)

    def reader(self, name, cls, on_sample, qos=T.DEFAULT_QOS):
        """A reader of DDS topic `name`; on_sample(sample) for each valid sample (its
        SampleInfo is `sample.sample_info`), called on the node's dispatch thread."""
        r = DataReader(self.dp, self.topic(name, cls), qos=qos)
        cond = ReadCondition(r, SampleState.NotRead | ViewState.Any | InstanceState.Any)
        with self.lock:
            self.waitset.attach(cond)
            self.readers.append((r, cond, on_sample))
        return r

    def _dispatch(self):
        while True:
            # Bounded, so a reader attached while waiting is served within 50 ms anyway;
            # the wait itself releases the GIL (ctypes).
            self.waitset.wait(50_000_000)
            with self.lock:
                readers = list(self.readers)
            for r, _, on_sample in readers:
                try:
                    while True:
                        got = r.take(N=64)
                        if not got:
                            break
                        for s in got:
                            if s.sample_info.valid_data:
                                on_sample(s)
                except Exception:  # a callback's bug must be seen, not end the thread
                    traceback.print_exc()


def topic_name(ros_name):
    return "rt" + ros_name


def wait_until(cond, timeout, step=0.05):
    deadline = time.monotonic() + timeout
    while not cond():
        if time.monotonic() > deadline:
            return False
        time.sleep(step)
    return True


# ---------------------------------------------------------------- services

class ServiceServer:
    """Answers `name`: handler(request, reply) is called for every request, on the
    node's dispatch thread; reply(**fields) sends the response with the request's header (now or
    later, from any thread)."""

    def __init__(self, node, name, req_cls, resp_cls, handler):
        self.resp_cls = resp_cls
        self.handler = handler
        self.writer = node.writer(f"rr{name}Reply", resp_cls)
        node.reader(f"rq{name}Request", req_cls, self._on_request)

    def _on_request(self, req):
        guid, seq = req.guid, req.seq
        self.handler(req, lambda **fields: self.writer.write(self.resp_cls(guid=guid, seq=seq, **fields)))


class ServiceClient:
    """Calls `name`. Every reply on the shared reply topic reaches every client; this one
    keeps those carrying its own guid and a sequence number it is waiting for."""

    def __init__(self, node, name, req_cls, resp_cls):
        self.name = name
        self.req_cls = req_cls
        self.guid = random.getrandbits(64)
        self.seq = 0
        self.pending = {}  # seq -> [threading.Event, response]
        self.lock = threading.Lock()
        self.writer = node.writer(f"rq{name}Request", req_cls)
        self.reader = node.reader(f"rr{name}Reply", resp_cls, self._on_reply)

    def ready(self):
        """Like rmw's service_server_is_available: a server reads our requests and writes
        replies we read (a request sent before that would be lost: volatile QoS)."""
        return (self.writer.get_publication_matched_status().current_count > 0
                and self.reader.get_subscription_matched_status().current_count > 0)

    def wait_ready(self, timeout):
        return wait_until(self.ready, timeout)

    def _on_reply(self, resp):
        if resp.guid != self.guid:
            return
        with self.lock:
            slot = self.pending.get(resp.seq)
        if slot:
            slot[1] = resp
            slot[0].set()

    def call(self, timeout, **fields):
        """The response, or None if none came within `timeout` seconds."""
        with self.lock:
            self.seq += 1
            seq = self.seq
            slot = self.pending[seq] = [threading.Event(), None]
        try:
            self.writer.write(self.req_cls(guid=self.guid, seq=seq, **fields))
            slot[0].wait(timeout)
            return slot[1]
        finally:
            with self.lock:
                del self.pending[seq]


# ---------------------------------------------------------------- parameters

class ParameterServer:
    """A node's parameters as an rclcpp node serves them: `<node>/get_parameters`,
    `set_parameters` and `list_parameters` (rcl_interfaces). `params` maps names to
    ParameterValues. Like a node whose parameters are declared with types, it refuses a
    change of type and a change of a read-only parameter, with a reason; setting
    NOT_SET undeclares a parameter. Every change is logged in `changes` (name, value)."""

    def __init__(self, node, name, params, read_only=()):
        self.params = dict(params)
        self.read_only = set(read_only)
        self.changes = []
        self.lock = threading.Lock()
        ServiceServer(node, f"{name}/get_parameters", T.GetParametersRequest, T.GetParametersResponse, self._get)
        ServiceServer(node, f"{name}/set_parameters", T.SetParametersRequest, T.SetParametersResponse, self._set)
        ServiceServer(node, f"{name}/list_parameters", T.ListParametersRequest, T.ListParametersResponse, self._list)

    def values(self):
        """name -> plain value (what rosapi would give), for the suite's report."""
        with self.lock:
            return {n: v if not hasattr(v, "__len__") or isinstance(v, str) else list(v)
                    for n, pv in self.params.items()
                    for v in [getattr(pv, T.PARAMETER_FIELDS[pv.type])]}

    def _get(self, req, reply):
        with self.lock:
            values = [self.params.get(n, T.parameter_value(0)) for n in req.names]
        reply(values=values)

    def _set(self, req, reply):
        results = []
        with self.lock:
            for p in req.parameters:
                old = self.params.get(p.name)
                if p.name in self.read_only:
                    results.append(T.SetParametersResult(successful=False, reason=f"{p.name} is read-only"))
                elif p.value.type == 0:
                    self.params.pop(p.name, None)
                    self.changes.append((p.name, None))
                    results.append(T.SetParametersResult(successful=True, reason=""))
                elif old is not None and old.type != p.value.type:
                    results.append(T.SetParametersResult(
                        successful=False, reason=f"{p.name} has type {old.type}, not {p.value.type}"))
                else:
                    self.params[p.name] = p.value
                    self.changes.append((p.name, p.value.type))
                    results.append(T.SetParametersResult(successful=True, reason=""))
        reply(results=results)

    def _list(self, req, reply):
        with self.lock:
            names = sorted(n for n in self.params
                           if not req.prefixes or any(n == x or n.startswith(x + ".") for x in req.prefixes))
        reply(result=T.ListParametersResult(names=names, prefixes=[]))


# ---------------------------------------------------------------- the Fibonacci action

ZERO_UUID = bytes(16)


class FibonacciServer:
    """The action server of example_interfaces' Fibonacci example: the sequence grows by
    one number per `step` seconds, each step published as feedback; goals are accepted
    at once and may be cancelled. `goals` keeps (order, final status) of every goal for
    the suite's report."""

    def __init__(self, node, name, step=0.1):
        self.step = step
        self.lock = threading.Lock()
        self.goals = {}  # uuid bytes -> dict(order, status, stamp, result, waiting, cancel)
        base = f"{name}/_action/"
        self.feedback = node.writer(topic_name(base + "feedback"), T.FibonacciFeedbackMessage)
        self.status = node.writer(topic_name(base + "status"), T.GoalStatusArray, qos=T.ACTION_STATUS_QOS)
        ServiceServer(node, base + "send_goal", T.FibonacciSendGoalRequest, T.FibonacciSendGoalResponse, self._send_goal)
        ServiceServer(node, base + "get_result", T.FibonacciGetResultRequest, T.FibonacciGetResultResponse, self._get_result)
        ServiceServer(node, base + "cancel_goal", T.CancelGoalRequest, T.CancelGoalResponse, self._cancel_goal)

    def report(self):
        with self.lock:
            return [{"order": g["order"], "status": g["status"], "uuid": u.hex()} for u, g in self.goals.items()]

    def _publish_status(self):
        # Called with the lock held: one array of every goal, like rcl_action.
        self.status.write(T.GoalStatusArray(status_list=[
            T.GoalStatus(goal_info=T.GoalInfo(goal_id=T.UUID(uuid=u), stamp=g["stamp"]), status=g["status"])
            for u, g in self.goals.items()]))

    def _send_goal(self, req, reply):
        uuid = bytes(req.goal_id.uuid)
        stamp = now()
        with self.lock:
            if uuid in self.goals:  # a resent request: answer it again, run the goal once
                reply(accepted=True, stamp=self.goals[uuid]["stamp"])
                return
            self.goals[uuid] = {"order": req.goal.order, "status": T.ACCEPTED, "stamp": stamp, "result": None,
                                "waiting": [], "cancel": False}
            self._publish_status()
        reply(accepted=True, stamp=stamp)
        threading.Thread(target=self._execute, args=(uuid,), daemon=True).start()

    def _execute(self, uuid):
        with self.lock:
            goal = self.goals[uuid]
            goal["status"] = T.EXECUTING
            self._publish_status()
        seq = [0, 1]
        final = T.SUCCEEDED
        for i in range(1, goal["order"]):
            with self.lock:
                if goal["cancel"]:
                    final = T.CANCELED
                    break
            seq.append((seq[i] + seq[i - 1] + 2**31) % 2**32 - 2**31)  # int32 wrap-around
            self.feedback.write(T.FibonacciFeedbackMessage(goal_id=T.UUID(uuid=uuid),
                                                           feedback=T.FibonacciFeedback(sequence=seq)))
            time.sleep(self.step)
        with self.lock:
            if goal["cancel"]:
                final = T.CANCELED
            goal["status"], goal["result"] = final, list(seq)
            waiting, goal["waiting"] = goal["waiting"], []
            self._publish_status()
        for reply in waiting:
            reply(status=final, result=T.FibonacciResult(sequence=seq))

    def _get_result(self, req, reply):
        uuid = bytes(req.goal_id.uuid)
        with self.lock:
            goal = self.goals.get(uuid)
            if goal is None:  # unknown goal: STATUS_UNKNOWN, empty result (as rclcpp does)
                reply(status=0, result=T.FibonacciResult(sequence=[]))
            elif goal["result"] is None:
                goal["waiting"].append(reply)  # answered when the goal ends
            else:
                reply(status=goal["status"], result=T.FibonacciResult(sequence=goal["result"]))

    def _cancel_goal(self, req, reply):
        """action_msgs/srv/CancelGoal: a zero id and zero stamp cancel every goal; a zero id
        and a stamp cancel those accepted at or before it; an id cancels that goal (and,
        with a stamp, also those at or before it)."""
        uuid = bytes(req.goal_info.goal_id.uuid)
        stamp = (req.goal_info.stamp.sec, req.goal_info.stamp.nanosec)
        canceling, code = [], 0
        with self.lock:
            active = {u: g for u, g in self.goals.items() if g["result"] is None}
            for u, g in active.items():
                by_stamp = stamp != (0, 0) and (g["stamp"].sec, g["stamp"].nanosec) <= stamp
                if (uuid == ZERO_UUID and stamp == (0, 0)) or u == uuid or by_stamp:
                    g["cancel"], g["status"] = True, T.CANCELING
                    canceling.append(T.GoalInfo(goal_id=T.UUID(uuid=u), stamp=g["stamp"]))
            if not canceling and uuid != ZERO_UUID:
                code = 3 if uuid in self.goals else 2  # ERROR_GOAL_TERMINATED / ERROR_UNKNOWN_GOAL_ID
            if canceling:
                self._publish_status()
        reply(return_code=code, goals_canceling=canceling)


class FibonacciClient:
    """The client side of the Fibonacci action (the suite's self-test uses it to check
    FibonacciServer without fleetlink)."""

    def __init__(self, node, name):
        base = f"{name}/_action/"
        self.send = ServiceClient(node, base + "send_goal", T.FibonacciSendGoalRequest, T.FibonacciSendGoalResponse)
        self.result = ServiceClient(node, base + "get_result", T.FibonacciGetResultRequest, T.FibonacciGetResultResponse)
        self.cancel = ServiceClient(node, base + "cancel_goal", T.CancelGoalRequest, T.CancelGoalResponse)
        self.lock = threading.Lock()
        self.feedbacks = {}  # uuid -> [sequence, ...]
        self.statuses = {}  # uuid -> [status, ...] as seen on the status topic (changes only)
        node.reader(topic_name(base + "feedback"), T.FibonacciFeedbackMessage, self._on_feedback)
        node.reader(topic_name(base + "status"), T.GoalStatusArray, self._on_status, qos=T.ACTION_STATUS_QOS)

    def wait_ready(self, timeout):
        return all(c.wait_ready(timeout) for c in (self.send, self.result, self.cancel))

    def _on_feedback(self, m):
        with self.lock:
            self.feedbacks.setdefault(bytes(m.goal_id.uuid), []).append(list(m.feedback.sequence))

    def _on_status(self, m):
        with self.lock:
            for s in m.status_list:
                seen = self.statuses.setdefault(bytes(s.goal_info.goal_id.uuid), [])
                if not seen or seen[-1] != s.status:
                    seen.append(s.status)
