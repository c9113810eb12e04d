// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// Round trips of the C++ client, for bench/cpp_latency.py (which runs the same calls from the
// Python client beside it) and bench/fleet_latency.py.
//
//   armor_cpp_round_trips NAMESPACE REFERENCE CALLS
//
// Against the node in NAMESPACE, with REFERENCE loaded from robotics.owl: after a warm-up,
// CALLS round trips of each kind; prints one line per kind, `kind s1 s2 ...` in seconds.
#include <unistd.h>

#include <chrono>
#include <iostream>
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
    // Names of this process only: a change that is already there costs the node nothing.
    const std::string run = std::to_string(getpid());
    for (int i = 0; i < 20; ++i) {
      ref.instances("Room");
    }
    print("query", timed(calls, [&](int) {ref.instances("Room");}));
    print("manipulation", timed(calls, [&](int i) {
        ref.add_individual_to_class("cpp_box" + run + "_" + std::to_string(i), "Box");
      }));
    print("list_of_10", timed(calls, [&](int i) {
        armor::Batch batch = ref.batch();
        for (int j = 0; j < 10; ++j) {
          batch.add_individual_to_class(
            "cpp_item" + run + "_" + std::to_string(i) + "_" + std::to_string(j), "Box");
        }
        batch.send();
      }));
  } catch (const armor::Error & error) {
    std::cerr << "armor_cpp_round_trips: " << error.what() << "\n";
    return 1;
  }
  return 0;
}
