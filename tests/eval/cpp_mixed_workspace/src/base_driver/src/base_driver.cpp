#include "base_driver/base_driver.hpp"

#include <chrono>
#include <memory>

#include "rclcpp_components/register_node_macro.hpp"

namespace base_driver
{

static constexpr char kStatusTopic[] = "driver_status";

BaseDriver::BaseDriver(const rclcpp::NodeOptions & options)
: Node("base_driver", options)
{
  odom_topic_ = this->declare_parameter<std::string>("odom_topic", "odom");
  odom_pub_ = this->create_publisher<nav_msgs::msg::Odometry>(odom_topic_, 10);
  battery_pub_ = create_publisher<BatteryMsg>("battery", rclcpp::QoS(5));
  status_pub_ = this->create_publisher<std_msgs::msg::String>(kStatusTopic, 10);
  reset_srv_ = this->create_service<std_srvs::srv::Trigger>(
    "~/reset", std::bind(&BaseDriver::on_reset, this, std::placeholders::_1, std::placeholders::_2));
  timer_ = create_wall_timer(std::chrono::milliseconds(50), [this]() {publish_state();});
}

// The IMU topic is chosen by the caller: unknown here, but only an IMU subscription could be it.
void BaseDriver::watch_imu(const std::string & topic)
{
  imu_sub_ = create_subscription<sensor_msgs::msg::Imu>(
    topic, rclcpp::SensorDataQoS(), [](sensor_msgs::msg::Imu::ConstSharedPtr) {});
}

void BaseDriver::publish_state()
{
  odom_pub_->publish(nav_msgs::msg::Odometry());
  battery_pub_->publish(BatteryMsg());
}

void BaseDriver::on_reset(
  const std::shared_ptr<std_srvs::srv::Trigger::Request>,
  std::shared_ptr<std_srvs::srv::Trigger::Response> response)
{
  response->success = true;
}

}  // namespace base_driver

RCLCPP_COMPONENTS_REGISTER_NODE(base_driver::BaseDriver)
