// A stand-alone executable: the node is made in main, the publisher's topic is misspelt.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "std_msgs/msg/string.hpp"

#define SUMMARY_TOPIC "diagnostic_summary"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("diagnostics_aggregator");
  auto summary = node->create_publisher<std_msgs::msg::String>(SUMMARY_TOPIC, 10);
  auto timer = node->create_wall_timer(
    std::chrono::seconds(1), [summary]() {
      std_msgs::msg::String msg;
      msg.data = "ok";
      summary->publish(msg);
    });
  rclcpp::spin(node);
  rclcpp::shutdown();
  return 0;
}
