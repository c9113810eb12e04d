// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
#include "armor_cpp/errors.hpp"

#include <string>
#include <utility>
#include <vector>

#include "armor_cpp/contract.hpp"

namespace armor
{
namespace
{

using armor_msgs::msg::ArmorDirectiveRes;
using contract::ExitCode;

std::string with_code(const std::string & description, std::optional<int> exit_code)
{
  return exit_code ? std::to_string(*exit_code) + ": " + description : description;
}

template<typename E>
[[noreturn]] void throw_as(
  const ArmorDirectiveRes & response, std::optional<std::size_t> index,
  const std::vector<ArmorDirectiveRes> & responses)
{
  throw E(response, index, responses);
}

// The error class of each exit code: as the Python client groups them (errors.py).
[[noreturn]] void throw_by_code(
  const ArmorDirectiveRes & response, std::optional<std::size_t> index,
  const std::vector<ArmorDirectiveRes> & responses)
{
  switch (static_cast<ExitCode>(response.exit_code)) {
    case ExitCode::REFERENCE_MOUNTED:
    case ExitCode::MOUNT_REFUSED:
      throw_as<MountError>(response, index, responses);
    case ExitCode::BAD_DATA_TYPE:
    case ExitCode::NO_REFERENCE_NAME:
    case ExitCode::NO_COMMAND:
    case ExitCode::UNKNOWN_COMMAND:
    case ExitCode::WRONG_ARGUMENTS:
    case ExitCode::BAD_SYNTAX:
    case ExitCode::AMBIGUOUS_NAME:
    case ExitCode::TOO_LARGE:
    case ExitCode::FEDERATED_QUERY_DISABLED:
      throw_as<ArgumentError>(response, index, responses);
    case ExitCode::UNKNOWN_REFERENCE:
      throw_as<UnknownReferenceError>(response, index, responses);
    case ExitCode::LOAD_FAILED:
    case ExitCode::PATH_NOT_ALLOWED:
    case ExitCode::REFERENCE_EXISTS:
    case ExitCode::WEB_LOADING_DISABLED:
    case ExitCode::IMPORTS_UNRESOLVED:
      throw_as<FileError>(response, index, responses);
    case ExitCode::REASONER_FAILED:
    case ExitCode::INCONSISTENT:
    case ExitCode::NOT_SUPPORTED:
      throw_as<ReasonerError>(response, index, responses);
    case ExitCode::TIMEOUT:
      throw_as<TimeLimitError>(response, index, responses);
    case ExitCode::ROLLED_BACK:
      throw_as<RolledBackError>(response, index, responses);
    case ExitCode::CORE_UNAVAILABLE:
      throw_as<CoreUnavailableError>(response, index, responses);
    default:
      throw_as<ServiceInternalError>(response, index, responses);
  }
}

}  // namespace

Error::Error(const std::string & description, std::optional<int> exit_code)
: std::runtime_error(with_code(description, exit_code)), exit_code_(exit_code),
  description_(description) {}

ServiceCallError::ServiceCallError(const std::string & description)
: Error(description, std::nullopt) {}

ServiceInternalError::ServiceInternalError(
  const ArmorDirectiveRes & response, std::optional<std::size_t> index,
  std::vector<ArmorDirectiveRes> responses)
: Error(response.error_description, response.exit_code), response_(response), index_(index),
  responses_(std::move(responses)) {}

void throw_error_for(const ArmorDirectiveRes & response)
{
  throw_by_code(response, std::nullopt, {});
}

void throw_list_error(const std::vector<ArmorDirectiveRes> & responses)
{
  for (std::size_t index = 0; index < responses.size(); ++index) {
    const ArmorDirectiveRes & response = responses[index];
    if (!response.success && response.exit_code != static_cast<int>(ExitCode::ROLLED_BACK)) {
      throw_by_code(response, index, responses);
    }
  }
  ArmorDirectiveRes rolled_back;
  rolled_back.exit_code = static_cast<int>(ExitCode::ROLLED_BACK);
  rolled_back.error_description = "the list was rolled back";
  throw RolledBackError(rolled_back, std::nullopt, responses);
}

}  // namespace armor
