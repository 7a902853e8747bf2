#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "wheel_base/wheel_controller.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<wheel_base::WheelController>());
  rclcpp::shutdown();
  return 0;
}
