#include <memory>
#include <string>

#include "rclcpp/rclcpp.hpp"
#include "std_srvs/srv/set_bool.hpp"
#include "std_srvs/srv/trigger.hpp"

void start_drive_state(rclcpp::Node * node);

class CtrlNode : public rclcpp::Node
{
public:
  explicit CtrlNode(const std::string & name)
  : rclcpp::Node(name)
  {
    // Relative names: the launch file puts them under /ctrl_pkg.
    enable_srv_ = create_service<std_srvs::srv::SetBool>(
      "enable_state",
      [](const std::shared_ptr<std_srvs::srv::SetBool::Request>,
      std::shared_ptr<std_srvs::srv::SetBool::Response>) {});
    calibrate_srv_ = create_service<std_srvs::srv::Trigger>(
      "calibrate",
      [](const std::shared_ptr<std_srvs::srv::Trigger::Request>,
      std::shared_ptr<std_srvs::srv::Trigger::Response>) {});
    start_drive_state(this);
  }

private:
  rclcpp::Service<std_srvs::srv::SetBool>::SharedPtr enable_srv_;
  rclcpp::Service<std_srvs::srv::Trigger>::SharedPtr calibrate_srv_;
};

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  rclcpp::spin(std::make_shared<CtrlNode>("ctrl_node"));
  rclcpp::shutdown();
  return 0;
}
