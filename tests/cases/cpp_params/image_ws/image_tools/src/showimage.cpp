// After ros2/demos image_tools/src/showimage.cpp: its parameters, no window.
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace image_tools
{
class ShowImage : public rclcpp::Node
{
public:
  explicit ShowImage(const rclcpp::NodeOptions & options)
  : Node("showimage", options)
  {
    depth_ = this->declare_parameter("depth", 10);
    show_image_ = this->declare_parameter("show_image", true);
    window_name_ = this->declare_parameter("window_name", "");
    sub_ = create_subscription<sensor_msgs::msg::Image>(
      "image", depth_, [](sensor_msgs::msg::Image::ConstSharedPtr) {});
  }

private:
  int64_t depth_;
  bool show_image_;
  std::string window_name_;
  rclcpp::Subscription<sensor_msgs::msg::Image>::SharedPtr sub_;
};
}  // namespace image_tools

RCLCPP_COMPONENTS_REGISTER_NODE(image_tools::ShowImage)
