// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
#include "armor_cpp/values.hpp"

#include <charconv>
#include <cmath>
#include <limits>
#include <set>
#include <stdexcept>
#include <string>
#include <system_error>

namespace armor
{
namespace
{

const std::set<std::string, std::less<>> kIntegerTypes{
  "integer", "int", "long", "short", "byte", "nonNegativeInteger", "positiveInteger",
  "nonPositiveInteger", "negativeInteger", "unsignedLong", "unsignedInt", "unsignedShort",
  "unsignedByte"};
const std::set<std::string, std::less<>> kRealTypes{"float", "double", "decimal"};
constexpr std::string_view kXsd = "http://www.w3.org/2001/XMLSchema#";

bool starts_with(std::string_view text, std::string_view prefix)
{
  return text.substr(0, prefix.size()) == prefix;
}

bool ends_with(std::string_view text, std::string_view suffix)
{
  return text.size() >= suffix.size() && text.substr(text.size() - suffix.size()) == suffix;
}

std::invalid_argument not_a(const std::string & what, std::string_view text)
{
  return std::invalid_argument("not " + what + ": '" + std::string(text) + "'");
}

std::int64_t xsd_integer(std::string_view lexical)
{
  // xsd allows a leading '+', which from_chars does not take.
  std::string_view digits = starts_with(lexical, "+") ? lexical.substr(1) : lexical;
  std::int64_t value = 0;
  auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size()) {
    throw not_a("an integer", lexical);
  }
  return value;
}

double xsd_real(std::string_view lexical)
{
  if (lexical == "INF" || lexical == "+INF") {
    return std::numeric_limits<double>::infinity();
  }
  if (lexical == "-INF") {
    return -std::numeric_limits<double>::infinity();
  }
  if (lexical == "NaN") {
    return std::numeric_limits<double>::quiet_NaN();
  }
  std::string_view digits = starts_with(lexical, "+") ? lexical.substr(1) : lexical;
  double value = 0;
  auto [end, error] = std::from_chars(digits.data(), digits.data() + digits.size(), value);
  if (digits.empty() || error != std::errc() || end != digits.data() + digits.size()) {
    throw not_a("a real number", lexical);
  }
  return value;
}

// The shortest text that reads back as the same double, with a '.0' on whole numbers (as
// Python's repr, so both clients send the same lexical form).
std::string real_text(double value)
{
  char buffer[64];
  auto [end, error] = std::to_chars(buffer, buffer + sizeof(buffer), value);
  std::string text(buffer, end);
  if (std::isfinite(value) && text.find_first_of(".e") == std::string::npos) {
    text += ".0";
  }
  return text;
}

}  // namespace

std::string Value::to_string() const
{
  if (is<bool>()) {
    return as<bool>() ? "true" : "false";
  }
  if (is<std::int64_t>()) {
    return std::to_string(as<std::int64_t>());
  }
  if (is<double>()) {
    return real_text(as<double>());
  }
  return as<std::string>();
}

std::string entity_iri(std::string_view entity)
{
  if (starts_with(entity, "<") && ends_with(entity, ">")) {
    return std::string(entity.substr(1, entity.size() - 2));
  }
  return std::string(entity);
}

std::string short_name(std::string_view entity)
{
  std::string iri = entity_iri(entity);
  for (char separator : {'#', '/'}) {
    auto at = iri.rfind(separator);
    if (at != std::string::npos) {
      return iri.substr(at + 1);
    }
  }
  return iri;
}

bool is_literal(std::string_view answer)
{
  return starts_with(answer, "\"") &&
         (answer.find("\"^^") != std::string_view::npos ||
         answer.find("\"@") != std::string_view::npos || ends_with(answer, "\""));
}

Literal split_literal(std::string_view answer)
{
  if (!starts_with(answer, "\"")) {
    throw not_a("a literal", answer);
  }
  // The lexical form may itself contain quotes, so split at the last closing quote.
  auto typed = answer.rfind("\"^^");
  if (typed != std::string_view::npos && typed > 0) {
    std::string datatype(answer.substr(typed + 3));
    if (starts_with(datatype, "<" + std::string(kXsd))) {
      datatype = "xsd:" + datatype.substr(kXsd.size() + 1, datatype.size() - kXsd.size() - 2);
    }
    return {std::string(answer.substr(1, typed - 1)), datatype};
  }
  auto tagged = answer.rfind("\"@");
  if (tagged != std::string_view::npos && tagged > 0) {
    return {std::string(answer.substr(1, tagged - 1)), "rdf:langString"};
  }
  if (answer.size() >= 2 && ends_with(answer, "\"")) {
    return {std::string(answer.substr(1, answer.size() - 2)), "xsd:string"};
  }
  throw not_a("a literal", answer);
}

Value literal_value(std::string_view answer)
{
  Literal literal = split_literal(answer);
  std::string_view local = starts_with(literal.datatype, "xsd:") ?
    std::string_view(literal.datatype).substr(4) : std::string_view();
  if (kIntegerTypes.count(local)) {
    return xsd_integer(literal.lexical);
  }
  if (kRealTypes.count(local)) {
    return xsd_real(literal.lexical);
  }
  if (local == "boolean") {
    const std::string & text = literal.lexical;
    if (text != "true" && text != "false" && text != "1" && text != "0") {
      throw not_a("an xsd:boolean", text);
    }
    return text == "true" || text == "1";
  }
  return literal.lexical;
}

Value answer_value(std::string_view answer, bool iris)
{
  if (starts_with(answer, "\"")) {
    return literal_value(answer);
  }
  return iris ? entity_iri(answer) : short_name(answer);
}

std::pair<std::string, std::string> typed_argument(const Value & value, const std::string & datatype)
{
  if (value.is<bool>()) {
    return {datatype.empty() ? "BOOLEAN" : datatype, value.to_string()};
  }
  if (value.is<std::int64_t>()) {
    return {datatype.empty() ? "INTEGER" : datatype, value.to_string()};
  }
  if (value.is<double>()) {
    if (datatype.empty() && !std::isfinite(value.as<double>())) {
      throw std::invalid_argument(
              value.to_string() + " has no xsd:double lexical form ARMOR accepts");
    }
    return {datatype.empty() ? "DOUBLE" : datatype, value.to_string()};
  }
  return {datatype.empty() ? "STRING" : datatype, value.as<std::string>()};
}

}  // namespace armor
