from geometry_msgs.msg import TransformStamped

class Buffer:
    def lookup_transform(
        self, target_frame: str, source_frame: str, time: object, timeout: object = None
    ) -> TransformStamped: ...
