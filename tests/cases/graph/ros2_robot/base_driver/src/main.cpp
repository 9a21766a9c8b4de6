#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "base_driver/driver.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<base_driver::BaseDriver>());
  rclcpp::shutdown();
  return 0;
}
