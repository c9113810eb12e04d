// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
#include "armor_cpp/scenes.hpp"

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

#include "armor_cpp/errors.hpp"
#include "armor_cpp/values.hpp"

namespace armor
{

namespace
{

// A plugin's command: not in the built-in catalogue the contract header is made from.
constexpr contract::Command kSitScene{"SIT", "SCENE", "", contract::Kind::Manipulation, 4, 0, false, true};

std::string number(double value)
{
  if (std::isnan(value)) {
    return "NaN";
  }
  if (std::isinf(value)) {
    return value > 0 ? "Infinity" : "-Infinity";
  }
  char text[32];
  std::snprintf(text, sizeof(text), "%.17g", value);
  return text;
}

std::string json_string(const std::string & text)
{
  std::string quoted = "\"";
  for (char c : text) {
    if (c == '"' || c == '\\') {
      quoted += '\\';
      quoted += c;
    } else if (static_cast<unsigned char>(c) < 0x20) {
      char escaped[8];
      std::snprintf(escaped, sizeof(escaped), "\\u%04x", static_cast<unsigned char>(c));
      quoted += escaped;
    } else {
      quoted += c;
    }
  }
  return quoted + "\"";
}

}  // namespace

std::vector<std::string> scene_arguments(
  const std::vector<SceneElement> & elements, double threshold, const SceneThresholds & thresholds)
{
  std::string json = "[";
  for (std::size_t i = 0; i < elements.size(); ++i) {
    json += (i ? ", " : "") + std::string("{\"type\": ") + json_string(elements[i].type) +
      ", \"features\": [";
    for (std::size_t j = 0; j < elements[i].features.size(); ++j) {
      json += (j ? ", " : "") + number(elements[i].features[j]);
    }
    json += "]}";
  }
  json += "]";
  return {number(threshold), number(thresholds.position), number(thresholds.axis), json};
}

SceneAnswer read_scene_answer(const std::vector<std::string> & queried_objects)
{
  SceneAnswer answer;
  for (const std::string & line : queried_objects) {
    std::size_t space = line.find(' ');
    std::string word = line.substr(0, space);
    std::string rest = space == std::string::npos ? "" : line.substr(space + 1);
    if (word == "learned") {
      answer.learned_scene_name = short_name(rest);
    } else if (word == "recognised") {
      std::size_t last = rest.rfind(' ');
      answer.recognitions.push_back(
        Recognition{short_name(rest.substr(0, last)), std::stod(rest.substr(last + 1))});
    }
  }
  return answer;
}

SceneAnswer learn_scene(
  const Reference & reference, const std::vector<SceneElement> & elements, double threshold,
  const SceneThresholds & thresholds)
{
  return read_scene_answer(reference.armor().execute(
      reference.name(), kSitScene, scene_arguments(elements, threshold, thresholds)).queried_objects);
}

}  // namespace armor
