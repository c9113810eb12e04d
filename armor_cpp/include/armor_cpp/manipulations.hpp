// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Every change ARMOR can make to a reference, written once for Reference (which sends each at
// once) and Batch (which queues it for one atomic list): the Python client's Manipulations.
// The changes with a face in the core's catalogue are generated (faces.hpp, by make
// catalogue); the ones here take typed values or a characteristic.
//
// A method names its command by the constant of contract.hpp, generated from the core's
// catalogue; a command that leaves the catalogue, or whose number of arguments changes there,
// stops this file compiling. The class that mixes it in decides what "send" means through
// `send_change(command, args)` (changes.hpp) and what a method returns (Reference: void,
// Batch: Batch &).
//
// Arguments naming entities take a plain name (`Robot`), a full IRI
// (`http://example.org/onto#Robot` or `<...>`) or a prefixed name (`dev:Charger`). Naming an
// entity that does not exist creates it. A refused change throws ServiceInternalError (a
// subclass by exit code; MountError under another client's mount) and changes nothing.
#ifndef ARMOR_CPP__MANIPULATIONS_HPP_
#define ARMOR_CPP__MANIPULATIONS_HPP_

#include <string>
#include <vector>

#include "armor_cpp/contract.hpp"
#include "armor_cpp/faces.hpp"
#include "armor_cpp/values.hpp"

namespace armor
{

// Characteristics of an object property (a data property can only be FUNCTIONAL).
namespace characteristic
{
inline constexpr const char * FUNCTIONAL = "FUNCTIONAL";
inline constexpr const char * INVERSE_FUNCTIONAL = "INVERSE_FUNCTIONAL";
inline constexpr const char * TRANSITIVE = "TRANSITIVE";
inline constexpr const char * SYMMETRIC = "SYMMETRIC";
inline constexpr const char * ASYMMETRIC = "ASYMMETRIC";
inline constexpr const char * REFLEXIVE = "REFLEXIVE";
inline constexpr const char * IRREFLEXIVE = "IRREFLEXIVE";
}  // namespace characteristic

template<typename Derived>
class Manipulations : public ManipulationFaces<Derived>
{
public:
  // Give an individual a data property value (ADD DATAPROP IND); the value's C++ type picks
  // BOOLEAN, INTEGER, DOUBLE or STRING unless `datatype` (LONG, FLOAT, xsd:date...) is given.
  decltype(auto) add_data_value(
    const std::string & prop, const std::string & individual, const Value & value,
    const std::string & datatype = "")
  {
    auto [type, text] = typed_argument(value, datatype);
    return this->template change<contract::ADD_DATAPROP_IND>(prop, individual, type, text);
  }
  // Remove a data property value, typed as when it was added (REMOVE DATAPROP IND).
  decltype(auto) remove_data_value(
    const std::string & prop, const std::string & individual, const Value & value,
    const std::string & datatype = "")
  {
    auto [type, text] = typed_argument(value, datatype);
    return this->template change<contract::REMOVE_DATAPROP_IND>(prop, individual, type, text);
  }
  // Replace one data property value by another in one step (REPLACE DATAPROP IND).
  decltype(auto) replace_data_value(
    const std::string & prop, const std::string & individual, const Value & new_value,
    const Value & old_value, const std::string & datatype = "")
  {
    auto [type, new_text] = typed_argument(new_value, datatype);
    return this->template change<contract::REPLACE_DATAPROP_IND>(
      prop, individual, type, new_text, typed_argument(old_value, type).second);
  }

  // Give an object property a characteristic (ADD OBJECTPROP CHARACTERISTIC).
  decltype(auto) add_object_characteristic(const std::string & prop, const std::string & which)
  {return this->template change<contract::ADD_OBJECTPROP_CHARACTERISTIC>(prop, which);}
  // Take a characteristic from an object property (REMOVE OBJECTPROP CHARACTERISTIC).
  decltype(auto) remove_object_characteristic(const std::string & prop, const std::string & which)
  {return this->template change<contract::REMOVE_OBJECTPROP_CHARACTERISTIC>(prop, which);}
  // Make a data property functional (ADD DATAPROP CHARACTERISTIC).
  decltype(auto) add_data_characteristic(
    const std::string & prop, const std::string & which = characteristic::FUNCTIONAL)
  {return this->template change<contract::ADD_DATAPROP_CHARACTERISTIC>(prop, which);}
  // Make a data property no longer functional (REMOVE DATAPROP CHARACTERISTIC).
  decltype(auto) remove_data_characteristic(
    const std::string & prop, const std::string & which = characteristic::FUNCTIONAL)
  {return this->template change<contract::REMOVE_DATAPROP_CHARACTERISTIC>(prop, which);}

protected:
  ~Manipulations() = default;

};

}  // namespace armor

#endif  // ARMOR_CPP__MANIPULATIONS_HPP_
