// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Exceptions of the C++ client: the same classes as the Python client's armor_client.errors.
//
// ServiceCallError: the service could not be called (not running, no answer in time).
// ServiceInternalError: ARMOR answered and the directive failed; it carries the exit code and
// ARMOR's description. Its subclasses group the exit codes by what a program usually does
// about them, so `catch (const armor::UnknownReferenceError &)` reads better than comparing
// codes.
#ifndef ARMOR_CPP__ERRORS_HPP_
#define ARMOR_CPP__ERRORS_HPP_

#include <cstddef>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "armor_msgs/msg/armor_directive_res.hpp"

namespace armor
{

// Base of every error the client throws.
class Error : public std::runtime_error
{
public:
  Error(const std::string & description, std::optional<int> exit_code);

  // ARMOR's exit code; empty when the service never answered.
  std::optional<int> exit_code() const noexcept {return exit_code_;}
  // What went wrong, in words (without the code what() starts with).
  const std::string & description() const noexcept {return description_;}

private:
  std::optional<int> exit_code_;
  std::string description_;
};

// The service could not be called: not running, no answer in time, or the call broke.
class ServiceCallError : public Error
{
public:
  explicit ServiceCallError(const std::string & description);
};

// The service did not answer within the client's time limit.
class CallTimeout : public ServiceCallError
{
public:
  using ServiceCallError::ServiceCallError;
};

// ARMOR answered, and the directive failed.
class ServiceInternalError : public Error
{
public:
  // `index` and `responses`: for a directive of an atomic list, see index() and responses().
  explicit ServiceInternalError(
    const armor_msgs::msg::ArmorDirectiveRes & response,
    std::optional<std::size_t> index = std::nullopt,
    std::vector<armor_msgs::msg::ArmorDirectiveRes> responses = {});

  int code() const noexcept {return *exit_code();}
  // The response's timeout flag: a time limit of the service was reached.
  bool timeout() const noexcept {return response_.timeout;}
  // The whole response.
  const armor_msgs::msg::ArmorDirectiveRes & response() const noexcept {return response_;}
  // For a failed atomic list: the position of the directive that failed (empty when the list
  // was rolled back without one failing) and every directive's response.
  std::optional<std::size_t> index() const noexcept {return index_;}
  const std::vector<armor_msgs::msg::ArmorDirectiveRes> & responses() const noexcept
  {
    return responses_;
  }

private:
  armor_msgs::msg::ArmorDirectiveRes response_;
  std::optional<std::size_t> index_;
  std::vector<armor_msgs::msg::ArmorDirectiveRes> responses_;
};

// 102 (another client holds the mount, nothing changed) or 203 (mount refused).
class MountError : public ServiceInternalError {using ServiceInternalError::ServiceInternalError;};
// The directive itself is wrong: 101, 201, 202, 205, 207, 208, 215, 221, 223.
class ArgumentError : public ServiceInternalError
{using ServiceInternalError::ServiceInternalError;};
// 206: no reference is loaded under that name.
class UnknownReferenceError : public ServiceInternalError
{using ServiceInternalError::ServiceInternalError;};
// An ontology could not be read or written: 209, 213, 214, 218, 222.
class FileError : public ServiceInternalError {using ServiceInternalError::ServiceInternalError;};
// The reasoner failed, cannot answer, or the ontology is inconsistent: 210, 217, 219.
class ReasonerError : public ServiceInternalError
{using ServiceInternalError::ServiceInternalError;};
// 211: a time limit of the service (lock wait, reasoner, SPARQL) was reached.
class TimeLimitError : public ServiceInternalError
{using ServiceInternalError::ServiceInternalError;};
// 212: undone or not run because another directive of the same list failed.
class RolledBackError : public ServiceInternalError
{using ServiceInternalError::ServiceInternalError;};
// 216: the knowledge core is restarting; the same directive may succeed when retried.
class CoreUnavailableError : public ServiceInternalError
{using ServiceInternalError::ServiceInternalError;};

// Throw the ServiceInternalError subclass of a failed response's exit code.
[[noreturn]] void throw_error_for(const armor_msgs::msg::ArmorDirectiveRes & response);

// Throw the error of a failed atomic list: that of the one directive that failed, with
// index() and responses() set.
[[noreturn]] void throw_list_error(
  const std::vector<armor_msgs::msg::ArmorDirectiveRes> & responses);

}  // namespace armor

#endif  // ARMOR_CPP__ERRORS_HPP_
