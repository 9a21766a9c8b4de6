// After navigation2's nav2_velocity_smoother/src/velocity_smoother.cpp: its
// parameters, declared in on_configure with nav2_util's helper.
#include <string>
#include <vector>

#include "geometry_msgs/msg/twist.hpp"
#include "nav2_util/lifecycle_node.hpp"
#include "nav2_util/node_utils.hpp"

using nav2_util::declare_parameter_if_not_declared;

namespace nav2_velocity_smoother
{
class VelocitySmoother : public nav2_util::LifecycleNode
{
public:
  explicit VelocitySmoother(const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : LifecycleNode("velocity_smoother", "", options)
  {
  }

  nav2_util::CallbackReturn on_configure(const rclcpp_lifecycle::State &)
  {
    auto node = shared_from_this();
    declare_parameter_if_not_declared(node, "smoothing_frequency", rclcpp::ParameterValue(20.0));
    declare_parameter_if_not_declared(
      node, "feedback", rclcpp::ParameterValue(std::string("OPEN_LOOP")));
    declare_parameter_if_not_declared(node, "scale_velocities", rclcpp::ParameterValue(false));
    declare_parameter_if_not_declared(
      node, "max_velocity", rclcpp::ParameterValue(std::vector<double>{0.50, 0.0, 2.5}));
    declare_parameter_if_not_declared(
      node, "min_velocity", rclcpp::ParameterValue(std::vector<double>{-0.50, 0.0, -2.5}));
    declare_parameter_if_not_declared(
      node, "deadband_velocity", rclcpp::ParameterValue(std::vector<double>{0.0, 0.0, 0.0}));
    declare_parameter_if_not_declared(node, "velocity_timeout", rclcpp::ParameterValue(1.0));
    declare_parameter_if_not_declared(node, "odom_topic", rclcpp::ParameterValue("odom"));
    declare_parameter_if_not_declared(node, "odom_duration", rclcpp::ParameterValue(0.1));
    node->get_parameter("smoothing_frequency", smoothing_frequency_);
    smoothed_cmd_pub_ = create_publisher<geometry_msgs::msg::Twist>("cmd_vel_smoothed", 1);
    return nav2_util::CallbackReturn::SUCCESS;
  }

private:
  double smoothing_frequency_;
  rclcpp_lifecycle::LifecyclePublisher<geometry_msgs::msg::Twist>::SharedPtr smoothed_cmd_pub_;
};
}  // namespace nav2_velocity_smoother

#include "rclcpp_components/register_node_macro.hpp"
RCLCPP_COMPONENTS_REGISTER_NODE(nav2_velocity_smoother::VelocitySmoother)
