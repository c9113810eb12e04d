// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Every change ARMOR can make to a reference, written once for Reference (which sends each at
// once) and Batch (which queues it for one atomic list): the Python client's Manipulations.
//
// A method names its command by the constant of contract.hpp, generated from the core's
// catalogue; a command that leaves the catalogue, or whose number of arguments changes there,
// stops this file compiling. The class that mixes it in decides what "send" means through
// `send_change(command, args)` and what a method returns (Reference: void, Batch: Batch &).
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
class Manipulations
{
public:
  // Individuals

  // Declare an individual (ADD IND).
  decltype(auto) add_individual(const std::string & individual)
  {return change<contract::ADD_IND>(individual);}
  // Assert that an individual belongs to a class (ADD IND CLASS).
  decltype(auto) add_individual_to_class(const std::string & individual, const std::string & cls)
  {return change<contract::ADD_IND_CLASS>(individual, cls);}
  // Remove every axiom that mentions the individual (REMOVE IND).
  decltype(auto) remove_individual(const std::string & individual)
  {return change<contract::REMOVE_IND>(individual);}
  // Remove the assertion that an individual belongs to a class (REMOVE IND CLASS).
  decltype(auto) remove_individual_from_class(
    const std::string & individual, const std::string & cls)
  {return change<contract::REMOVE_IND_CLASS>(individual, cls);}
  // Assert that two or more names denote the same individual (ADD IND SAME).
  decltype(auto) add_same_individuals(const std::vector<std::string> & individuals)
  {return change_all<contract::ADD_IND_SAME>(individuals);}
  // Remove a SameIndividual assertion (REMOVE IND SAME).
  decltype(auto) remove_same_individuals(const std::vector<std::string> & individuals)
  {return change_all<contract::REMOVE_IND_SAME>(individuals);}
  // Assert that the individuals are pairwise different (DISJOINT IND).
  decltype(auto) make_individuals_different(const std::vector<std::string> & individuals)
  {return change_all<contract::DISJOINT_IND>(individuals);}
  // Make all instances of a class, inferred ones too, pairwise different (DISJOINT IND CLASS).
  decltype(auto) make_instances_different(const std::string & cls)
  {return change<contract::DISJOINT_IND_CLASS>(cls);}
  // Rename an individual everywhere (RENAME IND).
  decltype(auto) rename_individual(const std::string & old_name, const std::string & new_name)
  {return change<contract::RENAME_IND>(old_name, new_name);}

  // Classes

  // Declare a class (ADD CLASS).
  decltype(auto) add_class(const std::string & cls) {return change<contract::ADD_CLASS>(cls);}
  // Assert SubClassOf(subclass, superclass) (ADD CLASS CLASS).
  decltype(auto) add_subclass(const std::string & subclass, const std::string & superclass)
  {return change<contract::ADD_CLASS_CLASS>(subclass, superclass);}
  // Remove every axiom that mentions the class (REMOVE CLASS).
  decltype(auto) remove_class(const std::string & cls)
  {return change<contract::REMOVE_CLASS>(cls);}
  // Remove SubClassOf(subclass, superclass) (REMOVE CLASS CLASS).
  decltype(auto) remove_subclass(const std::string & subclass, const std::string & superclass)
  {return change<contract::REMOVE_CLASS_CLASS>(subclass, superclass);}
  // Assert that the classes are pairwise disjoint (DISJOINT CLASS).
  decltype(auto) make_classes_disjoint(const std::vector<std::string> & classes)
  {return change_all<contract::DISJOINT_CLASS>(classes);}
  // Make the direct subclasses of a class, inferred ones too, disjoint (DISJOINT CLASS CLASS).
  decltype(auto) make_subclasses_disjoint(const std::string & cls)
  {return change<contract::DISJOINT_CLASS_CLASS>(cls);}
  // Turn a class's SubClassOf axioms into one EquivalentClasses axiom (MAKE EQUIVALENT CLASS).
  decltype(auto) make_equivalent_to_superclasses(const std::string & cls)
  {return change<contract::MAKE_EQUIVALENT_CLASS>(cls);}
  // Define a class by a class expression in Manchester syntax (ADD CLASS EQUIVALENT).
  decltype(auto) add_equivalent_class(const std::string & cls, const std::string & expression)
  {return change<contract::ADD_CLASS_EQUIVALENT>(cls, expression);}
  // Remove a definition added by add_equivalent_class (REMOVE CLASS EQUIVALENT).
  decltype(auto) remove_equivalent_class(const std::string & cls, const std::string & expression)
  {return change<contract::REMOVE_CLASS_EQUIVALENT>(cls, expression);}
  // Assert `cls SubClassOf prop min count value_class` (ADD CARDINALITY MIN).
  decltype(auto) add_min_cardinality(
    const std::string & cls, const std::string & prop, int count, const std::string & value_class)
  {return change<contract::ADD_CARDINALITY_MIN>(cls, prop, std::to_string(count), value_class);}
  // Rename a class everywhere (RENAME CLASS).
  decltype(auto) rename_class(const std::string & old_name, const std::string & new_name)
  {return change<contract::RENAME_CLASS>(old_name, new_name);}

  // Property values

  // Give an individual a data property value (ADD DATAPROP IND); the value's C++ type picks
  // BOOLEAN, INTEGER, DOUBLE or STRING unless `datatype` (LONG, FLOAT, xsd:date...) is given.
  decltype(auto) add_data_value(
    const std::string & prop, const std::string & individual, const Value & value,
    const std::string & datatype = "")
  {
    auto [type, text] = typed_argument(value, datatype);
    return change<contract::ADD_DATAPROP_IND>(prop, individual, type, text);
  }
  // Remove a data property value, typed as when it was added (REMOVE DATAPROP IND).
  decltype(auto) remove_data_value(
    const std::string & prop, const std::string & individual, const Value & value,
    const std::string & datatype = "")
  {
    auto [type, text] = typed_argument(value, datatype);
    return change<contract::REMOVE_DATAPROP_IND>(prop, individual, type, text);
  }
  // Replace one data property value by another in one step (REPLACE DATAPROP IND).
  decltype(auto) replace_data_value(
    const std::string & prop, const std::string & individual, const Value & new_value,
    const Value & old_value, const std::string & datatype = "")
  {
    auto [type, new_text] = typed_argument(new_value, datatype);
    return change<contract::REPLACE_DATAPROP_IND>(
      prop, individual, type, new_text, typed_argument(old_value, type).second);
  }
  // Relate an individual to another (ADD OBJECTPROP IND).
  decltype(auto) add_object_value(
    const std::string & prop, const std::string & individual, const std::string & value)
  {return change<contract::ADD_OBJECTPROP_IND>(prop, individual, value);}
  // Remove a relation between two individuals (REMOVE OBJECTPROP IND).
  decltype(auto) remove_object_value(
    const std::string & prop, const std::string & individual, const std::string & value)
  {return change<contract::REMOVE_OBJECTPROP_IND>(prop, individual, value);}
  // Replace the related individual in one step (REPLACE OBJECTPROP IND): new, then old.
  decltype(auto) replace_object_value(
    const std::string & prop, const std::string & individual, const std::string & new_value,
    const std::string & old_value)
  {return change<contract::REPLACE_OBJECTPROP_IND>(prop, individual, new_value, old_value);}

  // Properties

  // Assert SubObjectPropertyOf (ADD OBJECTPROP OBJECTPROP).
  decltype(auto) add_object_subproperty(const std::string & sub, const std::string & super)
  {return change<contract::ADD_OBJECTPROP_OBJECTPROP>(sub, super);}
  // Remove SubObjectPropertyOf (REMOVE OBJECTPROP OBJECTPROP).
  decltype(auto) remove_object_subproperty(const std::string & sub, const std::string & super)
  {return change<contract::REMOVE_OBJECTPROP_OBJECTPROP>(sub, super);}
  // Assert SubDataPropertyOf (ADD DATAPROP DATAPROP).
  decltype(auto) add_data_subproperty(const std::string & sub, const std::string & super)
  {return change<contract::ADD_DATAPROP_DATAPROP>(sub, super);}
  // Remove SubDataPropertyOf (REMOVE DATAPROP DATAPROP).
  decltype(auto) remove_data_subproperty(const std::string & sub, const std::string & super)
  {return change<contract::REMOVE_DATAPROP_DATAPROP>(sub, super);}
  // Assert that two object properties are inverses (ADD OBJECTPROP INVERSE).
  decltype(auto) add_inverse_property(const std::string & prop, const std::string & inverse)
  {return change<contract::ADD_OBJECTPROP_INVERSE>(prop, inverse);}
  // Remove an InverseObjectProperties axiom (REMOVE OBJECTPROP INVERSE).
  decltype(auto) remove_inverse_property(const std::string & prop, const std::string & inverse)
  {return change<contract::REMOVE_OBJECTPROP_INVERSE>(prop, inverse);}
  // Give an object property a characteristic (ADD OBJECTPROP CHARACTERISTIC).
  decltype(auto) add_object_characteristic(const std::string & prop, const std::string & which)
  {return change<contract::ADD_OBJECTPROP_CHARACTERISTIC>(prop, which);}
  // Take a characteristic from an object property (REMOVE OBJECTPROP CHARACTERISTIC).
  decltype(auto) remove_object_characteristic(const std::string & prop, const std::string & which)
  {return change<contract::REMOVE_OBJECTPROP_CHARACTERISTIC>(prop, which);}
  // Make a data property functional (ADD DATAPROP CHARACTERISTIC).
  decltype(auto) add_data_characteristic(
    const std::string & prop, const std::string & which = characteristic::FUNCTIONAL)
  {return change<contract::ADD_DATAPROP_CHARACTERISTIC>(prop, which);}
  // Make a data property no longer functional (REMOVE DATAPROP CHARACTERISTIC).
  decltype(auto) remove_data_characteristic(
    const std::string & prop, const std::string & which = characteristic::FUNCTIONAL)
  {return change<contract::REMOVE_DATAPROP_CHARACTERISTIC>(prop, which);}
  // Assert an object property's domain (ADD OBJECTPROP DOMAIN).
  decltype(auto) add_object_domain(const std::string & prop, const std::string & cls)
  {return change<contract::ADD_OBJECTPROP_DOMAIN>(prop, cls);}
  // Remove an object property's domain (REMOVE OBJECTPROP DOMAIN).
  decltype(auto) remove_object_domain(const std::string & prop, const std::string & cls)
  {return change<contract::REMOVE_OBJECTPROP_DOMAIN>(prop, cls);}
  // Assert an object property's range (ADD OBJECTPROP RANGE).
  decltype(auto) add_object_range(const std::string & prop, const std::string & cls)
  {return change<contract::ADD_OBJECTPROP_RANGE>(prop, cls);}
  // Remove an object property's range (REMOVE OBJECTPROP RANGE).
  decltype(auto) remove_object_range(const std::string & prop, const std::string & cls)
  {return change<contract::REMOVE_OBJECTPROP_RANGE>(prop, cls);}
  // Assert a data property's domain (ADD DATAPROP DOMAIN).
  decltype(auto) add_data_domain(const std::string & prop, const std::string & cls)
  {return change<contract::ADD_DATAPROP_DOMAIN>(prop, cls);}
  // Remove a data property's domain (REMOVE DATAPROP DOMAIN).
  decltype(auto) remove_data_domain(const std::string & prop, const std::string & cls)
  {return change<contract::REMOVE_DATAPROP_DOMAIN>(prop, cls);}
  // Assert a data property's range: ARMOR's type name or an xsd: datatype (ADD DATAPROP RANGE).
  decltype(auto) add_data_range(const std::string & prop, const std::string & datatype)
  {return change<contract::ADD_DATAPROP_RANGE>(prop, datatype);}
  // Remove a data property's range (REMOVE DATAPROP RANGE).
  decltype(auto) remove_data_range(const std::string & prop, const std::string & datatype)
  {return change<contract::REMOVE_DATAPROP_RANGE>(prop, datatype);}
  // Rename an object property everywhere (RENAME OBJECTPROP).
  decltype(auto) rename_object_property(const std::string & old_name, const std::string & new_name)
  {return change<contract::RENAME_OBJECTPROP>(old_name, new_name);}
  // Rename a data property everywhere (RENAME DATAPROP).
  decltype(auto) rename_data_property(const std::string & old_name, const std::string & new_name)
  {return change<contract::RENAME_DATAPROP>(old_name, new_name);}

  // Axioms and rules

  // Add one axiom in Manchester or OWL functional syntax (ADD AXIOM).
  decltype(auto) add_axiom(const std::string & axiom) {return change<contract::ADD_AXIOM>(axiom);}
  // Remove one axiom (REMOVE AXIOM).
  decltype(auto) remove_axiom(const std::string & axiom)
  {return change<contract::REMOVE_AXIOM>(axiom);}
  // Add a SWRL rule, `Robot(?r), isIn(?r, ?l) -> Visited(?l)` (ADD SWRL).
  decltype(auto) add_rule(const std::string & name, const std::string & rule)
  {return change<contract::ADD_SWRL>(name, rule);}
  // Remove a SWRL rule (REMOVE SWRL).
  decltype(auto) remove_rule(const std::string & name, const std::string & rule)
  {return change<contract::REMOVE_SWRL>(name, rule);}

  // Buffers

  // Apply the buffered manipulations of a buffered reference (APPLY).
  decltype(auto) apply() {return change<contract::APPLY>();}
  // Apply the buffer and bring the reasoner up to date (REASON).
  decltype(auto) reason() {return change<contract::REASON>();}

protected:
  ~Manipulations() = default;

private:
  template<const contract::Command & C, typename ... Args>
  decltype(auto) change(const Args & ... args)
  {
    static_assert(C.kind == contract::Kind::Manipulation, "not a manipulation in the catalogue");
    static_assert(C.accepts(static_cast<int>(sizeof...(Args))),
      "the core's catalogue gives this command another number of arguments");
    return static_cast<Derived &>(*this).send_change(C, std::vector<std::string>{args ...});
  }

  template<const contract::Command & C>
  decltype(auto) change_all(const std::vector<std::string> & args)
  {
    static_assert(C.kind == contract::Kind::Manipulation && C.variadic,
      "not a variadic manipulation in the catalogue");
    return static_cast<Derived &>(*this).send_change(C, args);
  }
};

}  // namespace armor

#endif  // ARMOR_CPP__MANIPULATIONS_HPP_
