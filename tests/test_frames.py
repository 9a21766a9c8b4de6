"""The frame data (`ros/frames_model.py`) against the standard messages, and frame
names as tf2 compares them."""

from __future__ import annotations

import pytest

from robotfix import api
from robotfix.analysis.frames import known_frame, normalize
from robotfix.analysis.values import Value
from robotfix.annotations import ast as A
from robotfix.ros.catalog import FieldSpec, MsgCatalog
from robotfix.ros.frames_model import FRAMED_FIELDS, TF2_CALLS, TRANSFORM_TYPE

CATALOG = MsgCatalog([])


def field_at(msg_type: str, path: str) -> FieldSpec:
    spec = CATALOG.lookup(msg_type)
    assert spec is not None, msg_type
    *parents, last = path.split(".")
    for part in parents:
        sub = spec.fields[part]
        assert sub.kind == "msg" and sub.msg_type and not sub.array, (msg_type, path)
        found = CATALOG.lookup(sub.msg_type)
        assert found is not None, sub.msg_type
        spec = found
    return spec.fields[last]


@pytest.mark.parametrize("msg_type", sorted(FRAMED_FIELDS))
def test_framed_fields_name_a_message_and_a_frame_string(msg_type: str) -> None:
    for prefix, frame_path in FRAMED_FIELDS[msg_type]:
        data = field_at(msg_type, prefix)
        assert data.kind == "msg" and not data.array, (msg_type, prefix)
        frame = field_at(msg_type, frame_path)
        assert frame.kind == "str" and not frame.array, (msg_type, frame_path)


def test_transform_stamped_relates_two_frames_and_is_not_framed() -> None:
    assert TRANSFORM_TYPE not in FRAMED_FIELDS
    assert field_at(TRANSFORM_TYPE, "header.frame_id").kind == "str"
    assert field_at(TRANSFORM_TYPE, "child_frame_id").kind == "str"


def test_tf2_argument_positions_follow_geometry2() -> None:
    # tf2_ros Buffer.lookup_transform(target_frame, source_frame, time, timeout)
    lookup = TF2_CALLS["lookup_transform"]
    assert (lookup.target, lookup.source) == ((0, "target_frame"), (1, "source_frame"))
    # BufferInterface.transform(object_stamped, target_frame, timeout, new_type)
    moved = TF2_CALLS["transform"]
    assert (moved.data, moved.target) == ((0, "object_stamped"), (1, "target_frame"))
    # tf2_geometry_msgs.do_transform_*(value, transform)
    for name, call in TF2_CALLS.items():
        if name.startswith("do_transform_"):
            assert call.kind == "apply" and call.transform == (1, "transform")


def test_one_leading_slash_is_stripped_as_tf2_does() -> None:
    assert normalize("/map") == "map"
    assert normalize("map") == "map"
    assert normalize("//map") == "/map"  # stripSlash removes one


@pytest.mark.parametrize(
    ("value", "frame"),
    [
        (Value("str", A.Str("/odom")), "odom"),
        (Value("str", A.Str("camera_link_optical")), "camera_link_optical"),
        (Value("str", A.Str("")), None),  # tf2: frame ids cannot be empty
        (Value("str", A.Str("/")), None),
        (Value("str", A.Sym(1, "str")), None),  # not known
        (Value("str", A.Sym(2, "str"), frame="map"), "map"),  # a parameter default
    ],
)
def test_known_frames(value: Value, frame: str | None) -> None:
    assert known_frame(value) == frame


STAMPED = """from geometry_msgs.msg import PointStamped

p = PointStamped()
p.header.frame_id = "/odom"
x = p.point.x
"""


def test_hover_on_a_field_of_a_stamped_message_names_its_frame() -> None:

    col = STAMPED.splitlines()[4].index(".x") + 1
    found = api.hover(STAMPED, "p.py", 5, col, CATALOG)
    assert found is not None
    assert "in `m` in frame `odom` (its message's `header.frame_id`)" in found
