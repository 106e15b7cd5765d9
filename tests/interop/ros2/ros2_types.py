"""ROS 2 message types as Cyclone DDS IDL structs, the way a ROS 2 node puts them on the
wire (rmw_cyclonedds), plus the QoS profiles and a cross-check against rosbags.

Naming: the ROS 2 type `pkg/msg/T` is the DDS type `pkg::msg::dds_::T_` (nested types
likewise); `pkg/srv/S` becomes `pkg::srv::dds_::S_Request_` / `S_Response_`; the parts
of an action `pkg/action/A` are `pkg::action::dds_::A_Goal_`, `A_SendGoal_Request_`, ...
The field lists follow crates/msg/defs/ros2 (the definitions bundled with fleetlink).

Service samples (rmw_cyclonedds' request/reply mapping) start with a 16-byte header
`uint64 guid; int64 seq` before the ROS fields: the client picks the guid, numbers its
requests, and the server copies both into the reply. The structs here carry it as their
first two fields (`guid`, `seq`); see SERVICE_HEADER.

Data representation: XCDR1 (plain CDR, encapsulation 0x0001 little endian), what ROS 2
uses; the QoS profiles below pin it so the binding never picks XCDR2.
"""
import dataclasses
import os

import numpy as np
from cyclonedds.idl import IdlStruct
from cyclonedds.idl._main import get_extended_type_hints
from cyclonedds.idl.types import array, bounded_str, byte, float32, float64, int8, int16, int32, int64, sequence, uint8, uint32, uint64
from cyclonedds.qos import Policy, Qos
from cyclonedds.util import duration


def dds_name(ros_name):
    """'sensor_msgs/msg/LaserScan' -> 'sensor_msgs::msg::dds_::LaserScan_'."""
    pkg, kind, name = ros_name.split("/")
    return f"{pkg}::{kind}::dds_::{name}_"


def ros_name(cls):
    """The inverse of dds_name, from an IDL class."""
    pkg, kind, _, name = cls.__idl_typename__.replace(".", "::").split("::")
    return f"{pkg}/{kind}/{name[:-1]}"


# ---------------------------------------------------------------- messages

@dataclasses.dataclass
class Time(IdlStruct, typename=dds_name("builtin_interfaces/msg/Time")):
    sec: int32
    nanosec: uint32


@dataclasses.dataclass
class Header(IdlStruct, typename=dds_name("std_msgs/msg/Header")):
    stamp: Time
    frame_id: str


@dataclasses.dataclass
class String(IdlStruct, typename=dds_name("std_msgs/msg/String")):
    data: str


@dataclasses.dataclass
class Vector3(IdlStruct, typename=dds_name("geometry_msgs/msg/Vector3")):
    x: float64
    y: float64
    z: float64


@dataclasses.dataclass
class Twist(IdlStruct, typename=dds_name("geometry_msgs/msg/Twist")):
    linear: Vector3
    angular: Vector3


@dataclasses.dataclass
class LaserScan(IdlStruct, typename=dds_name("sensor_msgs/msg/LaserScan")):
    header: Header
    angle_min: float32
    angle_max: float32
    angle_increment: float32
    time_increment: float32
    scan_time: float32
    range_min: float32
    range_max: float32
    ranges: sequence[float32]
    intensities: sequence[float32]


@dataclasses.dataclass
class PointField(IdlStruct, typename=dds_name("sensor_msgs/msg/PointField")):
    name: str
    offset: uint32
    datatype: uint8
    count: uint32


@dataclasses.dataclass
class PointCloud2(IdlStruct, typename=dds_name("sensor_msgs/msg/PointCloud2")):
    header: Header
    height: uint32
    width: uint32
    fields: sequence[PointField]
    is_bigendian: bool
    point_step: uint32
    row_step: uint32
    data: sequence[uint8]
    is_dense: bool


# The suite's own type: its .msg exists only in a temporary package (run.sh writes it,
# the agent reads it through --msg-path). Keep this in step with BATTERY_MSG.
BATTERY_MSG = """\
# A type only the ros2 interop suite knows.
string label
float32 voltage
uint8 cells
int16[3] balance_mv
float64[] temps
builtin_interfaces/Time stamp
"""


@dataclasses.dataclass
class Battery(IdlStruct, typename=dds_name("fltest_msgs/msg/Battery")):
    label: str
    voltage: float32
    cells: uint8
    balance_mv: array[int16, 3]
    temps: sequence[float64]
    stamp: Time


# ---------------------------------------------------------------- services

SERVICE_HEADER = ("guid", "seq")


@dataclasses.dataclass
class AddTwoIntsRequest(IdlStruct, typename=dds_name("example_interfaces/srv/AddTwoInts_Request")):
    guid: uint64
    seq: int64
    a: int64
    b: int64


@dataclasses.dataclass
class AddTwoIntsResponse(IdlStruct, typename=dds_name("example_interfaces/srv/AddTwoInts_Response")):
    guid: uint64
    seq: int64
    sum: int64


@dataclasses.dataclass
class TriggerRequest(IdlStruct, typename=dds_name("std_srvs/srv/Trigger_Request")):
    guid: uint64
    seq: int64
    # An empty ROS 2 message still has one member in IDL (and one byte on the wire).
    structure_needs_at_least_one_member: uint8


@dataclasses.dataclass
class TriggerResponse(IdlStruct, typename=dds_name("std_srvs/srv/Trigger_Response")):
    guid: uint64
    seq: int64
    success: bool
    message: str


# ---------------------------------------------------------------- parameters (rcl_interfaces)

@dataclasses.dataclass
class ParameterValue(IdlStruct, typename=dds_name("rcl_interfaces/msg/ParameterValue")):
    type: uint8
    bool_value: bool
    integer_value: int64
    double_value: float64
    string_value: str
    byte_array_value: sequence[byte]
    bool_array_value: sequence[bool]
    integer_array_value: sequence[int64]
    double_array_value: sequence[float64]
    string_array_value: sequence[str]


@dataclasses.dataclass
class Parameter(IdlStruct, typename=dds_name("rcl_interfaces/msg/Parameter")):
    name: str
    value: ParameterValue


@dataclasses.dataclass
class SetParametersResult(IdlStruct, typename=dds_name("rcl_interfaces/msg/SetParametersResult")):
    successful: bool
    reason: str


@dataclasses.dataclass
class ListParametersResult(IdlStruct, typename=dds_name("rcl_interfaces/msg/ListParametersResult")):
    names: sequence[str]
    prefixes: sequence[str]


@dataclasses.dataclass
class GetParametersRequest(IdlStruct, typename=dds_name("rcl_interfaces/srv/GetParameters_Request")):
    guid: uint64
    seq: int64
    names: sequence[str]


@dataclasses.dataclass
class GetParametersResponse(IdlStruct, typename=dds_name("rcl_interfaces/srv/GetParameters_Response")):
    guid: uint64
    seq: int64
    values: sequence[ParameterValue]


@dataclasses.dataclass
class SetParametersRequest(IdlStruct, typename=dds_name("rcl_interfaces/srv/SetParameters_Request")):
    guid: uint64
    seq: int64
    parameters: sequence[Parameter]


@dataclasses.dataclass
class SetParametersResponse(IdlStruct, typename=dds_name("rcl_interfaces/srv/SetParameters_Response")):
    guid: uint64
    seq: int64
    results: sequence[SetParametersResult]


@dataclasses.dataclass
class ListParametersRequest(IdlStruct, typename=dds_name("rcl_interfaces/srv/ListParameters_Request")):
    guid: uint64
    seq: int64
    prefixes: sequence[str]
    depth: uint64


@dataclasses.dataclass
class ListParametersResponse(IdlStruct, typename=dds_name("rcl_interfaces/srv/ListParameters_Response")):
    guid: uint64
    seq: int64
    result: ListParametersResult


# rcl_interfaces/msg/ParameterType: the ParameterValue field each type uses.
PARAMETER_FIELDS = [None, "bool_value", "integer_value", "double_value", "string_value", "byte_array_value",
                    "bool_array_value", "integer_array_value", "double_array_value", "string_array_value"]


def parameter_value(type_, value=None):
    """A ParameterValue of `type_` holding `value` (the other fields at their defaults)."""
    pv = ParameterValue(type=type_, bool_value=False, integer_value=0, double_value=0.0, string_value="",
                        byte_array_value=[], bool_array_value=[], integer_array_value=[],
                        double_array_value=[], string_array_value=[])
    if PARAMETER_FIELDS[type_]:
        setattr(pv, PARAMETER_FIELDS[type_], value)
    return pv


# ---------------------------------------------------------------- ros_discovery_info (rmw_dds_common)

def discovery_types(gid_len):
    """rmw_dds_common's Gid, NodeEntitiesInfo and ParticipantEntitiesInfo with `gid_len`-byte
    GIDs: 24 up to Humble, 16 from Iron on (the type names did not change)."""

    # The ROS type is char[N]; the binding reads a char as a signed byte and fails on
    # bytes above 0x7f, so the bytes are read as uint8 (the same wire layout).
    @dataclasses.dataclass
    class Gid(IdlStruct, typename=dds_name("rmw_dds_common/msg/Gid")):
        data: array[uint8, gid_len]

    @dataclasses.dataclass
    class NodeEntitiesInfo(IdlStruct, typename=dds_name("rmw_dds_common/msg/NodeEntitiesInfo")):
        node_namespace: bounded_str[256]
        node_name: bounded_str[256]
        reader_gid_seq: sequence[Gid]
        writer_gid_seq: sequence[Gid]

    @dataclasses.dataclass
    class ParticipantEntitiesInfo(IdlStruct, typename=dds_name("rmw_dds_common/msg/ParticipantEntitiesInfo")):
        gid: Gid
        node_entities_info_seq: sequence[NodeEntitiesInfo]

    return Gid, NodeEntitiesInfo, ParticipantEntitiesInfo


def gid_bytes(gid):
    """A Gid's data as bytes."""
    return bytes(gid.data)


# ---------------------------------------------------------------- actions

@dataclasses.dataclass
class UUID(IdlStruct, typename=dds_name("unique_identifier_msgs/msg/UUID")):
    uuid: array[uint8, 16]


@dataclasses.dataclass
class GoalInfo(IdlStruct, typename=dds_name("action_msgs/msg/GoalInfo")):
    goal_id: UUID
    stamp: Time


@dataclasses.dataclass
class GoalStatus(IdlStruct, typename=dds_name("action_msgs/msg/GoalStatus")):
    goal_info: GoalInfo
    status: int8


@dataclasses.dataclass
class GoalStatusArray(IdlStruct, typename=dds_name("action_msgs/msg/GoalStatusArray")):
    status_list: sequence[GoalStatus]


@dataclasses.dataclass
class CancelGoalRequest(IdlStruct, typename=dds_name("action_msgs/srv/CancelGoal_Request")):
    guid: uint64
    seq: int64
    goal_info: GoalInfo


@dataclasses.dataclass
class CancelGoalResponse(IdlStruct, typename=dds_name("action_msgs/srv/CancelGoal_Response")):
    guid: uint64
    seq: int64
    return_code: int8
    goals_canceling: sequence[GoalInfo]


@dataclasses.dataclass
class FibonacciGoal(IdlStruct, typename=dds_name("example_interfaces/action/Fibonacci_Goal")):
    order: int32


@dataclasses.dataclass
class FibonacciResult(IdlStruct, typename=dds_name("example_interfaces/action/Fibonacci_Result")):
    sequence: sequence[int32]


@dataclasses.dataclass
class FibonacciFeedback(IdlStruct, typename=dds_name("example_interfaces/action/Fibonacci_Feedback")):
    sequence: sequence[int32]


@dataclasses.dataclass
class FibonacciSendGoalRequest(IdlStruct, typename=dds_name("example_interfaces/action/Fibonacci_SendGoal_Request")):
    guid: uint64
    seq: int64
    goal_id: UUID
    goal: FibonacciGoal


@dataclasses.dataclass
class FibonacciSendGoalResponse(IdlStruct, typename=dds_name("example_interfaces/action/Fibonacci_SendGoal_Response")):
    guid: uint64
    seq: int64
    accepted: bool
    stamp: Time


@dataclasses.dataclass
class FibonacciGetResultRequest(IdlStruct, typename=dds_name("example_interfaces/action/Fibonacci_GetResult_Request")):
    guid: uint64
    seq: int64
    goal_id: UUID


@dataclasses.dataclass
class FibonacciGetResultResponse(IdlStruct, typename=dds_name("example_interfaces/action/Fibonacci_GetResult_Response")):
    guid: uint64
    seq: int64
    status: int8
    result: FibonacciResult


@dataclasses.dataclass
class FibonacciFeedbackMessage(IdlStruct, typename=dds_name("example_interfaces/action/Fibonacci_FeedbackMessage")):
    goal_id: UUID
    feedback: FibonacciFeedback


# action_msgs/msg/GoalStatus codes
ACCEPTED, EXECUTING, CANCELING, SUCCEEDED, CANCELED, ABORTED = 1, 2, 3, 4, 5, 6


# ---------------------------------------------------------------- QoS

def qos(reliable=True, transient_local=False, depth=10):
    """A ROS 2-like QoS profile. The default is rmw's: reliable, volatile, keep last 10."""
    return Qos(
        Policy.Reliability.Reliable(duration(seconds=1)) if reliable else Policy.Reliability.BestEffort,
        Policy.Durability.TransientLocal if transient_local else Policy.Durability.Volatile,
        Policy.History.KeepLast(depth),
        Policy.DataRepresentation(use_cdrv0_representation=True),
    )


DEFAULT_QOS = qos()
# What ROS 2 uses for latched topics (/robot_description, /tf_static, ...).
LATCHED_QOS = qos(transient_local=True, depth=1)
# rcl_action's profile for the status topic.
ACTION_STATUS_QOS = qos(transient_local=True, depth=1)


# ---------------------------------------------------------------- rosbags cross-check

def ros2_defs_dir():
    """The ROS 2 definitions bundled with fleetlink (read only)."""
    here = os.path.dirname(os.path.abspath(__file__))
    return os.path.join(here, "..", "..", "..", "crates", "msg", "defs", "ros2")


def typestore(battery_msg_text):
    """rosbags' own ROS 2 (Humble) type store, plus the suite's custom type from its .msg
    text and the service and action parts this suite uses, from fleetlink's bundled
    .srv/.action files. rosbags resolves relative names only for `pkg/msg/T`, so service
    and action parts are registered under msg/ (their bytes do not depend on the name)."""
    from rosbags.typesys import Stores, get_types_from_msg, get_typestore

    store = get_typestore(Stores.ROS2_HUMBLE)
    store.register(get_types_from_msg(battery_msg_text, "fltest_msgs/msg/Battery"))
    defs = ros2_defs_dir()
    for path, parts in (
        ("example_interfaces/srv/AddTwoInts.srv", ["AddTwoInts_Request", "AddTwoInts_Response"]),
        ("std_srvs/srv/Trigger.srv", ["Trigger_Request", "Trigger_Response"]),
        ("action_msgs/srv/CancelGoal.srv", ["CancelGoal_Request", "CancelGoal_Response"]),
        ("rcl_interfaces/srv/GetParameters.srv", ["GetParameters_Request", "GetParameters_Response"]),
        ("rcl_interfaces/srv/SetParameters.srv", ["SetParameters_Request", "SetParameters_Response"]),
        ("rcl_interfaces/srv/ListParameters.srv", ["ListParameters_Request", "ListParameters_Response"]),
        ("example_interfaces/action/Fibonacci.action", ["Fibonacci_Goal", "Fibonacci_Result", "Fibonacci_Feedback"]),
    ):
        with open(os.path.join(defs, path)) as f:
            sections = [[]]
            for line in f.read().splitlines():
                if line.strip() == "---":
                    sections.append([])
                else:
                    sections[-1].append(line)
        sections = ["\n".join(lines) + "\n" for lines in sections]
        pkg = path.split("/")[0]
        for part, body in zip(parts, sections, strict=True):
            store.register(get_types_from_msg(body, f"{pkg}/msg/{part}"))
    # The action's wrapper types (what rosidl generates around Goal/Result/Feedback).
    ei = "example_interfaces/msg/Fibonacci"
    for part, body in (
        ("_SendGoal_Request", "unique_identifier_msgs/UUID goal_id\nFibonacci_Goal goal\n"),
        ("_SendGoal_Response", "bool accepted\nbuiltin_interfaces/Time stamp\n"),
        ("_GetResult_Request", "unique_identifier_msgs/UUID goal_id\n"),
        ("_GetResult_Response", "int8 status\nFibonacci_Result result\n"),
        ("_FeedbackMessage", "unique_identifier_msgs/UUID goal_id\nFibonacci_Feedback feedback\n"),
    ):
        store.register(get_types_from_msg(body, ei + part))
    return store


def rosbags_name(cls):
    """The name a class's type is registered under in typestore()."""
    pkg, kind, name = ros_name(cls).split("/")
    return f"{pkg}/msg/{name}"


NUMPY = {"bool": np.bool_, "int8": np.int8, "uint8": np.uint8, "byte": np.uint8, "char": np.uint8,
         "int16": np.int16, "uint16": np.uint16, "int32": np.int32, "uint32": np.uint32,
         "int64": np.int64, "uint64": np.uint64, "float32": np.float32, "float64": np.float64}


def idl_shape(hint):
    """A Cyclone IDL field type in the form of a rosbags field definition."""
    from rosbags.typesys.store import Nodetype

    if hint is str:
        return (Nodetype.BASE, ("string", 0))
    if hint is bool:
        return (Nodetype.BASE, ("bool", 0))
    if isinstance(hint, bounded_str):
        return (Nodetype.BASE, ("string", hint.max_length))
    if getattr(hint, "__metadata__", None):  # Annotated[int, 'uint8'] and the like
        return (Nodetype.BASE, (hint.__metadata__[0], 0))
    if isinstance(hint, array):
        return (Nodetype.ARRAY, (idl_shape(hint.subtype), hint.length))
    if isinstance(hint, sequence):
        return (Nodetype.SEQUENCE, (idl_shape(hint.subtype), hint.max_length or 0))
    if isinstance(hint, type) and issubclass(hint, IdlStruct):
        return (Nodetype.NAME, rosbags_name(hint))
    raise ValueError(f"no ROS 2 equivalent for the IDL type {hint}")


def same_bytes(nt, det):
    """A rosbags field type with ROS's `char` read as `uint8`: one unsigned byte on the
    wire either way (see discovery_types for why the IDL side says uint8)."""
    from rosbags.typesys.store import Nodetype

    if nt == Nodetype.BASE and det[0] == "char":
        return (nt, ("uint8", det[1]))
    if nt in (Nodetype.ARRAY, Nodetype.SEQUENCE):
        (ent, edet), size = det
        return (nt, (same_bytes(ent, edet), size))
    return (nt, det)


def to_rosbags(store, name, obj, path):
    """The rosbags message `name` holding the values of IDL struct `obj`. The two field
    lists must be the same (names and order; the service header aside), else ValueError."""
    from rosbags.typesys.store import Nodetype

    _, fields = store.fielddefs[name]
    ours = [f.name for f in dataclasses.fields(obj) if f.name not in SERVICE_HEADER]
    theirs = [n for n, _ in fields]
    if ours != theirs:
        raise ValueError(f"{path}: fields {ours} but rosbags' {name} has {theirs}")

    def value(nt, det, v, where):
        if nt == Nodetype.BASE:
            return v
        if nt == Nodetype.NAME:
            return to_rosbags(store, det, v, where)
        (ent, edet), _size = det
        if ent == Nodetype.BASE and edet[0] != "string":
            return np.array(list(v), dtype=NUMPY[edet[0]])
        return [value(ent, edet, x, f"{where}[{i}]") for i, x in enumerate(v)]

    # Equal bytes for the values sent need not mean equal types (a uint8 followed by
    # padding looks like a uint16): compare the declared field types as well.
    hints = get_extended_type_hints(type(obj))
    for n, (nt, det) in fields:
        if idl_shape(hints[n]) != same_bytes(nt, det):
            raise ValueError(f"{path}.{n}: Cyclone type {hints[n]} but rosbags' {name} declares {(nt, det)}")
    kwargs = {n: value(nt, det, getattr(obj, n), f"{path}.{n}") for n, (nt, det) in fields}
    return store.types[name](**kwargs)


def crosscheck(store, obj):
    """Serializes `obj` with Cyclone and with rosbags; returns None when the CDR bytes are
    equal, else a description of the difference. For service samples the 16-byte header
    is cut out first: it starts at offset 0 and is 8 bytes aligned, so the ROS fields after
    it have the same alignment as they have on their own."""
    cls = type(obj)
    ours = bytes(obj.serialize(use_version_2=False))
    if [f.name for f in dataclasses.fields(obj)][:2] == list(SERVICE_HEADER):
        ours = ours[:4] + ours[4 + 16:]
    try:
        theirs = bytes(store.serialize_cdr(to_rosbags(store, rosbags_name(cls), obj, cls.__name__), rosbags_name(cls)))
    except ValueError as e:
        return str(e)
    if ours == theirs:
        return None
    at = next((i for i, (a, b) in enumerate(zip(ours, theirs)) if a != b), min(len(ours), len(theirs)))
    return (f"{ros_name(cls)}: Cyclone wrote {len(ours)} bytes, rosbags {len(theirs)}; first difference at "
            f"byte {at}: {ours[at:at + 8].hex()} vs {theirs[at:at + 8].hex()}")
