// The last function of this file is damaged (a merge left it unfinished): the rest still counts.
#include <memory>

#include "rclcpp/rclcpp.hpp"
#include "rclcpp_action/rclcpp_action.hpp"
#include "nav2_msgs/action/dock_robot.hpp"
#include "std_msgs/msg/bool.hpp"

class DockingServer : public rclcpp::Node
{
public:
  using DockRobot = nav2_msgs::action::DockRobot;

  DockingServer()
  : rclcpp::Node("docking_server")
  {
    charging_pub_ = create_publisher<std_msgs::msg::Bool>("is_charging", 1);
    server_ = rclcpp_action::create_server<DockRobot>(
      this, "dock_robot",
      [](const rclcpp_action::GoalUUID &, std::shared_ptr<const DockRobot::Goal>) {
        return rclcpp_action::GoalResponse::ACCEPT_AND_EXECUTE;
      },
      [](const std::shared_ptr<rclcpp_action::ServerGoalHandle<DockRobot>>) {
        return rclcpp_action::CancelResponse::ACCEPT;
      },
      [](const std::shared_ptr<rclcpp_action::ServerGoalHandle<DockRobot>>) {});
  }

  void report_undocked();

private:
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr charging_pub_;
  rclcpp::Publisher<std_msgs::msg::Bool>::SharedPtr undocked_pub_;
  rclcpp_action::Server<DockRobot>::SharedPtr server_;
};

void DockingServer::report_undocked(
{
  undocked_pub_ = create_publisher<std_msgs::msg::Bool>("undocked" 1;
  undocked_pub_->publish(std_msgs::msg::Bool());
