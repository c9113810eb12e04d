// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// The C++ client without a node: a recording transport stands in for the service.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <set>
#include <string>
#include <tuple>
#include <vector>

#include "armor_cpp/armor.hpp"

namespace
{

using armor_msgs::msg::ArmorDirectiveReq;
using armor_msgs::msg::ArmorDirectiveRes;
using Words = std::tuple<std::string, std::string, std::string>;

// Answers every directive with `answer` and remembers what was sent.
class RecordingTransport : public armor::Transport
{
public:
  std::vector<ArmorDirectiveReq> sent;
  std::vector<std::vector<ArmorDirectiveReq>> lists;
  ArmorDirectiveRes answer;
  armor_msgs::srv::ArmorDirectiveList::Response list_answer;

  RecordingTransport()
  {
    answer.success = true;
    answer.is_consistent = true;
    armor_msgs::msg::QueryItem ask;
    ask.key = "ASK";
    ask.value = "true";
    answer.sparql_queried_objects.push_back(ask);
    list_answer.success = true;
    list_answer.is_consistent = true;
  }

  ArmorDirectiveRes call(const ArmorDirectiveReq & request, armor::Timeout) override
  {
    sent.push_back(request);
    return answer;
  }

  armor_msgs::srv::ArmorDirectiveList::Response call_list(
    const std::vector<ArmorDirectiveReq> & requests, armor::Timeout) override
  {
    lists.push_back(requests);
    return list_answer;
  }
};

Words words_of(const ArmorDirectiveReq & request)
{
  return {request.command, request.primary_command_spec, request.secondary_command_spec};
}

// Every manipulation, on a Reference or a Batch alike (one list for both, as the methods).
template<typename Target>
void every_manipulation(Target & t)
{
  t.add_individual("i");
  t.add_individual_to_class("i", "C");
  t.remove_individual("i");
  t.remove_individual_from_class("i", "C");
  t.add_same_individuals({"a", "b"});
  t.remove_same_individuals({"a", "b"});
  t.make_individuals_different({"a", "b"});
  t.make_instances_different("C");
  t.rename_individual("a", "b");
  t.add_class("C");
  t.add_subclass("C", "D");
  t.remove_class("C");
  t.remove_subclass("C", "D");
  t.make_classes_disjoint({"C", "D"});
  t.make_subclasses_disjoint("C");
  t.make_equivalent_to_superclasses("C");
  t.add_equivalent_class("C", "D and E");
  t.remove_equivalent_class("C", "D and E");
  t.add_min_cardinality("C", "p", 2, "D");
  t.rename_class("C", "D");
  t.add_data_value("p", "i", 80);
  t.remove_data_value("p", "i", 80);
  t.replace_data_value("p", "i", 81, 80);
  t.add_object_value("p", "i", "j");
  t.remove_object_value("p", "i", "j");
  t.replace_object_value("p", "i", "k", "j");
  t.add_object_subproperty("p", "q");
  t.remove_object_subproperty("p", "q");
  t.add_data_subproperty("p", "q");
  t.remove_data_subproperty("p", "q");
  t.add_inverse_property("p", "q");
  t.remove_inverse_property("p", "q");
  t.add_object_characteristic("p", armor::characteristic::TRANSITIVE);
  t.remove_object_characteristic("p", armor::characteristic::TRANSITIVE);
  t.add_data_characteristic("p");
  t.remove_data_characteristic("p");
  t.add_object_domain("p", "C");
  t.remove_object_domain("p", "C");
  t.add_object_range("p", "C");
  t.remove_object_range("p", "C");
  t.add_data_domain("p", "C");
  t.remove_data_domain("p", "C");
  t.add_data_range("p", "INTEGER");
  t.remove_data_range("p", "INTEGER");
  t.rename_object_property("p", "q");
  t.rename_data_property("p", "q");
  t.add_axiom("C SubClassOf D");
  t.remove_axiom("C SubClassOf D");
  t.add_rule("r", "C(?x) -> D(?x)");
  t.remove_rule("r", "C(?x) -> D(?x)");
  t.apply();
  t.reason();
}

// Every other method of Armor and Reference, each variant that sends other words.
void every_other_method(const armor::Armor & armor, armor::Reference & ref)
{
  armor::LoadOptions mounted;
  mounted.mount = true;
  armor.load_file("r", "/x.owl");
  armor.load_file("r", "/x.owl", "", mounted);
  armor.load_web("r", "http://x.org/o.owl");
  armor.load_web("r", "http://x.org/o.owl", "", mounted);
  armor.create("r", "http://x.org/o");
  armor.references();
  armor.load_progress();
  armor.catalogue();
  armor.mounted_by("r");
  armor.revision("r");
  armor.changes_since("r", 3);
  armor.digest("r");
  armor.state_damage();
  ref.explain_instance("i", "C");
  ref.explain_object_property("p", "i", "j", 2);
  ref.explain_data_property("p", "i", "INTEGER", "3");
  ref.explain_subclass("C", "D");
  ref.explain_inconsistency();
  armor.log_to_screen(true);
  armor.log_to_screen(false);
  armor.log_to_file(std::string("/tmp/armor.log"));
  armor.log_to_file(std::nullopt);
  ref.types_of("i");
  ref.classes_of("i");
  ref.instances("C");
  ref.dl_instances("C and D");
  ref.same_individuals("i");
  ref.data_properties_of("i");
  ref.object_properties_of("i");
  ref.data_values("p", "i");
  ref.object_values("p", "i");
  ref.subclasses("C");
  ref.dl_subclasses("C and D");
  ref.superclasses("C");
  ref.equivalent_classes("C");
  ref.disjoint_classes("C");
  ref.restrictions("C");
  ref.object_subproperties("p");
  ref.data_subproperties("p");
  ref.sparql("SELECT ?x WHERE { ?x a :C }");
  ref.sparql_lines("SELECT ?x WHERE { ?x a :C }");
  ref.ask("ASK { :a :p :b }");
  ref.check_consistency();
  ref.save();
  ref.save("", "", true);
  ref.drop();
  ref.mount();
  ref.unmount();
  ref.mounted_by();
  ref.revision();
  ref.changes_since();
}

std::string name_of(const Words & words)
{
  return std::get<0>(words) + " " + std::get<1>(words) + " " + std::get<2>(words);
}

TEST(Catalogue, EveryCommandOfTheCoresCatalogueHasAMethodThatSendsIt)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Armor armor("me", transport);
  armor::Reference ref = armor.reference("ref");
  every_manipulation(ref);
  every_other_method(armor, ref);
  std::set<Words> sent;
  for (const auto & request : transport->sent) {
    sent.insert(words_of(request));
  }
  for (const armor::contract::Command * command : armor::contract::kCommands) {
    Words words{std::string(command->command), std::string(command->primary),
      std::string(command->secondary)};
    EXPECT_TRUE(sent.count(words)) << "no method of the C++ client sends " << name_of(words);
  }
}

TEST(Catalogue, EveryDirectiveSentHasTheArgumentCountTheCatalogueGivesIt)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Armor armor("me", transport);
  armor::Reference ref = armor.reference("ref");
  every_manipulation(ref);
  every_other_method(armor, ref);
  for (const auto & request : transport->sent) {
    const armor::contract::Command * found = nullptr;
    for (const armor::contract::Command * command : armor::contract::kCommands) {
      if (words_of(request) == Words{std::string(command->command),
          std::string(command->primary), std::string(command->secondary)})
      {
        found = command;
      }
    }
    ASSERT_NE(found, nullptr) << name_of(words_of(request));
    EXPECT_TRUE(found->accepts(static_cast<int>(request.args.size())))
      << name_of(words_of(request)) << " sent with " << request.args.size() << " arguments";
    EXPECT_EQ(request.client_name, "me");
  }
}

TEST(Batch, QueuesTheSameManipulationsAsAReferenceAndSendsThemAsOneList)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Armor armor("me", transport);
  armor::Reference ref = armor.reference("ref");
  every_manipulation(ref);
  armor::Batch batch = ref.batch();
  every_manipulation(batch);
  EXPECT_EQ(batch.size(), transport->sent.size());
  for (std::size_t i = 0; i < batch.size(); ++i) {
    EXPECT_EQ(batch.requests()[i], transport->sent[i]);
  }
  EXPECT_TRUE(batch.send());
  ASSERT_EQ(transport->lists.size(), 1u);
  EXPECT_EQ(transport->lists[0].size(), transport->sent.size());
  EXPECT_EQ(batch.size(), 0u);
}

TEST(Batch, CallsChain)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Batch batch = armor::Armor("me", transport).reference("ref").batch();
  batch.add_individual("a").add_individual_to_class("a", "Room").add_data_value("p", "a", 1.5);
  ASSERT_EQ(batch.size(), 3u);
  EXPECT_EQ(batch.requests()[2].args,
    (std::vector<std::string>{"p", "a", "DOUBLE", "1.5"}));
}

TEST(Batch, AFailedListThrowsTheFailingDirectivesErrorWithItsIndex)
{
  auto transport = std::make_shared<RecordingTransport>();
  ArmorDirectiveRes ok, bad, rolled_back;
  ok.success = true;
  bad.exit_code = 102;
  bad.error_description = "mounted by someone";
  rolled_back.exit_code = 212;
  transport->list_answer.success = false;
  transport->list_answer.armor_responses = {rolled_back, bad, rolled_back};
  armor::Batch batch = armor::Armor("me", transport).reference("ref").batch();
  batch.add_individual("a").add_individual("b").add_individual("c");
  try {
    batch.send();
    FAIL() << "no exception";
  } catch (const armor::MountError & error) {
    EXPECT_EQ(error.code(), 102);
    EXPECT_EQ(error.description(), "mounted by someone");
    EXPECT_EQ(error.index(), std::optional<std::size_t>(1));
    EXPECT_EQ(error.responses().size(), 3u);
  }
  EXPECT_EQ(batch.size(), 3u) << "a failed list stays queued";
}

TEST(Batch, AtomicallySendsNothingWhenFillingThrows)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Reference ref = armor::Armor("me", transport).reference("ref");
  EXPECT_THROW(armor::atomically(ref, [](armor::Batch & batch) {
      batch.add_individual("a");
      throw std::runtime_error("changed my mind");
    }), std::runtime_error);
  EXPECT_TRUE(transport->lists.empty());
  EXPECT_EQ(armor::atomically(ref, [](armor::Batch &) {}), std::nullopt);
  EXPECT_TRUE(transport->lists.empty());
  EXPECT_EQ(armor::atomically(ref, [](armor::Batch & batch) {batch.add_individual("a");}),
    std::optional<bool>(true));
  EXPECT_EQ(transport->lists.size(), 1u);
}

TEST(Mount, TheGuardMountsAndUnmountsOnceEvenWhenTheBlockThrows)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Reference ref = armor::Armor("me", transport).reference("ref");
  try {
    auto mount = ref.mounted();
    ASSERT_EQ(transport->sent.size(), 1u);
    EXPECT_EQ(transport->sent[0].command, "MOUNT");
    throw std::runtime_error("the block failed");
  } catch (const std::runtime_error &) {
  }
  ASSERT_EQ(transport->sent.size(), 2u);
  EXPECT_EQ(transport->sent[1].command, "UNMOUNT");
  {
    auto mount = ref.mounted();
    mount.release();
  }
  EXPECT_EQ(transport->sent.size(), 4u) << "release() unmounts, the destructor not again";
}

TEST(Mount, ALostMountDoesNotThrowFromTheDestructor)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Reference ref = armor::Armor("me", transport).reference("ref");
  {
    auto mount = ref.mounted();
    transport->answer.success = false;
    transport->answer.exit_code = 203;
  }
  EXPECT_EQ(transport->sent.back().command, "UNMOUNT");
  transport->answer.success = true;
  auto mount = ref.mounted();
  transport->answer.success = false;
  EXPECT_THROW(mount.release(), armor::MountError);
}

TEST(Errors, EachExitCodeThrowsItsClassWithCodeAndDescription)
{
  auto expect = [](int code, auto * type) {
      using Expected = std::remove_pointer_t<decltype(type)>;
      ArmorDirectiveRes response;
      response.exit_code = code;
      response.error_description = "why";
      try {
        armor::throw_error_for(response);
      } catch (const Expected & error) {
        EXPECT_EQ(error.code(), code);
        EXPECT_EQ(error.description(), "why");
        EXPECT_EQ(std::string(error.what()), std::to_string(code) + ": why");
        return;
      } catch (...) {
      }
      ADD_FAILURE() << code << " did not throw the expected class";
    };
  expect(102, static_cast<armor::MountError *>(nullptr));
  expect(203, static_cast<armor::MountError *>(nullptr));
  expect(207, static_cast<armor::ArgumentError *>(nullptr));
  expect(206, static_cast<armor::UnknownReferenceError *>(nullptr));
  expect(213, static_cast<armor::FileError *>(nullptr));
  expect(217, static_cast<armor::ReasonerError *>(nullptr));
  expect(211, static_cast<armor::TimeLimitError *>(nullptr));
  expect(212, static_cast<armor::RolledBackError *>(nullptr));
  expect(216, static_cast<armor::CoreUnavailableError *>(nullptr));
  expect(220, static_cast<armor::ServiceInternalError *>(nullptr));
}

TEST(Errors, AFailedDirectiveThrowsAndAFailedQueryTooAndTheRawCallDoesNot)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Armor armor("me", transport);
  transport->answer.success = false;
  transport->answer.exit_code = 206;
  EXPECT_THROW(armor.reference("nope").instances("Room"), armor::UnknownReferenceError);
  EXPECT_THROW(armor.reference("nope").add_individual("a"), armor::ServiceInternalError);
  EXPECT_EQ(armor.call("nope", "QUERY", "IND", "CLASS", {"Room"}).exit_code, 206);
}

TEST(Answers, EntitiesAreShortNamesOrIrisAndLiteralsAreTyped)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Armor armor("me", transport);
  transport->answer.queried_objects = {"<http://x.org/o#kitchen>", "<http://x.org/o/bedroom>"};
  EXPECT_EQ(armor.reference("r").instances("Room"),
    (std::vector<std::string>{"kitchen", "bedroom"}));
  EXPECT_EQ(armor.reference("r", true).instances("Room"),
    (std::vector<std::string>{"http://x.org/o#kitchen", "http://x.org/o/bedroom"}));
  transport->answer.queried_objects = {"\"80\"^^xsd:integer", "\"0.5\"^^xsd:double",
    "\"true\"^^xsd:boolean", "\"hi\"@en", "<http://x.org/o#kitchen>"};
  EXPECT_EQ(armor.reference("r").data_values("p", "i"),
    (std::vector<armor::Value>{80, 0.5, true, "hi", "kitchen"}));
  transport->answer.queried_objects = {"<http://x.org/o#contains> some <http://x.org/o#Agent>"};
  EXPECT_EQ(armor.reference("r").restrictions("C"),
    (std::vector<std::string>{"contains some Agent"}));
}

TEST(Answers, SparqlRowsAreSplitAtEmptyKeysAndCellsDecoded)
{
  auto transport = std::make_shared<RecordingTransport>();
  armor::Armor armor("me", transport);
  auto item = [](const std::string & key, const std::string & value) {
      armor_msgs::msg::QueryItem made;
      made.key = key;
      made.value = value;
      return made;
    };
  transport->answer.sparql_queried_objects = {item("who", "<http://x.org/o#alice>"),
    item("level", "\"80\"^^xsd:integer"), item("", ""), item("who", "_:b0"), item("level", "")};
  transport->answer.timeout = true;
  armor::SparqlRows rows = armor.reference("r").sparql("SELECT ...", 10);
  ASSERT_EQ(rows.size(), 2u);
  EXPECT_EQ(rows[0].at("who"), armor::Value("alice"));
  EXPECT_EQ(rows[0].at("level"), armor::Value(80));
  EXPECT_EQ(rows[1].at("who"), armor::Value("_:b0"));
  EXPECT_EQ(rows[1].at("level"), std::nullopt);
  EXPECT_TRUE(rows.timed_out);
  EXPECT_EQ(transport->sent.back().args, (std::vector<std::string>{"SELECT ...", "10"}));
}

TEST(Values, LiteralsSplitAndConvertAsThePythonClientDoes)
{
  EXPECT_EQ(armor::literal_value("\"80\"^^xsd:integer"), armor::Value(80));
  EXPECT_EQ(armor::literal_value("\"+7\"^^xsd:long"), armor::Value(7));
  EXPECT_EQ(armor::literal_value("\"-INF\"^^xsd:double"),
    armor::Value(-std::numeric_limits<double>::infinity()));
  EXPECT_TRUE(std::isnan(armor::literal_value("\"NaN\"^^xsd:float").as<double>()));
  EXPECT_EQ(armor::literal_value("\"1\"^^xsd:boolean"), armor::Value(true));
  EXPECT_EQ(armor::literal_value("\"2024-01-01\"^^xsd:date"), armor::Value("2024-01-01"));
  EXPECT_EQ(armor::literal_value(
      "\"3\"^^<http://www.w3.org/2001/XMLSchema#integer>"), armor::Value(3));
  armor::Literal quoted = armor::split_literal("\"say \"hi\"\"^^xsd:string");
  EXPECT_EQ(quoted.lexical, "say \"hi\"");
  EXPECT_EQ(quoted.datatype, "xsd:string");
  EXPECT_EQ(armor::split_literal("\"hi\"@en").datatype, "rdf:langString");
  EXPECT_THROW(armor::split_literal("kitchen"), std::invalid_argument);
  EXPECT_THROW(armor::literal_value("\"maybe\"^^xsd:boolean"), std::invalid_argument);
  EXPECT_THROW(armor::literal_value("\"8x\"^^xsd:integer"), std::invalid_argument);
  EXPECT_EQ(armor::short_name("<http://x.org/o#Robot>"), "Robot");
  EXPECT_EQ(armor::short_name("Robot"), "Robot");
  EXPECT_EQ(armor::entity_iri("<http://x.org/o#Robot>"), "http://x.org/o#Robot");
}

TEST(Values, ValuesPickTheirArmorTypeAndLexicalForm)
{
  using Pair = std::pair<std::string, std::string>;
  EXPECT_EQ(armor::typed_argument(true), (Pair{"BOOLEAN", "true"}));
  EXPECT_EQ(armor::typed_argument(80), (Pair{"INTEGER", "80"}));
  EXPECT_EQ(armor::typed_argument(1700000000000LL, "LONG"), (Pair{"LONG", "1700000000000"}));
  EXPECT_EQ(armor::typed_argument(2.0), (Pair{"DOUBLE", "2.0"}));
  EXPECT_EQ(armor::typed_argument(0.1), (Pair{"DOUBLE", "0.1"}));
  EXPECT_EQ(armor::typed_argument("text"), (Pair{"STRING", "text"}));
  EXPECT_THROW(armor::typed_argument(std::nan("")), std::invalid_argument);
}

}  // namespace

TEST(Explanations, LinesAreGroupedByTheirJustificationNumber)
{
  auto transport = std::make_shared<RecordingTransport>();
  transport->answer.queried_objects = {"1 asserted robot1 Type Robot", "1 axiom Robot SubClassOf Agent",
    "2 asserted robot1 isIn kitchen", "2 axiom isIn Domain Agent"};
  armor::Armor armor("me", transport);
  armor::Justifications found = armor.reference("ref").explain_instance("robot1", "Agent", 2);
  ASSERT_EQ(found.size(), 2u);
  EXPECT_EQ(found[0], (std::vector<std::string>{"asserted robot1 Type Robot", "axiom Robot SubClassOf Agent"}));
  EXPECT_EQ(found[1], (std::vector<std::string>{"asserted robot1 isIn kitchen", "axiom isIn Domain Agent"}));
  EXPECT_EQ(transport->sent.back().args, (std::vector<std::string>{"robot1", "Agent", "2"}));
}
