#ifndef BASE_DRIVER__BASE_DRIVER_HPP_
#define BASE_DRIVER__BASE_DRIVER_HPP_

#include <string>

#include "rclcpp/rclcpp.hpp"
#include "nav_msgs/msg/odometry.hpp"
#include "sensor_msgs/msg/battery_state.hpp"
#include "sensor_msgs/msg/imu.hpp"
#include "std_msgs/msg/string.hpp"
#include "std_srvs/srv/trigger.hpp"
#include "base_driver/visibility_control.h"

namespace base_driver
{

using BatteryMsg = sensor_msgs::msg::BatteryState;

// A generic helper: neither the topic nor the type is known here, so it is no partner end.
template<typename MsgT>
typename rclcpp::Subscription<MsgT>::SharedPtr watch(rclcpp::Node * node, const std::string & topic)
{
  return node->create_subscription<MsgT>(topic, 10, [](typename MsgT::ConstSharedPtr) {});
}

// The motor controller bridge: odometry and battery out, status text out, a reset service.
class BaseDriver : public rclcpp::Node
{
public:
  BASE_DRIVER_PUBLIC
  explicit BaseDriver(const rclcpp::NodeOptions & options);

private:
  void publish_state();
  void watch_imu(const std::string & topic);
  void on_reset(
    const std::shared_ptr<std_srvs::srv::Trigger::Request> request,
    std::shared_ptr<std_srvs::srv::Trigger::Response> response);

  std::string odom_topic_;
  rclcpp::Publisher<nav_msgs::msg::Odometry>::SharedPtr odom_pub_;
  rclcpp::Publisher<BatteryMsg>::SharedPtr battery_pub_;
  rclcpp::Publisher<std_msgs::msg::String>::SharedPtr status_pub_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr reset_srv_;
  rclcpp::TimerBase::SharedPtr timer_;
  rclcpp::Subscription<sensor_msgs::msg::Imu>::SharedPtr imu_sub_;
};

}  // namespace base_driver

#endif  // BASE_DRIVER__BASE_DRIVER_HPP_
