// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
#include "armor_cpp/rcl_transport.hpp"

#include <unistd.h>

#include <atomic>
#include <cstdint>
#include <future>
#include <map>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>
#include <utility>

#include "armor_cpp/contract.hpp"
#include "armor_cpp/errors.hpp"
#include "armor_msgs/srv/armor_directive.hpp"
#include "armor_msgs/srv/armor_directive_list.hpp"
#include "rcl/client.h"
#include "rcl/error_handling.h"
#include "rcl/graph.h"
#include "rcl/guard_condition.h"
#include "rcl/init.h"
#include "rcl/node.h"
#include "rcl/wait.h"
#include "rmw/qos_profiles.h"
#include "rosidl_typesupport_cpp/service_type_support.hpp"

namespace armor
{
namespace
{

using armor_msgs::srv::ArmorDirective;
using armor_msgs::srv::ArmorDirectiveList;

std::atomic<int> node_numbers{0};

// rcl's last error as text (and cleared, as rcl expects).
std::string rcl_error()
{
  std::string text = rcl_get_error_string().str;
  rcl_reset_error();
  return text;
}

// For clean-up, where a failure can only be ignored.
void ignore(rcl_ret_t) {rcl_reset_error();}

void check(rcl_ret_t ret, const std::string & what)
{
  if (ret != RCL_RET_OK) {
    throw ServiceCallError(what + ": " + rcl_error());
  }
}

// One service client and the answers its callers wait for, by request sequence number.
template<typename Service>
struct Slot
{
  rcl_client_t client = rcl_get_zero_initialized_client();
  std::string name;
  std::mutex mutex;  // guards sending and `waiting`, so an answer never beats its promise
  std::map<std::int64_t, std::promise<typename Service::Response>> waiting;
  std::atomic<bool> answered_once{false};

  // Take every answer that has arrived and hand each to its caller; answers nobody waits
  // for any more (their caller timed out) are dropped.
  void take_answers()
  {
    while (true) {
      rmw_service_info_t info;
      typename Service::Response response;
      rcl_ret_t ret = rcl_take_response_with_info(&client, &info, &response);
      if (ret != RCL_RET_OK) {
        rcl_reset_error();
        return;
      }
      std::lock_guard<std::mutex> lock(mutex);
      auto found = waiting.find(info.request_id.sequence_number);
      if (found != waiting.end()) {
        found->second.set_value(std::move(response));
        waiting.erase(found);
      }
    }
  }
};

}  // namespace

struct RclTransport::Impl
{
  rcl_init_options_t init_options = rcl_get_zero_initialized_init_options();
  rcl_context_t context = rcl_get_zero_initialized_context();
  rcl_node_t node = rcl_get_zero_initialized_node();
  rcl_guard_condition_t wake = rcl_get_zero_initialized_guard_condition();
  rcl_wait_set_t wait_set = rcl_get_zero_initialized_wait_set();
  Slot<ArmorDirective> directive;
  Slot<ArmorDirectiveList> list;
  std::chrono::milliseconds service_wait;
  std::atomic<bool> running{true};
  std::thread taker;

  explicit Impl(const RclTransportOptions & options)
  : service_wait(options.service_wait)
  {
    try {
      start(options);
    } catch (...) {
      release();
      throw;
    }
  }

  ~Impl() {release();}

  void start(const RclTransportOptions & options)
  {
    rcl_allocator_t allocator = rcl_get_default_allocator();
    check(rcl_init_options_init(&init_options, allocator), "rcl_init_options_init");
    check(rcl_init(0, nullptr, &init_options, &context), "rcl_init");
    std::string node_name = options.node_name.empty() ?
      "armor_cpp_" + std::to_string(getpid()) + "_" + std::to_string(node_numbers++) :
      options.node_name;
    rcl_node_options_t node_options = rcl_node_get_default_options();
    node_options.enable_rosout = false;
    check(rcl_node_init(&node, node_name.c_str(), "", &context, &node_options), "rcl_node_init");
    std::string prefix = options.ns;
    while (!prefix.empty() && prefix.back() == '/') {
      prefix.pop_back();
    }
    if (!prefix.empty()) {
      prefix += '/';
    }
    init_client(directive, prefix + std::string(contract::kDirectiveService),
      rosidl_typesupport_cpp::get_service_type_support_handle<ArmorDirective>());
    init_client(list, prefix + std::string(contract::kListService),
      rosidl_typesupport_cpp::get_service_type_support_handle<ArmorDirectiveList>());
    check(rcl_guard_condition_init(&wake, &context, rcl_guard_condition_get_default_options()),
      "rcl_guard_condition_init");
    check(rcl_wait_set_init(&wait_set, 0, 1, 0, 2, 0, 0, &context, allocator),
      "rcl_wait_set_init");
    taker = std::thread([this] {take_answers();});
  }

  // Stop the taker and finish whatever was initialised (a zero-initialised handle's fini
  // only reports that it was not, which is ignored).
  void release()
  {
    running = false;
    if (taker.joinable()) {
      ignore(rcl_trigger_guard_condition(&wake));
      taker.join();
    }
    ignore(rcl_wait_set_fini(&wait_set));
    ignore(rcl_guard_condition_fini(&wake));
    ignore(rcl_client_fini(&list.client, &node));
    ignore(rcl_client_fini(&directive.client, &node));
    ignore(rcl_node_fini(&node));
    ignore(rcl_shutdown(&context));
    ignore(rcl_context_fini(&context));
    ignore(rcl_init_options_fini(&init_options));
    rcl_reset_error();
  }

  template<typename Service>
  void init_client(Slot<Service> & slot, const std::string & name,
    const rosidl_service_type_support_t * type_support)
  {
    rcl_client_options_t client_options = rcl_client_get_default_options();
    // The service's own QoS (armor_contract/services.py): reliable, deep history.
    client_options.qos = rmw_qos_profile_services_default;
    client_options.qos.history = RMW_QOS_POLICY_HISTORY_KEEP_LAST;
    client_options.qos.depth = contract::kServiceQueueDepth;
    client_options.qos.reliability = RMW_QOS_POLICY_RELIABILITY_RELIABLE;
    client_options.qos.durability = RMW_QOS_POLICY_DURABILITY_VOLATILE;
    check(rcl_client_init(&slot.client, &node, type_support, name.c_str(), &client_options),
      "rcl_client_init " + name);
    slot.name = rcl_client_get_service_name(&slot.client);
  }

  void take_answers()
  {
    while (running) {
      if (rcl_wait_set_clear(&wait_set) != RCL_RET_OK ||
        rcl_wait_set_add_guard_condition(&wait_set, &wake, nullptr) != RCL_RET_OK ||
        rcl_wait_set_add_client(&wait_set, &directive.client, nullptr) != RCL_RET_OK ||
        rcl_wait_set_add_client(&wait_set, &list.client, nullptr) != RCL_RET_OK)
      {
        rcl_reset_error();
        return;
      }
      rcl_ret_t ret = rcl_wait(&wait_set, -1);
      if (ret != RCL_RET_OK && ret != RCL_RET_TIMEOUT) {
        rcl_reset_error();
        continue;
      }
      directive.take_answers();
      list.take_answers();
    }
  }

  template<typename Service>
  typename Service::Response call(
    Slot<Service> & slot, const typename Service::Request & request, Timeout timeout)
  {
    if (!slot.answered_once) {
      wait_until_answered(slot);
    }
    try {
      return send(slot, request, timeout);
    } catch (const CallTimeout &) {
      // The node behind the service may have been replaced: prove the new one's response path
      // before the next call instead of risking another lost answer.
      slot.answered_once = false;
      throw;
    }
  }

  template<typename Service>
  typename Service::Response send(
    Slot<Service> & slot, const typename Service::Request & request, Timeout timeout)
  {
    std::future<typename Service::Response> answer;
    std::int64_t sequence = 0;
    {
      std::lock_guard<std::mutex> lock(slot.mutex);
      check(rcl_send_request(&slot.client, &request, &sequence), "call to " + slot.name);
      answer = slot.waiting[sequence].get_future();
    }
    if (timeout && answer.wait_for(*timeout) != std::future_status::ready) {
      std::lock_guard<std::mutex> lock(slot.mutex);
      if (answer.wait_for(std::chrono::seconds(0)) != std::future_status::ready) {
        slot.waiting.erase(sequence);
        throw CallTimeout("no answer from " + slot.name + " within " +
                std::to_string(timeout->count() / 1000.0) + " s");
      }
    }
    return answer.get();
  }

  template<typename Service>
  void wait_until_answered(Slot<Service> & slot)
  {
    typename Service::Request harmless;
    if constexpr (std::is_same_v<Service, ArmorDirective>) {
      harmless.armor_request = directive_of_words(contract::GET_ALL_REFS);
    }
    armor::wait_until_answered(slot.name, service_wait,
      [&] {
        bool available = false;
        if (rcl_service_server_is_available(&node, &slot.client, &available) != RCL_RET_OK) {
          rcl_reset_error();
        }
        return available;
      },
      [&](std::chrono::milliseconds attempt) {send(slot, harmless, attempt);});
    slot.answered_once = true;
  }

  static armor_msgs::msg::ArmorDirectiveReq directive_of_words(const contract::Command & c)
  {
    return armor::directive("", "", std::string(c.command), std::string(c.primary),
             std::string(c.secondary));
  }
};

RclTransport::RclTransport(const RclTransportOptions & options)
: impl_(std::make_unique<Impl>(options)) {}

RclTransport::~RclTransport() = default;

armor_msgs::msg::ArmorDirectiveRes RclTransport::call(
  const armor_msgs::msg::ArmorDirectiveReq & request, Timeout timeout)
{
  ArmorDirective::Request message;
  message.armor_request = request;
  return impl_->call(impl_->directive, message, timeout).armor_response;
}

armor_msgs::srv::ArmorDirectiveList::Response RclTransport::call_list(
  const std::vector<armor_msgs::msg::ArmorDirectiveReq> & requests, Timeout timeout)
{
  ArmorDirectiveList::Request message;
  message.armor_requests = requests;
  return impl_->call(impl_->list, message, timeout);
}

}  // namespace armor
