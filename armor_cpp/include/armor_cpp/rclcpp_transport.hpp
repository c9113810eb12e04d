// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// The C++ client inside an rclcpp node: the same Armor, Reference and Batch, speaking through
// the node's own service clients instead of a context of their own.
//
//   auto node = std::make_shared<rclcpp::Node>("planner");
//   armor::Armor armor("planner", std::make_shared<armor::RclcppTransport>(node));
//
// The node must be spun by an executor with a second thread (a MultiThreadedExecutor, or a
// thread running rclcpp::spin): a call blocks until its answer arrives, and the answer is
// delivered by the executor through this transport's own reentrant callback group, so a call
// may be made from the node's timers and subscriptions.
//
// Header-only, and compiled only where rclcpp exists (a ROS 2 distribution): the set-up of
// this repository has no rclcpp and does not build it.
#ifndef ARMOR_CPP__RCLCPP_TRANSPORT_HPP_
#define ARMOR_CPP__RCLCPP_TRANSPORT_HPP_

#include <atomic>
#include <chrono>
#include <future>
#include <memory>
#include <string>
#include <type_traits>
#include <vector>

#include "armor_cpp/contract.hpp"
#include "armor_cpp/errors.hpp"
#include "armor_cpp/transport.hpp"
#include "armor_msgs/srv/armor_directive.hpp"
#include "armor_msgs/srv/armor_directive_list.hpp"
#include "rclcpp/rclcpp.hpp"

namespace armor
{

class RclcppTransport : public Transport
{
public:
  // `ns`: namespace of the ARMOR node ('' for the default); `service_wait`: how long the first
  // call to a service waits for it to appear and answer.
  explicit RclcppTransport(
    const rclcpp::Node::SharedPtr & node, const std::string & ns = "",
    std::chrono::milliseconds service_wait = std::chrono::seconds(30))
  : node_(node), group_(node->create_callback_group(rclcpp::CallbackGroupType::Reentrant)),
    service_wait_(service_wait)
  {
    std::string prefix = ns;
    while (!prefix.empty() && prefix.back() == '/') {
      prefix.pop_back();
    }
    if (!prefix.empty()) {
      prefix += '/';
    }
    // The service's own QoS (armor_contract/services.py): reliable, deep history.
    rclcpp::QoS qos = rclcpp::ServicesQoS().keep_last(contract::kServiceQueueDepth).reliable();
    directive_.client = node->create_client<armor_msgs::srv::ArmorDirective>(
      prefix + std::string(contract::kDirectiveService), qos, group_);
    list_.client = node->create_client<armor_msgs::srv::ArmorDirectiveList>(
      prefix + std::string(contract::kListService), qos, group_);
  }

  armor_msgs::msg::ArmorDirectiveRes call(
    const armor_msgs::msg::ArmorDirectiveReq & request, Timeout timeout) override
  {
    auto message = std::make_shared<armor_msgs::srv::ArmorDirective::Request>();
    message->armor_request = request;
    return call_on(directive_, message, timeout).armor_response;
  }

  armor_msgs::srv::ArmorDirectiveList::Response call_list(
    const std::vector<armor_msgs::msg::ArmorDirectiveReq> & requests, Timeout timeout) override
  {
    auto message = std::make_shared<armor_msgs::srv::ArmorDirectiveList::Request>();
    message->armor_requests = requests;
    return call_on(list_, message, timeout);
  }

private:
  template<typename Service>
  struct Endpoint
  {
    typename rclcpp::Client<Service>::SharedPtr client;
    std::atomic<bool> answered_once{false};
  };

  template<typename Service>
  typename Service::Response call_on(
    Endpoint<Service> & endpoint, std::shared_ptr<typename Service::Request> request,
    Timeout timeout)
  {
    if (!endpoint.answered_once) {
      auto harmless = std::make_shared<typename Service::Request>();
      if constexpr (std::is_same_v<Service, armor_msgs::srv::ArmorDirective>) {
        harmless->armor_request = directive("", "", "GET", "ALL", "REFS");
      }
      wait_until_answered(endpoint.client->get_service_name(), service_wait_,
        [&] {return endpoint.client->service_is_ready();},
        [&](std::chrono::milliseconds attempt) {send(endpoint, harmless, attempt);});
      endpoint.answered_once = true;
    }
    try {
      return send(endpoint, request, timeout);
    } catch (const CallTimeout &) {
      // The node behind the service may have been replaced: prove its response path again.
      endpoint.answered_once = false;
      throw;
    }
  }

  template<typename Service>
  typename Service::Response send(
    Endpoint<Service> & endpoint, std::shared_ptr<typename Service::Request> request,
    Timeout timeout)
  {
    auto pending = endpoint.client->async_send_request(request);
    if (timeout && pending.future.wait_for(*timeout) != std::future_status::ready) {
      endpoint.client->remove_pending_request(pending);
      throw CallTimeout(std::string("no answer from ") + endpoint.client->get_service_name() +
              " within " + std::to_string(timeout->count() / 1000.0) + " s");
    }
    return *pending.future.get();
  }

  rclcpp::Node::SharedPtr node_;
  rclcpp::CallbackGroup::SharedPtr group_;
  std::chrono::milliseconds service_wait_;
  Endpoint<armor_msgs::srv::ArmorDirective> directive_;
  Endpoint<armor_msgs::srv::ArmorDirectiveList> list_;
};

}  // namespace armor

#endif  // ARMOR_CPP__RCLCPP_TRANSPORT_HPP_
