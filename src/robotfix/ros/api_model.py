"""What rclpy and rospy calls mean to the checker: pure data, no logic.

Registrations name where the interface type and the callback are among a call's
arguments (position, keyword); the analysis finds them syntactically so every
callback is analysed as an entry point that receives messages. The units of
parameters and results are not here: they are in the stubs (`robotfix/stubs/data`).
"""

from __future__ import annotations

from dataclasses import dataclass


@dataclass(frozen=True)
class Registration:
    """Where a registration call takes its interface type and its callback."""

    kind: str  # subscription, service, action, timer
    type_arg: tuple[int, str] | None  # (position, keyword) of the interface type
    callback_arg: tuple[int, str]  # (position, keyword) of the callback


# Keyed by the called name's last part; `rospy.Subscriber` and `Subscriber` alike.
REGISTRATIONS: dict[str, Registration] = {
    # ROS 2: Node methods
    "create_subscription": Registration(
        "subscription", (0, "msg_type"), (2, "callback")
    ),
    "create_service": Registration("service", (0, "srv_type"), (2, "callback")),
    "create_timer": Registration("timer", None, (1, "callback")),
    # ROS 2: rclpy.action
    "ActionServer": Registration("action", (1, "action_type"), (3, "execute_callback")),
    # ROS 1: rospy
    "Subscriber": Registration("subscription", (1, "data_class"), (2, "callback")),
    "Service": Registration("service1", (1, "service_class"), (2, "handler")),
    "Timer": Registration("timer", None, (1, "callback")),
    "SimpleActionServer": Registration("action1", (1, "ActionSpec"), (2, "execute_cb")),
}

# Calls that make a time object, not a number of seconds (`rospy.Duration(5)`).
TIME_OBJECTS = frozenset({"Duration", "Time"})


# Parameters (robotfix.analysis.parameters): what builds a node, rclpy's
# Parameter.Type names, and the fields of a ParameterValue by the type they hold.
NODE_CONSTRUCTORS = frozenset({"Node", "LifecycleNode", "create_node"})
PARAMETER_TYPES: dict[str, str] = {
    "BOOL": "bool",
    "INTEGER": "integer",
    "DOUBLE": "double",
    "STRING": "string",
    "BYTE_ARRAY": "byte_array",
    "BOOL_ARRAY": "bool_array",
    "INTEGER_ARRAY": "integer_array",
    "DOUBLE_ARRAY": "double_array",
    "STRING_ARRAY": "string_array",
}
PARAMETER_VALUE_FIELDS: dict[str, str] = {
    f"{name}_value": name for name in PARAMETER_TYPES.values()
}
# The analysis' value kind for a parameter of each scalar type
PARAMETER_KINDS: dict[str, str] = {
    "bool": "bool",
    "integer": "int",
    "double": "float",
    "string": "str",
}
# The ParameterValue field a type's value is not in holds its message default
PARAMETER_FIELD_DEFAULTS: dict[str, object] = {
    "bool": False,
    "integer": 0,
    "double": 0.0,
    "string": "",
}
PARAMETER_CALLS = frozenset(
    {"declare_parameter", "declare_parameters", "get_parameter", "get_param"}
)


@dataclass(frozen=True)
class EndpointCall:
    """A call that makes a graph endpoint (`robotfix.ros.graph.python`)."""

    kind: str  # robotfix.ros.graph.model's kinds
    ros: int
    type_arg: tuple[int, str]  # (position, keyword) of the interface type
    name_arg: tuple[int, str]  # of the topic, service or action name
    qos_arg: tuple[int, str] | None = None  # of the ROS 2 QoS profile
    # of the callback whose first parameter (after `self`) takes what the other
    # side sends: a subscription's message, a service's request, an action's goal
    taken_arg: tuple[int, str] | None = None


def _type_of(called: str) -> tuple[int, str]:
    registration = REGISTRATIONS[called]
    assert registration.type_arg is not None
    return registration.type_arg


def _taken(called: str) -> tuple[int, str]:
    return REGISTRATIONS[called].callback_arg


# rclpy's ActionServer takes `goal_callback` by keyword only (no position reaches
# it); it receives the goal, the execute callback a goal handle
GOAL_CALLBACK = (1 << 16, "goal_callback")


# Node methods, by name whatever the receiver (as REGISTRATIONS)
ENDPOINT_METHODS: dict[str, EndpointCall] = {
    "create_publisher": EndpointCall(
        "publisher", 2, (0, "msg_type"), (1, "topic"), (2, "qos_profile")
    ),
    "create_subscription": EndpointCall(
        "subscription",
        2,
        _type_of("create_subscription"),
        (1, "topic"),
        (3, "qos_profile"),
        _taken("create_subscription"),
    ),
    "create_service": EndpointCall(
        "service",
        2,
        _type_of("create_service"),
        (1, "srv_name"),
        taken_arg=_taken("create_service"),
    ),
    "create_client": EndpointCall("client", 2, (0, "srv_type"), (1, "srv_name")),
}
# Classes and functions, by qualified name (what the file's imports make of it)
ENDPOINT_CLASSES: dict[str, EndpointCall] = {
    "rclpy.action.ActionServer": EndpointCall(
        "action_server",
        2,
        _type_of("ActionServer"),
        (2, "action_name"),
        taken_arg=GOAL_CALLBACK,
    ),
    "rclpy.action.ActionClient": EndpointCall(
        "action_client", 2, (1, "action_type"), (2, "action_name")
    ),
    "rospy.Publisher": EndpointCall("publisher", 1, (1, "data_class"), (0, "name")),
    "rospy.Subscriber": EndpointCall(
        "subscription",
        1,
        _type_of("Subscriber"),
        (0, "name"),
        None,
        _taken("Subscriber"),
    ),
    "rospy.Service": EndpointCall(
        "service", 1, _type_of("Service"), (0, "name"), None, _taken("Service")
    ),
    "rospy.ServiceProxy": EndpointCall("client", 1, (1, "service_class"), (0, "name")),
    "actionlib.SimpleActionServer": EndpointCall(
        "action_server",
        1,
        _type_of("SimpleActionServer"),
        (0, "name"),
        taken_arg=_taken("SimpleActionServer"),
    ),
    "actionlib.SimpleActionClient": EndpointCall(
        "action_client", 1, (1, "ActionSpec"), (0, "ns")
    ),
    "actionlib.ActionServer": EndpointCall(
        "action_server", 1, (1, "ActionSpec"), (0, "ns")
    ),
    "actionlib.ActionClient": EndpointCall(
        "action_client", 1, (1, "ActionSpec"), (0, "ns")
    ),
}
ENDPOINT_CLASSES["rclpy.action.server.ActionServer"] = ENDPOINT_CLASSES[
    "rclpy.action.ActionServer"
]
ENDPOINT_CLASSES["rclpy.action.client.ActionClient"] = ENDPOINT_CLASSES[
    "rclpy.action.ActionClient"
]
ENDPOINT_CLASSES["rospy.topics.Publisher"] = ENDPOINT_CLASSES["rospy.Publisher"]
ENDPOINT_CLASSES["rospy.topics.Subscriber"] = ENDPOINT_CLASSES["rospy.Subscriber"]
# The words a file holds when it may make an endpoint (checked on its bytes)
ENDPOINT_WORDS = (
    b"create_publisher",
    b"create_subscription",
    b"create_service",
    b"create_client",
    b"Action",
    b"rospy",
)
