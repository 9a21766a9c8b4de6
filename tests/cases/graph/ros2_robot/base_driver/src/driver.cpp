// A base driver, modelled on turtlebot3_node and ros2/demos' dummy_sensors.
#include <memory>

#include "geometry_msgs/msg/twist.hpp"
#include "nav_msgs/msg/odometry.hpp"
#include "rclcpp/rclcpp.hpp"
#include "sensor_msgs/msg/laser_scan.hpp"
#include "std_msgs/msg/bool.hpp"
#include "std_msgs/msg/string.hpp"

namespace base_driver
{
using Twist = geometry_msgs::msg::Twist;

class BaseDriver : public rclcpp::Node
{
public:
  BaseDriver()
  : Node("base_driver")
  {
    max_speed_ = declare_parameter<double>("max_speed", 0.5);
    cmd_sub_ = create_subscription<Twist>(  // error: RF603
      "base/cmd_vel", 10,
      [this](const Twist::SharedPtr msg) {(void)msg;});
    scan_pub_ = create_publisher<sensor_msgs::msg::LaserScan>("scan", rclcpp::SensorDataQoS());
    odom_pub_ = this->create_publisher<nav_msgs::msg::Odometry>("odom", rclcpp::QoS(10));
    status_pub_ = create_publisher<std_msgs::msg::String>("~/status", 10);
    estop_sub_ = create_subscription<std_msgs::msg::Bool>(  // note: RF606
      "/emergency_stop", rclcpp::QoS(1).reliable(),
      [this](const std_msgs::msg::Bool::SharedPtr msg) {(void)msg;});
  }

private:
  double max_speed_;
  rclcpp::Subscription<Twist>::SharedPtr cmd_sub_;
  rclcpp::Subscription<std_msgs::msg::Bool>::SharedPtr estop_sub_;
  rclcpp::Publisher<sensor_msgs::msg::LaserScan>::SharedPtr scan_pub_;
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr odom_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
};
}  // namespace base_driver
