// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Teaching a reference scenes by demonstration (docs/scenes.md): the SIT plugin's SIT SCENE,
// as the Python client's Reference.learn_scene. The scene goes as a directive of this client
// (its mount applies; it is journaled and announced like any change).
//
//   armor::Reference table = armor.reference("table");
//   armor::SceneAnswer answer = armor::learn_scene(table,
//     {{"SPHERE", {0, 0, 0}}, {"CONE", {0.3, 0, 0, 0, 0, 1}}}, 0.9);
//   // answer.learned_scene_name == "SCENE-1", answer.recognitions empty
#ifndef ARMOR_CPP__SCENES_HPP_
#define ARMOR_CPP__SCENES_HPP_

#include <string>
#include <vector>

#include "armor_cpp/armor.hpp"

namespace armor
{

// One primitive: type SPHERE, PLANE, CONE or CYLINDER; features the centre x y z, for the last
// three optionally followed by the axis.
struct SceneElement
{
  std::string type;
  std::vector<double> features;
};

// A scene class the scene was recognised as: card(class) / card(scene), in [0, 1].
struct Recognition
{
  std::string class_name;
  double similarity = 0.0;
};

// The class learned from the scene (empty when none was) and every recognition, most similar first.
struct SceneAnswer
{
  std::string learned_scene_name;
  std::vector<Recognition> recognitions;
};

// The thresholds the relations are tested with (ROS 1 SIT's; the node's scene service uses its
// parameters sit_position_threshold and sit_axis_threshold instead).
struct SceneThresholds
{
  double position = 0.03;  // metres: right/behind/above, along an axis
  double axis = 0.05;  // parallel, perpendicular, coaxial
};

// Recognise a scene under the reference's learned scene classes and learn it as a new class
// unless one has a similarity above `threshold` (SIT SCENE). Class names are short (SCENE-3).
// Throws the error of ARMOR's exit code: ArgumentError for a bad element (207, 101, 221),
// MountError under another client's mount, UnknownReferenceError.
SceneAnswer learn_scene(
  const Reference & reference, const std::vector<SceneElement> & elements, double threshold,
  const SceneThresholds & thresholds = {});

// SIT SCENE's four arguments (the elements as JSON; NaN and infinities spelt for the core to refuse).
std::vector<std::string> scene_arguments(
  const std::vector<SceneElement> & elements, double threshold, const SceneThresholds & thresholds);

// SIT SCENE's answer read: "learned <class>" and "recognised <class> <similarity>" lines.
SceneAnswer read_scene_answer(const std::vector<std::string> & queried_objects);

}  // namespace armor

#endif  // ARMOR_CPP__SCENES_HPP_
