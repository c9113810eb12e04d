// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// ARMOR's services called through rcl, the C layer under every ROS 2 client library.
//
// The transport has its own ROS context and node (a DDS participant of its own) and one
// thread that takes the answers, so calls may come from any thread and several may be in
// flight at once. Before the first call to a service it proves the service's response path
// with a harmless request, as the Python transport does: Fast DDS drops an answer to a client
// whose response reader the service has not matched yet, and a lost answer to a change cannot
// be asked for again.
#ifndef ARMOR_CPP__RCL_TRANSPORT_HPP_
#define ARMOR_CPP__RCL_TRANSPORT_HPP_

#include <chrono>
#include <memory>
#include <string>
#include <vector>

#include "armor_cpp/transport.hpp"

namespace armor
{

struct RclTransportOptions
{
  // Namespace of the ARMOR node ('' for the default, `/robot1` for a robot's own service).
  std::string ns;
  // How long the first call to a service waits for it to appear and answer.
  std::chrono::milliseconds service_wait{std::chrono::seconds(30)};
  // Name of this transport's node; '' picks `armor_cpp_<pid>_<n>`.
  std::string node_name;
};

class RclTransport : public Transport
{
public:
  // Starts a ROS context (domain from ROS_DOMAIN_ID, discovery settings from the environment,
  // as every ROS 2 program) and the node. Throws ServiceCallError when rcl refuses.
  explicit RclTransport(const RclTransportOptions & options = {});
  ~RclTransport() override;
  RclTransport(const RclTransport &) = delete;
  RclTransport & operator=(const RclTransport &) = delete;

  armor_msgs::msg::ArmorDirectiveRes call(
    const armor_msgs::msg::ArmorDirectiveReq & request, Timeout timeout) override;
  armor_msgs::srv::ArmorDirectiveList::Response call_list(
    const std::vector<armor_msgs::msg::ArmorDirectiveReq> & requests, Timeout timeout) override;

private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace armor

#endif  // ARMOR_CPP__RCL_TRANSPORT_HPP_
