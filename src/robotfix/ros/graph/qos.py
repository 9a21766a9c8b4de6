"""ROS 2 QoS profiles where the code spells them as constants, and when a
subscription can never match a publisher (the ROS 2 documentation's "QoS
compatibilities" tables: a reliable subscription and a best-effort publisher, a
transient-local subscription and a volatile publisher, never connect).

A profile's unknown policy (the RMW's system default, a value computed at run
time) makes no finding.
"""

from __future__ import annotations

from robotfix.ros.graph.model import Qos

RELIABLE = "reliable"
BEST_EFFORT = "best_effort"
VOLATILE = "volatile"
TRANSIENT_LOCAL = "transient_local"

# rclpy.qos / rmw's preset profiles (rmw/qos_profiles.h), by their Python names
_SENSOR = Qos(BEST_EFFORT, VOLATILE, 5)
_DEFAULT = Qos(RELIABLE, VOLATILE, 10)
PY_PROFILES: dict[str, Qos] = {
    "qos_profile_sensor_data": _SENSOR,
    "qos_profile_default": _DEFAULT,
    "qos_profile_services_default": _DEFAULT,
    "qos_profile_parameters": Qos(RELIABLE, VOLATILE, 1000),
    "qos_profile_parameter_events": Qos(RELIABLE, VOLATILE, 1000),
    "qos_profile_action_status_default": Qos(RELIABLE, TRANSIENT_LOCAL, 1),
    "qos_profile_system_default": Qos(None, None, None),
    "SENSOR_DATA": _SENSOR,
    "SYSTEM_DEFAULT": Qos(None, None, None),
    "SERVICES_DEFAULT": _DEFAULT,
    "PARAMETERS": Qos(RELIABLE, VOLATILE, 1000),
    "PARAMETER_EVENTS": Qos(RELIABLE, VOLATILE, 1000),
    "ACTION_STATUS_DEFAULT": Qos(RELIABLE, TRANSIENT_LOCAL, 1),
}
# rclcpp's QoS classes (rclcpp/qos.hpp): `rclcpp::SensorDataQoS()`
CPP_PROFILES: dict[str, Qos] = {
    "SensorDataQoS": _SENSOR,
    "ParametersQoS": Qos(RELIABLE, VOLATILE, 1000),
    "ServicesQoS": _DEFAULT,
    "ParameterEventsQoS": Qos(RELIABLE, VOLATILE, 1000),
    "RosoutQoS": Qos(RELIABLE, TRANSIENT_LOCAL, 1000),
    "SystemDefaultsQoS": Qos(None, None, None),
    "ClockQoS": Qos(BEST_EFFORT, VOLATILE, 1),
}
# policy enum members (rclpy's ReliabilityPolicy / QoSReliabilityPolicy, and the
# RMW_QOS_POLICY_* spellings; rclcpp's ReliabilityPolicy::BestEffort, ...)
POLICIES: dict[str, tuple[str, str | None]] = {
    "RELIABLE": ("reliability", RELIABLE),
    "BEST_EFFORT": ("reliability", BEST_EFFORT),
    "RMW_QOS_POLICY_RELIABILITY_RELIABLE": ("reliability", RELIABLE),
    "RMW_QOS_POLICY_RELIABILITY_BEST_EFFORT": ("reliability", BEST_EFFORT),
    "RMW_QOS_POLICY_RELIABILITY_SYSTEM_DEFAULT": ("reliability", None),
    "Reliable": ("reliability", RELIABLE),
    "BestEffort": ("reliability", BEST_EFFORT),
    "VOLATILE": ("durability", VOLATILE),
    "TRANSIENT_LOCAL": ("durability", TRANSIENT_LOCAL),
    "RMW_QOS_POLICY_DURABILITY_VOLATILE": ("durability", VOLATILE),
    "RMW_QOS_POLICY_DURABILITY_TRANSIENT_LOCAL": ("durability", TRANSIENT_LOCAL),
    "RMW_QOS_POLICY_DURABILITY_SYSTEM_DEFAULT": ("durability", None),
    "Volatile": ("durability", VOLATILE),
    "TransientLocal": ("durability", TRANSIENT_LOCAL),
    "SYSTEM_DEFAULT": ("", None),
}
# rclcpp::QoS's setters: `rclcpp::QoS(10).best_effort().transient_local()`
CPP_SETTERS: dict[str, tuple[str, str]] = {
    "reliable": ("reliability", RELIABLE),
    "best_effort": ("reliability", BEST_EFFORT),
    "durability_volatile": ("durability", VOLATILE),
    "transient_local": ("durability", TRANSIENT_LOCAL),
}
# setters that change nothing RobotFix compares
CPP_NEUTRAL = frozenset(
    {
        "keep_last",
        "keep_all",
        "history",
        "deadline",
        "lifespan",
        "liveliness",
        "liveliness_lease_duration",
        "avoid_ros_namespace_conventions",
    }
)


def depth_only(depth: int | None) -> Qos:
    """`create_publisher(T, 'x', 10)`: a depth is rclpy's and rclcpp's default
    profile with that history depth (reliable, volatile)."""
    return Qos(RELIABLE, VOLATILE, depth)


def incompatible(publisher: Qos, subscription: Qos) -> list[str]:
    """Why a subscription with `subscription` never hears a publisher with
    `publisher` (empty: it may)."""
    why = []
    if publisher.reliability == BEST_EFFORT and subscription.reliability == RELIABLE:
        why.append(
            "the subscription asks reliable delivery, the publisher offers best effort"
        )
    if publisher.durability == VOLATILE and subscription.durability == TRANSIENT_LOCAL:
        why.append(
            "the subscription asks transient-local durability, the "
            "publisher offers volatile"
        )
    return why
