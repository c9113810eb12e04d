// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Which rooms are occupied? Asks a running ARMOR node (make run) through the C++ client.
//
//   query_rooms [class]        (default OccupiedRoom)
#include <iostream>
#include <string>

#include "armor_cpp/armor.hpp"

int main(int argc, char ** argv)
{
  const std::string cls = argc > 1 ? argv[1] : "OccupiedRoom";
  try {
    armor::Armor armor("query_rooms");
    armor::Reference robotics = armor.reference("robotics");
    for (const std::string & room : robotics.instances(cls)) {
      std::cout << room << " (battery of whoever is in it: ";
      for (const std::string & agent : robotics.dl_instances("isIn value " + room)) {
        for (const armor::Value & level : robotics.data_values("batteryLevel", agent)) {
          std::cout << agent << " " << level.to_string() << "% ";
        }
      }
      std::cout << ")\n";
    }
    std::cout << "consistent: " << (robotics.check_consistency() ? "yes" : "no") << "\n";
  } catch (const armor::Error & error) {
    std::cerr << "query_rooms: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
