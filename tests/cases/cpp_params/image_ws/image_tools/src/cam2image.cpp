// After ros2/demos image_tools/src/cam2image.cpp: its parameters, no camera.
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_components/register_node_macro.hpp"
#include "sensor_msgs/msg/image.hpp"

namespace image_tools
{
class Cam2Image : public rclcpp::Node
{
public:
  explicit Cam2Image(const rclcpp::NodeOptions & options)
  : Node("cam2image", options)
  {
    parse_parameters();
    pub_ = create_publisher<sensor_msgs::msg::Image>("image", depth_);
  }

private:
  void parse_parameters()
  {
    rcl_interfaces::msg::ParameterDescriptor reliability_desc;
    reliability_desc.description = "Reliability QoS setting for the image publisher";
    reliability_ = this->declare_parameter("reliability", "reliable", reliability_desc);
    depth_ = this->declare_parameter("depth", 10);
    freq_ = this->declare_parameter("frequency", 30.0);
    show_camera_ = this->declare_parameter("show_camera", false);
    width_ = this->declare_parameter("width", 320);
    height_ = this->declare_parameter("height", 240);
    burger_mode_ = this->declare_parameter<bool>("burger_mode", false);
    exposure_ = this->declare_parameter("exposure", rclcpp::ParameterValue(-0.5)).get<double>();
    frame_id_ = this->declare_parameter("frame_id", std::string("camera_frame"));
  }

  std::string reliability_;
  int64_t depth_;
  double freq_;
  bool show_camera_;
  int64_t width_;
  int64_t height_;
  bool burger_mode_;
  double exposure_;
  std::string frame_id_;
  rclcpp::Publisher<sensor_msgs::msg::Image>::SharedPtr pub_;
};
}  // namespace image_tools

RCLCPP_COMPONENTS_REGISTER_NODE(image_tools::Cam2Image)
