// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// The C++ client against a live ARMOR node, over real ROS 2 (rcl, Fast DDS).
//
// tests/integration/test_cpp_client.py starts the node and runs this program with
// ARMOR_TEST_ONTOLOGY (robotics.owl, readable by the node) and ARMOR_TEST_SCRATCH (a directory
// the node may write) set. Each test loads its own copy of robotics.owl under its own name and
// drops it, so tests neither see nor disturb each other or the node's preloaded "robotics".
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <memory>
#include <optional>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "armor_cpp/armor.hpp"
#include "armor_cpp/plugins.hpp"
#include "armor_cpp/rcl_transport.hpp"
#include "armor_cpp/scenes.hpp"

namespace
{

using Names = std::vector<std::string>;

std::string environment(const char * name)
{
  const char * value = std::getenv(name);
  if (value == nullptr) {
    throw std::runtime_error(std::string(name) + " is not set: run through test_cpp_client.py");
  }
  return value;
}

// One transport for the whole run, as a program would have (discovery is paid once).
std::shared_ptr<armor::Transport> shared_transport()
{
  static std::shared_ptr<armor::Transport> transport = [] {
      armor::RclTransportOptions options;
      options.service_wait = std::chrono::seconds(90);
      return std::make_shared<armor::RclTransport>(options);
    }();
  return transport;
}

armor::Armor session(const std::string & client)
{
  armor::Options options;
  options.timeout = std::chrono::seconds(120);
  return armor::Armor(client, shared_transport(), options);
}

// A fresh copy of robotics.owl under the test's name, dropped at the end of the test.
class LiveReference : public ::testing::Test
{
protected:
  void SetUp() override
  {
    const auto * info = ::testing::UnitTest::GetInstance()->current_test_info();
    name_ = std::string("cpp_") + info->test_suite_name() + "_" + info->name();
    ref_ = armor_.load_file(name_, environment("ARMOR_TEST_ONTOLOGY"));
  }

  void TearDown() override
  {
    Names loaded = armor_.references();
    if (std::find(loaded.begin(), loaded.end(), name_) != loaded.end()) {
      ref_->drop();
    }
  }

  armor::Armor armor_ = session("cpp_test");
  std::string name_;
  std::optional<armor::Reference> ref_;
};

TEST_F(LiveReference, QueriesAnswerNamesAndTypedValues)
{
  armor::Reference & ref = *ref_;
  EXPECT_EQ(ref.types_of("robot1"), (Names{"Agent", "Robot", "RobotInRoom"}));
  EXPECT_EQ(ref.classes_of("robot1", true), (Names{"RobotInRoom"}));
  EXPECT_EQ(ref.instances("Room"), (Names{"bedroom", "kitchen"}));
  EXPECT_EQ(ref.instances("OccupiedRoom"), (Names{"kitchen"}));
  EXPECT_EQ(ref.dl_instances("Agent and isIn some Room"), (Names{"robot1"}));
  EXPECT_EQ(ref.data_values("batteryLevel", "robot1"), (std::vector<armor::Value>{80}));
  EXPECT_EQ(ref.data_values("visitedAt", "bedroom"),
    (std::vector<armor::Value>{1700000000}));
  EXPECT_EQ(ref.object_values("connectedTo", "corridor1"), (Names{"bedroom", "kitchen"}));
  EXPECT_EQ(ref.subclasses("Agent"), (Names{"Person", "Robot", "RobotInRoom"}));
  EXPECT_EQ(ref.superclasses("RobotInRoom"), (Names{"Agent", "Robot"}));
  EXPECT_EQ(ref.disjoint_classes("Room"), (Names{"Corridor"}));
  EXPECT_EQ(ref.restrictions("OccupiedRoom"), (Names{"contains some Agent"}));
  EXPECT_EQ(armor_.reference(name_, true).instances("Room"),
    (Names{"http://www.example.org/robotics#bedroom", "http://www.example.org/robotics#kitchen"}));
  EXPECT_EQ(ref.consistent(), std::optional<bool>(true));
}

TEST_F(LiveReference, SparqlAskAndConsistency)
{
  armor::Reference & ref = *ref_;
  armor::SparqlRows rows = ref.sparql("SELECT ?who ?where WHERE { ?who :isIn ?where } ORDER BY ?who");
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("who"), armor::Value("alice"));
  EXPECT_EQ(rows[0].at("where"), armor::Value("corridor1"));
  EXPECT_EQ(rows[1].at("where"), armor::Value("kitchen"));
  EXPECT_FALSE(rows.timed_out);
  armor::SparqlRows level = ref.sparql("SELECT ?v WHERE { :robot1 :batteryLevel ?v }", 60000);
  ASSERT_EQ(level.size(), 1u);
  EXPECT_EQ(level[0].at("v"), armor::Value(80));
  EXPECT_EQ(ref.sparql_lines("SELECT ?r WHERE { ?r a :OccupiedRoom }"),
    (Names{"<http://www.example.org/robotics#kitchen>"}));
  EXPECT_TRUE(ref.ask("ASK { :robot1 :isIn :kitchen }"));
  EXPECT_FALSE(ref.ask("ASK { :robot1 :isIn :bedroom }"));
  armor::Consistency consistency = ref.check_consistency();
  EXPECT_TRUE(consistency);
  EXPECT_TRUE(consistency.explanation.empty());
}

TEST_F(LiveReference, ChangesAreSeenByTheReasoner)
{
  armor::Reference & ref = *ref_;
  ref.replace_object_value("isIn", "alice", "bedroom", "corridor1");
  EXPECT_EQ(ref.instances("OccupiedRoom"), (Names{"bedroom", "kitchen"}));
  ref.add_individual_to_class("bob", "Person");
  EXPECT_EQ(ref.instances("Person"), (Names{"alice", "bob"}));
  ref.add_data_value("batteryLevel", "bob", 42);
  ref.replace_data_value("batteryLevel", "bob", 41, 42);
  EXPECT_EQ(ref.data_values("batteryLevel", "bob"), (std::vector<armor::Value>{41}));
  ref.add_data_value("visitedAt", "kitchen", 1700000000123LL, "LONG");
  EXPECT_EQ(ref.data_values("visitedAt", "kitchen"),
    (std::vector<armor::Value>{1700000000123LL}));
  ref.remove_individual("bob");
  EXPECT_EQ(ref.instances("Person"), (Names{"alice"}));
}

TEST_F(LiveReference, TheMountGuardKeepsOtherClientsOutUntilItEnds)
{
  armor::Reference other = session("cpp_other").reference(name_);
  {
    auto mount = ref_->mounted();
    EXPECT_EQ(ref_->mounted_by(), std::optional<std::string>("cpp_test"));
    try {
      other.add_individual_to_class("intruder", "Person");
      FAIL() << "a change under another client's mount succeeded";
    } catch (const armor::MountError & refused) {
      EXPECT_EQ(refused.code(), 102);
    }
    EXPECT_EQ(other.instances("Person"), (Names{"alice"})) << "queries are never refused";
    ref_->add_individual_to_class("bob", "Person");
  }
  EXPECT_EQ(ref_->mounted_by(), std::nullopt);
  other.add_individual_to_class("carol", "Person");
  EXPECT_EQ(other.instances("Person"), (Names{"alice", "bob", "carol"}));
  EXPECT_THROW(ref_->unmount(), armor::MountError);
}

TEST_F(LiveReference, TheChangeHistoryTellsWhetherAChangeWasApplied)
{
  std::uint64_t before = ref_->revision();
  ref_->add_individual_to_class("dave", "Person");
  EXPECT_EQ(ref_->revision(), before + 1);
  auto changes = ref_->changes_since(static_cast<std::int64_t>(before));
  ASSERT_EQ(changes.size(), 1u);
  EXPECT_NE(changes.front().find("\"revision\":" + std::to_string(before + 1)), std::string::npos)
    << changes.front();
  EXPECT_NE(changes.front().find("\"args\":[\"dave\",\"Person\"]"), std::string::npos)
    << changes.front();
  EXPECT_NE(changes.front().find("\"client_name\":\"cpp_test\""), std::string::npos)
    << changes.front();
  EXPECT_TRUE(ref_->changes_since(static_cast<std::int64_t>(before + 1)).empty());
}

TEST_F(LiveReference, ABatchChangesAllOrNothing)
{
  armor::Reference & ref = *ref_;
  std::optional<bool> consistent = armor::atomically(ref, [](armor::Batch & batch) {
        batch.add_individual_to_class("bob", "Person").add_object_value("isIn", "bob", "bedroom");
      });
  EXPECT_EQ(consistent, std::optional<bool>(true));
  EXPECT_EQ(ref.instances("OccupiedRoom"), (Names{"bedroom", "kitchen"}));
  armor::Batch failing = ref.batch();
  failing.add_individual_to_class("dave", "Person")
  .add_data_value("batteryLevel", "dave", "eighty", "INTEGER")
  .add_individual_to_class("erin", "Person");
  try {
    failing.send();
    FAIL() << "a list with a bad value succeeded";
  } catch (const armor::ServiceInternalError & error) {
    EXPECT_EQ(error.index(), std::optional<std::size_t>(1));
    EXPECT_EQ(error.responses().size(), 3u);
    EXPECT_EQ(error.responses()[2].exit_code, 212);
  }
  EXPECT_EQ(ref.instances("Person"), (Names{"alice", "bob"})) << "the list was not undone";
}

TEST_F(LiveReference, ErrorsCarryTheExitCodeAndChangeNothing)
{
  armor::Reference & ref = *ref_;
  try {
    ref.add_data_value("batteryLevel", "robot1", "full", "NOT_A_TYPE");
    FAIL() << "an unknown datatype was accepted";
  } catch (const armor::ArgumentError & error) {
    EXPECT_EQ(error.code(), 101);
    EXPECT_FALSE(error.description().empty());
  }
  EXPECT_EQ(ref.data_values("batteryLevel", "robot1"), (std::vector<armor::Value>{80}));
  try {
    armor_.reference("cpp_nowhere").instances("Room");
    FAIL() << "a query on no reference answered";
  } catch (const armor::UnknownReferenceError & error) {
    EXPECT_EQ(error.code(), 206);
  }
  EXPECT_THROW(armor_.load_file("cpp_missing", "/nonexistent/robotics.owl"), armor::FileError);
}

TEST_F(LiveReference, SavesToAFileTheNodeWrites)
{
  std::string path = environment("ARMOR_TEST_SCRATCH") + "/cpp_saved.ttl";
  ref_->add_individual_to_class("bob", "Person");
  ref_->save(path, "turtle");
  std::ifstream saved(path);
  std::stringstream text;
  text << saved.rdbuf();
  EXPECT_NE(text.str().find("@prefix"), std::string::npos);
  EXPECT_NE(text.str().find("bob"), std::string::npos);
}

// Issue 35 item 1: a relative path is this process's, not the node's (whose working
// directory is ARMOR_TEST_SCRATCH itself): the client sends it made absolute.
TEST_F(LiveReference, RelativePathsAreTheCallers)
{
  const std::filesystem::path folder =
    std::filesystem::path(environment("ARMOR_TEST_SCRATCH")) / "cpp_caller";
  std::filesystem::create_directories(folder);
  std::filesystem::copy_file(environment("ARMOR_TEST_ONTOLOGY"), folder / "relative.owl",
    std::filesystem::copy_options::overwrite_existing);
  const std::filesystem::path before = std::filesystem::current_path();
  std::filesystem::current_path(folder);
  try {
    armor::Reference relative = armor_.load_file(name_ + "_relative", "relative.owl");
    relative.save("cpp_relative.ttl", "turtle");
    relative.drop();
  } catch (...) {
    std::filesystem::current_path(before);
    throw;
  }
  std::filesystem::current_path(before);
  EXPECT_TRUE(std::filesystem::exists(folder / "cpp_relative.ttl"));
  EXPECT_FALSE(std::filesystem::exists(
      std::filesystem::path(environment("ARMOR_TEST_SCRATCH")) / "cpp_relative.ttl"));
}

TEST(Session, UtilitiesAndRawCalls)
{
  armor::Armor armor = session("cpp_test");
  Names loaded = armor.references();
  EXPECT_NE(std::find(loaded.begin(), loaded.end(), "robotics"), loaded.end());
  EXPECT_NE(armor.catalogue().find("\"QUERY IND CLASS\""), std::string::npos);
  armor::Reference created = armor.create("cpp_created", "http://example.org/cpp",
      armor::ReasonerOptions{armor::reasoner::PELLET, false, false});
  created.add_individual_to_class("r1", "Room");
  EXPECT_EQ(created.instances("Room"), (Names{"r1"}));
  created.drop();
  auto raw = armor.call("robotics", "QUERY", "IND", "CLASS", {"Robot"});
  EXPECT_TRUE(raw.success);
  EXPECT_EQ(raw.queried_objects, (Names{"<http://www.example.org/robotics#robot1>"}));
  EXPECT_FALSE(armor.call("cpp_nowhere", "QUERY", "IND", "CLASS", {"Robot"}).success);
}

TEST(Session, TimeLimitsThrowCallTimeout)
{
  armor::Options impatient;
  impatient.timeout = std::chrono::milliseconds(0);
  armor::Armor armor("cpp_impatient", shared_transport(), impatient);
  EXPECT_THROW(armor.references(), armor::CallTimeout);
}

TEST(Session, NoServiceIsACallErrorWithoutExitCode)
{
  armor::Options lonely;
  lonely.ns = "/nobody_here";
  lonely.service_wait = std::chrono::milliseconds(500);
  armor::Armor armor("cpp_lonely", lonely);
  try {
    armor.references();
    FAIL() << "a call without a service answered";
  } catch (const armor::ServiceCallError & error) {
    EXPECT_EQ(error.exit_code(), std::nullopt);
    EXPECT_NE(std::string(error.what()).find("armor serve"), std::string::npos);
  }
}

TEST(Session, CallsFromSeveralThreadsAreAnsweredEachItsOwn)
{
  armor::Reference robotics = session("cpp_threads").reference("robotics");
  std::vector<std::thread> threads;
  std::vector<Names> answers(8);
  for (std::size_t i = 0; i < answers.size(); ++i) {
    threads.emplace_back([&, i] {
        answers[i] = robotics.instances(i % 2 ? "Room" : "Robot");
      });
  }
  for (auto & thread : threads) {
    thread.join();
  }
  for (std::size_t i = 0; i < answers.size(); ++i) {
    EXPECT_EQ(answers[i], i % 2 ? (Names{"bedroom", "kitchen"}) : (Names{"robot1"}));
  }
}

// The scene plugin (docs/scenes.md) through learn_scene: learned, then recognised with 1.0;
// a bad element is an ArgumentError that leaves no class behind.
TEST(Scenes, ASceneIsLearnedThenRecognised)
{
  armor::Armor armor = session("cpp_scenes");
  const std::string name = "cpp_scenes";
  Names loaded = armor.references();
  if (std::find(loaded.begin(), loaded.end(), name) != loaded.end()) {
    armor.reference(name).drop();
  }
  armor::Reference table = armor.create(name, "http://www.emarolab.it/sit/simple");
  std::vector<armor::SceneElement> scene{{"SPHERE", {0, 0, 0}}, {"CONE", {-0.8, -0.8, 0, 0, 0, 1}}};
  armor::SceneAnswer learned = armor::learn_scene(table, scene, 0.9);
  EXPECT_EQ(learned.learned_scene_name, "SCENE-1");
  EXPECT_TRUE(learned.recognitions.empty());
  armor::SceneAnswer again = armor::learn_scene(table, scene, 0.9);
  EXPECT_EQ(again.learned_scene_name, "");
  ASSERT_EQ(again.recognitions.size(), 1u);
  EXPECT_EQ(again.recognitions[0].class_name, "SCENE-1");
  EXPECT_DOUBLE_EQ(again.recognitions[0].similarity, 1.0);
  EXPECT_THROW(
    armor::learn_scene(table, {{"CUBE", {0, 0, 0}}, {"SPHERE", {1, 1, 1}}}, 0.9), armor::ArgumentError);
  EXPECT_THROW(
    armor::learn_scene(table, {{"SPHERE", {0, std::nan(""), 0}}, {"SPHERE", {1, 1, 1}}}, 0.9),
    armor::ArgumentError);
  EXPECT_EQ(table.subclasses("SCENE"), Names{"SCENE-1"});
  // QUERY SIT SCENES through its generated method (plugins.hpp): one JSON object, SCENE-1's.
  Names classes = armor::plugins::Reference(table).scene_classes();
  ASSERT_EQ(classes.size(), 1u);
  EXPECT_NE(classes[0].find("\"SCENE-1\""), std::string::npos) << classes[0];
  table.drop();
}

// The PDDL plugin (loaded by every node by default) through the method plugins.hpp generates
// from its catalogue entry: the same problem as the raw directive, and the reasoner's
// conclusions in it (OccupiedRoom is inferred); the mapping given as text.
TEST_F(LiveReference, APluginsQueryAnswersThroughItsGeneratedMethod)
{
  std::ifstream file(environment("ARMOR_TEST_PDDL_MAPPING"));
  std::stringstream mapping;
  mapping << file.rdbuf();
  armor::plugins::Reference planner = *ref_;
  Names problem = planner.pddl_problem(mapping.str());
  ASSERT_EQ(problem.size(), 1u);
  EXPECT_EQ(problem, armor_.call(name_, "QUERY", "PDDL", "PROBLEM", {mapping.str()}).queried_objects);
  EXPECT_NE(problem[0].find("(problem check-occupied-rooms)"), std::string::npos) << problem[0];
  EXPECT_NE(problem[0].find("(visited "), std::string::npos) << problem[0];
  // The built-in methods are armor::Reference's, on the same reference.
  EXPECT_EQ(planner.instances("Robot"), ref_->instances("Robot"));
}

}  // namespace

int main(int argc, char ** argv)
{
  ::testing::InitGoogleTest(&argc, argv);
  return RUN_ALL_TESTS();
}
