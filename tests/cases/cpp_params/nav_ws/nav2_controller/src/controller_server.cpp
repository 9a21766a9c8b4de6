// After navigation2's nav2_controller/src/controller_server.cpp: its own
// parameters, and the controller plugins pluginlib loads (each declares its own
// parameters, `FollowPath.max_vel_x`, under the name it is given).
#include <string>
#include <vector>

#include "nav2_core/controller.hpp"
#include "nav2_util/lifecycle_node.hpp"
#include "pluginlib/class_loader.hpp"

namespace nav2_controller
{
class ControllerServer : public nav2_util::LifecycleNode
{
public:
  explicit ControllerServer(const rclcpp::NodeOptions & options = rclcpp::NodeOptions())
  : nav2_util::LifecycleNode("controller_server", "", options),
    lp_loader_("nav2_core", "nav2_core::Controller"),
    default_ids_{"FollowPath"},
    default_types_{"dwb_core::DWBLocalPlanner"}
  {
    declare_parameter("controller_frequency", 20.0);
    declare_parameter("controller_plugins", default_ids_);
    declare_parameter("min_x_velocity_threshold", rclcpp::ParameterValue(0.0001));
    declare_parameter("min_theta_velocity_threshold", rclcpp::ParameterValue(0.0001));
    declare_parameter("speed_limit_topic", rclcpp::ParameterValue("speed_limit"));
    declare_parameter("failure_tolerance", rclcpp::ParameterValue(0.0));
    declare_parameter("use_realtime_priority", rclcpp::ParameterValue(false));
    declare_parameter("costmap_update_timeout", 0.30);
  }

  nav2_util::CallbackReturn on_configure(const rclcpp_lifecycle::State &)
  {
    auto node = shared_from_this();
    get_parameter("controller_plugins", controller_ids_);
    for (size_t i = 0; i != controller_ids_.size(); i++) {
      nav2_util::declare_parameter_if_not_declared(
        node, controller_ids_[i] + ".plugin", rclcpp::ParameterValue(default_types_[i]));
      auto controller = lp_loader_.createUniqueInstance(default_types_[i]);
    }
    return nav2_util::CallbackReturn::SUCCESS;
  }

private:
  pluginlib::ClassLoader<nav2_core::Controller> lp_loader_;
  std::vector<std::string> default_ids_;
  std::vector<std::string> default_types_;
  std::vector<std::string> controller_ids_;
};
}  // namespace nav2_controller

#include "rclcpp_components/register_node_macro.hpp"
RCLCPP_COMPONENTS_REGISTER_NODE(nav2_controller::ControllerServer)
