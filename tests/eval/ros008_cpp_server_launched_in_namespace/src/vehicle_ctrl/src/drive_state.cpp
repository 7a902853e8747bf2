#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

// The node is handed in: its entities are the same node's, not another node's.
void start_drive_state(rclcpp::Node * node)
{
  static auto pub = node->create_publisher<std_msgs::msg::String>("drive_mode", 10);
  static auto sub = node->create_subscription<std_msgs::msg::String>(
    "mode_request", 10, [](std_msgs::msg::String::SharedPtr) {});
}
