#include "wheel_base/wheel_controller.hpp"

namespace wheel_base
{

WheelController::WheelController()
: Node("wheel_controller")
{
  this->declare_parameter<double>("wheel_radius", 0.05);
  odom_pub_ = this->create_publisher<nav_msgs::msg::Odometry>("odom", 10);
  reset_srv_ = this->create_service<std_srvs::srv::Trigger>(
    "reset_odometry",
    std::bind(&WheelController::on_reset, this, std::placeholders::_1, std::placeholders::_2));
}

void WheelController::on_reset(
  const std::shared_ptr<std_srvs::srv::Trigger::Request>,
  std::shared_ptr<std_srvs::srv::Trigger::Response> response)
{
  response->success = true;
}

}  // namespace wheel_base
