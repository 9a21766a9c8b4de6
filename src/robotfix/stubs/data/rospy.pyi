# rospy (ROS 1), checked against ros/ros_comm clients/rospy (noetic-devel, 2023-11)
# and genpy's TVal: Duration(secs=0, nsecs=0), Time(secs=0, nsecs=0),
# wait_for_service(service, timeout=None) (the name first),
# wait_for_message(topic, topic_type, timeout=None), Rate(hz, reset=False).
from typing import Annotated

class Duration:
    secs: Annotated[int, "Unit('s')"]
    nsecs: Annotated[int, "Unit('ns')"]
    def __init__(
        self,
        secs: Annotated[float, "Unit('s')"] = 0,
        nsecs: Annotated[int, "Unit('ns')"] = 0,
    ) -> None: ...
    @classmethod
    def from_sec(cls, float_seconds: Annotated[float, "Unit('s')"]) -> Duration: ...
    def to_sec(self) -> Annotated[float, "Unit('s')"]: ...
    def to_nsec(self) -> Annotated[int, "Unit('ns')"]: ...

class Time:
    secs: Annotated[int, "Unit('s')"]
    nsecs: Annotated[int, "Unit('ns')"]
    def __init__(
        self,
        secs: Annotated[float, "Unit('s')"] = 0,
        nsecs: Annotated[int, "Unit('ns')"] = 0,
    ) -> None: ...
    @staticmethod
    def now() -> Time: ...
    @classmethod
    def from_sec(cls, float_secs: Annotated[float, "Unit('s')"]) -> Time: ...
    @classmethod
    def from_seconds(cls, float_secs: Annotated[float, "Unit('s')"]) -> Time: ...
    def to_sec(self) -> Annotated[float, "Unit('s')"]: ...
    def to_nsec(self) -> Annotated[int, "Unit('ns')"]: ...

class Rate:
    def __init__(
        self, hz: Annotated[float, "Unit('Hz')"], reset: bool = False
    ) -> None: ...
    def sleep(self) -> None: ...

class Timer:
    def __init__(
        self,
        period: Duration,
        callback: object,
        oneshot: bool = False,
        reset: bool = False,
    ) -> None: ...

class ServiceProxy:
    def __init__(
        self,
        name: str,
        service_class: object,
        persistent: bool = False,
        headers: object = None,
    ) -> None: ...
    def wait_for_service(
        self, timeout: Annotated[float, "Unit('s')"] = None
    ) -> None: ...

def sleep(duration: Annotated[float, "Unit('s')"]) -> None: ...
def get_time() -> Annotated[float, "Unit('s')"]: ...
def get_rostime() -> Time: ...
def wait_for_service(
    service: str, timeout: Annotated[float, "Unit('s')"] = None
) -> None: ...
def wait_for_message(
    topic: str, topic_type: object, timeout: Annotated[float, "Unit('s')"] = None
) -> object: ...
