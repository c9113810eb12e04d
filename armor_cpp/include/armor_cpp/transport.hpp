// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// What sends ARMOR's two services: the seam between the typed client and a ROS client library.
//
// RclTransport (rcl_transport.hpp) speaks through rcl, the C layer every ROS 2 install has;
// RclcppTransport (rclcpp_transport.hpp) through an rclcpp node the program already spins.
// A test may put a recording transport in their place.
#ifndef ARMOR_CPP__TRANSPORT_HPP_
#define ARMOR_CPP__TRANSPORT_HPP_

#include <chrono>
#include <functional>
#include <optional>
#include <string>
#include <vector>

#include "armor_msgs/msg/armor_directive_req.hpp"
#include "armor_msgs/msg/armor_directive_res.hpp"
#include "armor_msgs/srv/armor_directive_list.hpp"

namespace armor
{

// The longest wait for one answer; empty: as long as it takes.
using Timeout = std::optional<std::chrono::milliseconds>;

class Transport
{
public:
  virtual ~Transport() = default;

  // Send one directive; ARMOR's response, failed directives included. Throws ServiceCallError
  // (CallTimeout when no answer came in time).
  virtual armor_msgs::msg::ArmorDirectiveRes call(
    const armor_msgs::msg::ArmorDirectiveReq & request, Timeout timeout) = 0;

  // Send an atomic list of directives through armor_interface_serialized_srv.
  virtual armor_msgs::srv::ArmorDirectiveList::Response call_list(
    const std::vector<armor_msgs::msg::ArmorDirectiveReq> & requests, Timeout timeout) = 0;
};

// An ArmorDirectiveReq; every argument is sent as given.
armor_msgs::msg::ArmorDirectiveReq directive(
  const std::string & client, const std::string & reference, const std::string & command,
  const std::string & primary = "", const std::string & secondary = "",
  const std::vector<std::string> & args = {});

// Block until a service has answered a harmless request from this client, as every
// transport does before its first call: a service that is discovered may still drop the
// answer to a client whose response reader it has not matched yet (Fast DDS), and a lost
// answer to a change cannot be asked for again.
//
//   service:       the service's name, for the error.
//   service_wait:  how long to keep trying; ServiceCallError after that.
//   available:     whether the service is discovered yet.
//   ask_harmless:  send the harmless request and wait for its answer at most `attempt`;
//                  throws ServiceCallError (CallTimeout) when none came.
void wait_until_answered(
  const std::string & service, std::chrono::milliseconds service_wait,
  const std::function<bool()> & available,
  const std::function<void(std::chrono::milliseconds attempt)> & ask_harmless);

}  // namespace armor

#endif  // ARMOR_CPP__TRANSPORT_HPP_
