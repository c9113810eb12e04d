// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
#include "armor_cpp/transport.hpp"

#include <algorithm>
#include <string>
#include <thread>
#include <vector>

#include "armor_cpp/errors.hpp"

namespace armor
{

armor_msgs::msg::ArmorDirectiveReq directive(
  const std::string & client, const std::string & reference, const std::string & command,
  const std::string & primary, const std::string & secondary,
  const std::vector<std::string> & args)
{
  armor_msgs::msg::ArmorDirectiveReq request;
  request.client_name = client;
  request.reference_name = reference;
  request.command = command;
  request.primary_command_spec = primary;
  request.secondary_command_spec = secondary;
  request.args = args;
  return request;
}

void wait_until_answered(
  const std::string & service, std::chrono::milliseconds service_wait,
  const std::function<bool()> & available,
  const std::function<void(std::chrono::milliseconds attempt)> & ask_harmless)
{
  using Clock = std::chrono::steady_clock;
  const auto deadline = Clock::now() + service_wait;
  while (Clock::now() < deadline) {
    if (!available()) {
      std::this_thread::sleep_for(std::chrono::milliseconds(20));
      continue;
    }
    auto remaining = std::chrono::duration_cast<std::chrono::milliseconds>(
      deadline - Clock::now());
    try {
      // Short attempts: an answer lost to an unmatched reader is simply asked for again.
      ask_harmless(std::clamp(remaining, std::chrono::milliseconds(100),
        std::chrono::milliseconds(2000)));
      return;
    } catch (const ServiceCallError &) {
      continue;
    }
  }
  throw ServiceCallError("service " + service + " did not answer within " +
          std::to_string(service_wait.count() / 1000.0) +
          " s; is the ARMOR node running (armor serve)?");
}

}  // namespace armor
