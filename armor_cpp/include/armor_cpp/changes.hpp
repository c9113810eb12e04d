// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// How every change method of the C++ client sends its command: the generated ones of the core's
// commands (faces.hpp) and of plugins' commands (plugins.hpp, tools/faces.py --cpp-plugins) and
// the hand-written ones (manipulations.hpp). The class that mixes it in decides what "send"
// means through `send_change(command, args)` (Reference: at once; Batch: queued) and names
// Changes<itself> its friend.
#ifndef ARMOR_CPP__CHANGES_HPP_
#define ARMOR_CPP__CHANGES_HPP_

#include <string>
#include <vector>

#include "armor_cpp/contract.hpp"

namespace armor
{

template<typename Derived>
class Changes
{
protected:
  ~Changes() = default;

  // A change with the arguments the catalogue gives its command, checked when compiled.
  template<const contract::Command & C, typename ... Args>
  decltype(auto) change(const Args & ... args)
  {
    static_assert(C.kind == contract::Kind::Manipulation, "not a manipulation in the catalogue");
    static_assert(C.accepts(static_cast<int>(sizeof...(Args))),
      "the core's catalogue gives this command another number of arguments");
    return static_cast<Derived &>(*this).send_change(C, std::vector<std::string>{args ...});
  }

  // A variadic change, its arguments one list.
  template<const contract::Command & C>
  decltype(auto) change_all(const std::vector<std::string> & args)
  {
    static_assert(C.kind == contract::Kind::Manipulation && C.variadic,
      "not a variadic manipulation in the catalogue");
    return static_cast<Derived &>(*this).send_change(C, args);
  }
};

}  // namespace armor

#endif  // ARMOR_CPP__CHANGES_HPP_
