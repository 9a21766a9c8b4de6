from rclpy.action.client import ActionClient as ActionClient
