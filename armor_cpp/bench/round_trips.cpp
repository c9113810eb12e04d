// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Round trips of the C++ client, for bench/cpp_latency.py (which runs the same calls from the
// Python client beside it) and bench/fleet_latency.py.
//
//   armor_cpp_round_trips NAMESPACE REFERENCE CALLS
//
// Against the node in NAMESPACE, with REFERENCE loaded from robotics.owl: after a warm-up,
// CALLS round trips of each kind (a query; a change; an atomic list of 10 changes, the
// changes moving robot1 back and forth, so that every call finds the same ontology); prints
// one line per kind, `kind s1 s2 ...` in seconds. Leaves the ontology as it found it. Every
// answer is checked (the rooms; where robot1 is after the changes): a wrong one exits with 1.
#include <chrono>
#include <iostream>
#include <stdexcept>
#include <string>
#include <vector>

#include "armor_cpp/armor.hpp"

namespace
{

template<typename Call>
std::vector<double> timed(int calls, Call && call)
{
  std::vector<double> seconds;
  for (int i = 0; i < calls; ++i) {
    auto start = std::chrono::steady_clock::now();
    call(i);
    seconds.push_back(std::chrono::duration<double>(std::chrono::steady_clock::now() - start)
      .count());
  }
  return seconds;
}

// Stops the run when an answer is not the one its figure assumes.
void expect(
  const std::vector<std::string> & answer, const std::vector<std::string> & right,
  const std::string & what)
{
  if (answer != right) {
    throw std::runtime_error("wrong answer to " + what);
  }
}

void print(const std::string & kind, const std::vector<double> & seconds)
{
  std::cout << kind;
  for (double s : seconds) {
    std::cout << ' ' << s;
  }
  std::cout << std::endl;
}

}  // namespace

int main(int argc, char ** argv)
{
  if (argc != 4) {
    std::cerr << "usage: armor_cpp_round_trips NAMESPACE REFERENCE CALLS\n";
    return 2;
  }
  armor::Options options;
  options.ns = argv[1];
  options.service_wait = std::chrono::seconds(120);
  const int calls = std::stoi(argv[3]);
  try {
    armor::Armor armor("bench_cpp", options);
    armor::Reference ref = armor.reference(argv[2]);
    const std::vector<std::string> all_rooms = {"bedroom", "kitchen"};
    for (int i = 0; i < 20; ++i) {
      ref.instances("Room");
    }
    print("query", timed(calls, [&](int) {expect(ref.instances("Room"), all_rooms, "a query");}));
    // Changes that undo each other (robot1 moves between kitchen and bedroom), so the
    // ontology, and with it the reasoner's work, is the same for every call and client.
    const char * rooms[] = {"kitchen", "bedroom"};
    print("manipulation", timed(calls, [&](int i) {
        ref.replace_object_value("isIn", "robot1", rooms[(i + 1) % 2], rooms[i % 2]);
      }));
    expect(ref.object_values("isIn", "robot1"), {rooms[calls % 2]}, "where robot1 went");
    if (calls % 2) {  // back to the kitchen before the lists, which start from there
      ref.replace_object_value("isIn", "robot1", "kitchen", "bedroom");
    }
    print("list_of_10", timed(calls, [&](int) {
        armor::Batch batch = ref.batch();
        for (int j = 0; j < 10; ++j) {
          batch.replace_object_value("isIn", "robot1", rooms[(j + 1) % 2], rooms[j % 2]);
        }
        batch.send();
      }));
    expect(ref.object_values("isIn", "robot1"), {"kitchen"}, "where the lists left robot1");
  } catch (const std::runtime_error & error) {  // armor::Error, or a wrong answer
    std::cerr << "armor_cpp_round_trips: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
