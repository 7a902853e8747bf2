#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/trigger.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("wheel_calibrator");
  auto client = node->create_client<std_srvs::srv::Trigger>("calibrate");
  rclcpp::shutdown();
  return 0;
}
