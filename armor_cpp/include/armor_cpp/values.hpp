// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Between ARMOR's strings and C++ values (the Python client's armor_client.values).
//
// ARMOR answers entities as `<http://example.org/onto#Robot>` (or `Robot` when the node runs
// with full_entity_iri:=false) and literals as `"80"^^xsd:integer` or `"text"@en`. These
// functions turn answers into short names, IRIs and typed Values, and turn Values into the
// (type, lexical value) pair that ADD DATAPROP IND takes.
#ifndef ARMOR_CPP__VALUES_HPP_
#define ARMOR_CPP__VALUES_HPP_

#include <cstdint>
#include <string>
#include <string_view>
#include <type_traits>
#include <utility>
#include <variant>

namespace armor
{

// A literal's value (bool, integer, real or text) or an entity's name.
class Value
{
public:
  using Variant = std::variant<bool, std::int64_t, double, std::string>;

  Value(bool value)  // NOLINT(runtime/explicit): values convert implicitly, as in Python
  : value_(value) {}
  template<typename T, std::enable_if_t<std::is_integral_v<T> && !std::is_same_v<T, bool>,
    int> = 0>
  Value(T value)  // NOLINT(runtime/explicit)
  : value_(static_cast<std::int64_t>(value)) {}
  Value(double value)  // NOLINT(runtime/explicit)
  : value_(value) {}
  Value(float value)  // NOLINT(runtime/explicit)
  : value_(static_cast<double>(value)) {}
  Value(std::string value)  // NOLINT(runtime/explicit)
  : value_(std::move(value)) {}
  Value(const char * value)  // NOLINT(runtime/explicit)
  : value_(std::string(value)) {}
  Value(std::string_view value)  // NOLINT(runtime/explicit)
  : value_(std::string(value)) {}

  // Whether it holds a T (bool, std::int64_t, double or std::string).
  template<typename T>
  bool is() const noexcept {return std::holds_alternative<T>(value_);}
  // The T it holds; std::bad_variant_access when it holds another type.
  template<typename T>
  const T & as() const {return std::get<T>(value_);}
  const Variant & variant() const noexcept {return value_;}
  // Its lexical form: `true`, `80`, `0.5`, the text itself.
  std::string to_string() const;

  bool operator==(const Value & other) const {return value_ == other.value_;}
  bool operator!=(const Value & other) const {return value_ != other.value_;}

private:
  Variant value_;
};

// A literal answer split in two: `"80"^^xsd:integer` is {"80", "xsd:integer"}.
struct Literal
{
  std::string lexical;
  std::string datatype;
};

// `<http://x.org/o#Robot>` -> `Robot`: what follows the last `#` (else the last `/`).
std::string short_name(std::string_view entity);
// `<http://x.org/o#Robot>` -> `http://x.org/o#Robot` (a short name comes back unchanged).
std::string entity_iri(std::string_view entity);
// Whether an answer is a literal (`"..."^^type`, `"..."@lang` or `"..."`).
bool is_literal(std::string_view answer);
// The lexical form and datatype of a literal answer; the datatype of a language-tagged
// string is rdf:langString, of a plain quoted string xsd:string. Throws std::invalid_argument
// for an answer that is not a literal.
Literal split_literal(std::string_view answer);
// The value of a literal answer: std::int64_t for the xsd integer types, double for
// float/double/decimal, bool for xsd:boolean, the lexical form for everything else. Throws
// std::invalid_argument when the lexical form does not fit its type.
Value literal_value(std::string_view answer);
// One answer as a Value: literals converted, entities named (as IRIs when `iris`).
Value answer_value(std::string_view answer, bool iris = false);
// The (type, lexical value) arguments of ADD/REMOVE/REPLACE DATAPROP IND for a value; bool,
// integer, real and text pick BOOLEAN, INTEGER, DOUBLE and STRING unless `datatype` (ARMOR's
// type name or an xsd: datatype) is given. Throws std::invalid_argument for a real that is
// not finite without an explicit datatype.
std::pair<std::string, std::string> typed_argument(
  const Value & value, const std::string & datatype = "");

}  // namespace armor

#endif  // ARMOR_CPP__VALUES_HPP_
