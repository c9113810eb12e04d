// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
#include "armor_cpp/armor.hpp"

#include <unistd.h>

#include <filesystem>
#include <regex>
#include <string>
#include <utility>
#include <vector>

#include "armor_cpp/rcl_transport.hpp"

namespace armor
{
namespace
{

using armor_msgs::msg::ArmorDirectiveRes;

std::string word(std::string_view text) {return std::string(text);}

std::string flag(bool value) {return value ? "true" : "false";}

// The arguments of CREATE, which are also the last four of LOAD FILE and LOAD WEB.
std::vector<std::string> reasoning_args(const std::string & iri, const ReasonerOptions & options)
{
  return {iri, flag(options.buffered_manipulation), options.reasoner,
    flag(options.buffered_reasoner)};
}

std::vector<std::string> load_args(
  const std::string & source, const std::string & iri, const ReasonerOptions & options)
{
  std::vector<std::string> args{source};
  for (std::string & arg : reasoning_args(iri, options)) {
    args.push_back(std::move(arg));
  }
  return args;
}

std::vector<std::string> with_timeout(const std::string & query, std::optional<int> timeout_ms)
{
  if (!timeout_ms) {
    return {query};
  }
  return {query, std::to_string(*timeout_ms)};
}

// One SPARQL cell: empty when unbound, a bool for true/false (ASK), a blank node as is, else
// a literal's value or an entity's name.
std::optional<Value> sparql_cell(const std::string & text, bool iris)
{
  if (text.empty()) {
    return std::nullopt;
  }
  if (text == "true" || text == "false") {
    return Value(text == "true");
  }
  if (text.rfind("_:", 0) == 0) {
    return Value(text);
  }
  return answer_value(text, iris);
}

}  // namespace

// The node refuses relative paths: a relative one is the caller's, joined to this process's
// working directory.
std::string path_argument(const std::string & path)
{
  if (path.empty() || path.find('\n') != std::string::npos || path.rfind('{', 0) == 0 ||
    std::filesystem::path(path).is_absolute())
  {
    return path;
  }
  return (std::filesystem::current_path() / path).string();
}

// ---------------------------------------------------------------- Armor

struct Armor::Session
{
  std::string client_name;
  Options options;
  std::shared_ptr<Transport> transport;
};

Armor::Armor(const std::string & client_name, const Options & options)
: Armor(client_name, std::make_shared<RclTransport>(
      RclTransportOptions{options.ns, options.service_wait, ""}), options) {}

Armor::Armor(
  const std::string & client_name, std::shared_ptr<Transport> transport, const Options & options)
: session_(std::make_shared<const Session>(Session{
      client_name.empty() ? "armor_cpp_" + std::to_string(getpid()) : client_name, options,
      std::move(transport)})) {}

const std::string & Armor::client_name() const {return session_->client_name;}

const Options & Armor::options() const {return session_->options;}

Reference Armor::reference(const std::string & name) const
{
  return Reference(*this, name, session_->options.iris);
}

Reference Armor::reference(const std::string & name, bool iris) const
{
  return Reference(*this, name, iris);
}

ArmorDirectiveRes Armor::call(
  const std::string & reference, const std::string & command, const std::string & primary,
  const std::string & secondary, const std::vector<std::string> & args) const
{
  return session_->transport->call(
    directive(session_->client_name, reference, command, primary, secondary, args),
    session_->options.timeout);
}

armor_msgs::srv::ArmorDirectiveList::Response Armor::call_list(
  const std::vector<armor_msgs::msg::ArmorDirectiveReq> & requests) const
{
  return session_->transport->call_list(requests, session_->options.timeout);
}

ArmorDirectiveRes Armor::execute(
  const std::string & reference, const contract::Command & command,
  const std::vector<std::string> & args) const
{
  ArmorDirectiveRes response = call(
    reference, word(command.command), word(command.primary), word(command.secondary), args);
  if (!response.success) {
    throw_error_for(response);
  }
  return response;
}

Reference Armor::load_file(
  const std::string & name, const std::string & path, const std::string & iri,
  const LoadOptions & options) const
{
  Reference loaded = reference(name);
  loaded.consistent_from(execute(name,
    options.mount ? contract::LOAD_FILE_MOUNTED : contract::LOAD_FILE,
    load_args(path_argument(path), iri, options)));
  return loaded;
}

Reference Armor::load_web(
  const std::string & name, const std::string & url, const std::string & iri,
  const LoadOptions & options) const
{
  Reference loaded = reference(name);
  loaded.consistent_from(execute(name,
    options.mount ? contract::LOAD_WEB_MOUNTED : contract::LOAD_WEB,
    load_args(url, iri, options)));
  return loaded;
}

Reference Armor::create(
  const std::string & name, const std::string & iri, const ReasonerOptions & options) const
{
  Reference created = reference(name);
  created.consistent_from(execute(name, contract::CREATE, reasoning_args(iri, options)));
  return created;
}

std::vector<std::string> Armor::references() const
{
  return execute("", contract::GET_ALL_REFS, {}).queried_objects;
}

std::vector<std::string> Armor::load_progress() const
{
  return execute("", contract::GET_LOAD_PROGRESS, {}).queried_objects;
}

std::string Armor::catalogue() const
{
  auto texts = execute("", contract::GET_CATALOGUE, {}).queried_objects;
  return texts.empty() ? std::string() : texts.front();
}

std::optional<std::string> Armor::mounted_by(const std::string & reference) const
{
  auto holders = execute("", contract::GET_REF_CLIENT, {reference}).queried_objects;
  if (holders.empty()) {
    return std::nullopt;
  }
  return holders.front();
}

std::uint64_t Armor::revision(const std::string & reference) const
{
  auto answer = execute("", contract::GET_REF_REVISION, {reference}).queried_objects;
  return answer.empty() ? 0 : std::stoull(answer.front());
}

std::string Armor::digest(const std::string & reference) const
{
  auto answer = execute("", contract::GET_REF_DIGEST, {reference}).queried_objects;
  return answer.empty() ? "" : answer.front();
}

std::vector<std::string> Armor::state_damage() const
{
  return execute("", contract::GET_STATE_DAMAGE, {}).queried_objects;
}

std::vector<std::string> Armor::changes_since(
  const std::string & reference, std::int64_t revision, const std::string & client) const
{
  std::vector<std::string> args{reference, std::to_string(revision)};
  if (!client.empty()) {
    args.push_back(client);
  }
  return execute("", contract::GET_REF_CHANGES, args).queried_objects;
}

void Armor::log_to_screen(bool on) const
{
  execute("", on ? contract::LOG_SCREEN_ON : contract::LOG_SCREEN_OFF, {});
}

void Armor::log_to_file(const std::optional<std::string> & path) const
{
  if (path) {
    execute("", contract::LOG_FILE_ON, {path_argument(*path)});
  } else {
    execute("", contract::LOG_FILE_OFF, {});
  }
}

// ---------------------------------------------------------------- Reference

struct Reference::State
{
  std::string name;
  bool iris;
  std::optional<bool> consistent;
};

Reference::Reference(Armor armor, const std::string & name, bool iris)
: armor_(std::move(armor)), state_(std::make_shared<State>(State{name, iris, std::nullopt})) {}

const std::string & Reference::name() const {return state_->name;}

const Armor & Reference::armor() const {return armor_;}

std::optional<bool> Reference::consistent() const {return state_->consistent;}

void Reference::consistent_from(const ArmorDirectiveRes & response) const
{
  state_->consistent = response.is_consistent;
}

ArmorDirectiveRes Reference::answer(
  const contract::Command & command, const std::vector<std::string> & args) const
{
  ArmorDirectiveRes response = armor_.execute(state_->name, command, args);
  consistent_from(response);
  return response;
}

void Reference::send_change(
  const contract::Command & command, const std::vector<std::string> & args)
{
  answer(command, args);
}

std::vector<std::string> Reference::entities(
  const contract::Command & command, const std::vector<std::string> & args) const
{
  std::vector<std::string> names;
  for (const std::string & entity : answer(command, args).queried_objects) {
    names.push_back(state_->iris ? entity_iri(entity) : short_name(entity));
  }
  return names;
}

std::vector<std::string> Reference::classes_of(
  const std::string & individual, bool most_specific) const
{
  if (most_specific) {
    return entities(contract::QUERY_CLASS_IND, {individual, "true"});
  }
  return entities(contract::QUERY_CLASS_IND, {individual});
}

std::vector<Value> Reference::values(
  const contract::Command & command, const std::vector<std::string> & args) const
{
  std::vector<Value> values;
  for (const std::string & text : answer(command, args).queried_objects) {
    values.push_back(answer_value(text, state_->iris));
  }
  return values;
}

namespace
{
// EXPLAIN's lines "<n> <kind> <axiom>" grouped by n, in the order answered.
Justifications grouped(const std::vector<std::string> & lines)
{
  Justifications found;
  std::vector<std::string> numbers;
  for (const std::string & line : lines) {
    auto space = line.find(' ');
    std::string number = line.substr(0, space);
    std::string rest = space == std::string::npos ? "" : line.substr(space + 1);
    if (numbers.empty() || numbers.back() != number) {
      numbers.push_back(number);
      found.emplace_back();
    }
    found.back().push_back(rest);
  }
  return found;
}
}  // namespace

Justifications Reference::explain_instance(
  const std::string & individual, const std::string & cls, int justifications) const
{
  return grouped(answer(contract::EXPLAIN_IND_CLASS,
    {individual, cls, std::to_string(justifications)}).queried_objects);
}

Justifications Reference::explain_object_property(
  const std::string & prop, const std::string & subject, const std::string & object,
  int justifications) const
{
  return grouped(answer(contract::EXPLAIN_OBJECTPROP_IND,
    {prop, subject, object, std::to_string(justifications)}).queried_objects);
}

Justifications Reference::explain_data_property(
  const std::string & prop, const std::string & individual, const std::string & type,
  const std::string & value, int justifications) const
{
  return grouped(answer(contract::EXPLAIN_DATAPROP_IND,
    {prop, individual, type, value, std::to_string(justifications)}).queried_objects);
}

Justifications Reference::explain_subclass(
  const std::string & sub, const std::string & super, int justifications) const
{
  return grouped(answer(contract::EXPLAIN_CLASS_CLASS,
    {sub, super, std::to_string(justifications)}).queried_objects);
}

Justifications Reference::explain_inconsistency(int justifications) const
{
  return grouped(answer(contract::EXPLAIN_INCONSISTENCY,
    {std::to_string(justifications)}).queried_objects);
}

std::vector<std::string> Reference::expressions(
  const contract::Command & command, const std::vector<std::string> & args) const
{
  std::vector<std::string> texts = answer(command, args).queried_objects;
  if (state_->iris) {
    return texts;
  }
  // Manchester text with each bracketed IRI written as its short name.
  static const std::regex bracketed_iri("<([^<>\\s]+)>");
  for (std::string & text : texts) {
    std::string shortened;
    auto last = text.cbegin();
    for (std::sregex_iterator match(text.cbegin(), text.cend(), bracketed_iri), end;
      match != end; ++match)
    {
      shortened.append(last, (*match)[0].first);
      shortened += short_name((*match)[1].str());
      last = (*match)[0].second;
    }
    shortened.append(last, text.cend());
    text = shortened;
  }
  return texts;
}

SparqlRows Reference::sparql(const std::string & query, std::optional<int> timeout_ms) const
{
  ArmorDirectiveRes response = answer(contract::QUERY_SPARQL_FORMATTED,
      with_timeout(query, timeout_ms));
  // Items with an empty key separate the rows.
  SparqlRows rows;
  SparqlRow row;
  for (const auto & item : response.sparql_queried_objects) {
    if (item.key.empty()) {
      rows.push_back(std::move(row));
      row = SparqlRow();
    } else {
      row[item.key] = sparql_cell(item.value, state_->iris);
    }
  }
  if (!row.empty()) {
    rows.push_back(std::move(row));
  }
  rows.timed_out = response.timeout;
  return rows;
}

SparqlLines Reference::sparql_lines(
  const std::string & query, std::optional<int> timeout_ms) const
{
  ArmorDirectiveRes response = answer(contract::QUERY_SPARQL, with_timeout(query, timeout_ms));
  SparqlLines lines;
  lines.assign(response.queried_objects.begin(), response.queried_objects.end());
  lines.timed_out = response.timeout;
  return lines;
}

bool Reference::ask(const std::string & query) const
{
  SparqlRows rows = sparql(query);
  if (rows.empty() || !rows.front().count("ASK") || !rows.front().at("ASK") ||
    !rows.front().at("ASK")->is<bool>())
  {
    throw std::invalid_argument("not an ASK query: " + query);
  }
  return rows.front().at("ASK")->as<bool>();
}

Consistency Reference::check_consistency() const
{
  ArmorDirectiveRes response = answer(contract::QUERY_CONSISTENCY, {});
  return Consistency{response.is_consistent, response.queried_objects};
}

void Reference::save(const std::string & path, const std::string & format, bool inferences) const
{
  std::vector<std::string> args;
  if (!format.empty()) {
    args = {path_argument(path), format};
  } else if (!path.empty()) {
    args = {path_argument(path)};
  }
  answer(inferences ? contract::SAVE_INFERENCE : contract::SAVE, args);
}

void Reference::drop() const {answer(contract::DROP, {});}

void Reference::mount() const {answer(contract::MOUNT, {});}

void Reference::unmount() const {answer(contract::UNMOUNT, {});}

std::optional<std::string> Reference::mounted_by() const {return armor_.mounted_by(name());}

std::uint64_t Reference::revision() const {return armor_.revision(name());}

std::vector<std::string> Reference::changes_since(
  std::int64_t revision, const std::string & client) const
{
  return armor_.changes_since(name(), revision, client);
}

Mount Reference::mounted() const {return Mount(*this);}

Batch Reference::batch() const {return Batch(armor_, name());}

// ---------------------------------------------------------------- Mount

Mount::Mount(const Reference & reference)
: reference_(std::make_unique<Reference>(reference))
{
  reference_->mount();
}

Mount::Mount(Mount && other) noexcept
: reference_(std::move(other.reference_)) {}

Mount::~Mount()
{
  if (!reference_) {
    return;
  }
  try {
    reference_->unmount();
  } catch (const Error &) {
    // Lost already (lease, DROP) or unreachable: nothing a destructor could do about it.
  }
}

void Mount::release()
{
  std::unique_ptr<Reference> reference = std::move(reference_);
  if (reference) {
    reference->unmount();
  }
}

// ---------------------------------------------------------------- Batch

Batch::Batch(Armor armor, std::string reference)
: armor_(std::move(armor)), reference_(std::move(reference)) {}

Batch & Batch::send_change(
  const contract::Command & command, const std::vector<std::string> & args)
{
  requests_.push_back(directive(armor_.client_name(), reference_, word(command.command),
    word(command.primary), word(command.secondary), args));
  return *this;
}

bool Batch::send()
{
  auto answer = armor_.call_list(requests_);
  if (!answer.success) {
    throw_list_error(answer.armor_responses);
  }
  requests_.clear();
  consistent_ = answer.is_consistent;
  return answer.is_consistent;
}

}  // namespace armor
