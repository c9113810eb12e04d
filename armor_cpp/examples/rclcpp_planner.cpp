// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// An rclcpp node that asks ARMOR every second which rooms are occupied, through its own node.
// Built only where rclcpp exists (colcon build in a ROS 2 workspace): ros2 run armor_cpp
// rclcpp_planner.
#include <chrono>
#include <memory>
#include <string>

#include "armor_cpp/armor.hpp"
#include "armor_cpp/rclcpp_transport.hpp"
#include "rclcpp/rclcpp.hpp"

int main(int argc, char ** argv)
{
  rclcpp::init(argc, argv);
  auto node = std::make_shared<rclcpp::Node>("planner");
  armor::Armor armor("planner", std::make_shared<armor::RclcppTransport>(node));
  armor::Reference robotics = armor.reference("robotics");
  rclcpp::Logger logger = node->get_logger();
  // The timer's callback waits for ARMOR's answer; the transport's own callback group lets
  // the executor's other thread deliver it meanwhile.
  auto timer = node->create_wall_timer(std::chrono::seconds(1), [robotics, logger]() {
        try {
          std::string rooms;
          for (const std::string & room : robotics.instances("OccupiedRoom")) {
            rooms += " " + room;
          }
          RCLCPP_INFO(logger, "occupied:%s", rooms.c_str());
        } catch (const armor::Error & error) {
          RCLCPP_WARN(logger, "ARMOR: %s", error.what());
        }
      });
  rclcpp::executors::MultiThreadedExecutor executor;
  executor.add_node(node);
  executor.spin();
  rclcpp::shutdown();
  return 0;
}
