// Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
//
// The C++ client of ARMOR for ROS 2: one Armor session, one Reference object per ontology.
//
//   armor::Armor armor("planner");
//   armor::Reference robotics = armor.reference("robotics");
//   robotics.replace_object_value("isIn", "alice", "bedroom", "corridor1");
//   for (const std::string & room : robotics.instances("OccupiedRoom")) { ... }
//
// The same methods, names and answers as the Python client's Armor and Reference
// (armor_client): manipulations return nothing, queries return std::vector<std::string> (short
// names, or IRIs with iris) or typed Values, a failed directive throws the ServiceInternalError
// subclass of its exit code. `auto mount = ref.mounted();` holds the mount until the guard goes
// out of scope; `ref.batch()` collects changes sent as one atomic list.
#ifndef ARMOR_CPP__ARMOR_HPP_
#define ARMOR_CPP__ARMOR_HPP_

#include <chrono>
#include <cstdint>
#include <map>
#include <memory>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "armor_cpp/contract.hpp"
#include "armor_cpp/errors.hpp"
#include "armor_cpp/manipulations.hpp"
#include "armor_cpp/transport.hpp"
#include "armor_cpp/values.hpp"

namespace armor
{

class Reference;

// The justifications of one fact: each a list of "<kind> <axiom>" lines.
using Justifications = std::vector<std::vector<std::string>>;
class Batch;

// The reasoners every node has; any OWLReasonerFactory class name works too.
namespace reasoner
{
inline constexpr const char * HERMIT = "HERMIT";
inline constexpr const char * PELLET = "PELLET";
inline constexpr const char * JFACT = "JFACT";
inline constexpr const char * ELK = "ELK";
}  // namespace reasoner

struct Options
{
  // Namespace of the ARMOR node ('' for the default).
  std::string ns;
  // Longest wait for each answer; empty: as long as it takes.
  Timeout timeout{std::chrono::seconds(60)};
  // How long the first call waits for the service to appear and answer.
  std::chrono::milliseconds service_wait{std::chrono::seconds(30)};
  // Answer entities as full IRIs instead of short names.
  bool iris = false;
};

// How a new reference reasons and buffers (the last arguments of LOAD and CREATE).
struct ReasonerOptions
{
  // HERMIT, PELLET, JFACT, ELK or '' for the node's default.
  std::string reasoner;
  // Queue changes until apply() or reason().
  bool buffered_manipulation = false;
  // The reasoner sees changes only at reason().
  bool buffered_reasoner = false;
};

struct LoadOptions : ReasonerOptions
{
  // Also mount this client on the new reference (LOAD ... MOUNTED).
  bool mount = false;
};

// The answer of QUERY CONSISTENCY: true in a boolean context when consistent.
struct Consistency
{
  bool consistent = true;
  // When inconsistent: the axioms that cause it (Manchester syntax).
  std::vector<std::string> explanation;
  explicit operator bool() const {return consistent;}
};

// One SPARQL answer row: variable -> value (empty when unbound).
using SparqlRow = std::map<std::string, std::optional<Value>>;

// SPARQL rows; timed_out says the query's time limit cut the answer short.
struct SparqlRows : std::vector<SparqlRow>
{
  bool timed_out = false;
};

// ARMOR's text rows of an unformatted SPARQL answer.
struct SparqlLines : std::vector<std::string>
{
  bool timed_out = false;
};

// A connection to one ARMOR node, speaking as one client. Copies share the connection.
class Armor
{
public:
  // Connects through rcl (RclTransport). `client_name` is the name this program uses in
  // directives (the mount holder's name); '' picks `armor_cpp_<pid>`.
  explicit Armor(const std::string & client_name = "", const Options & options = {});
  // Speaks through a transport of the caller's (RclcppTransport, or a test's); options.ns and
  // options.service_wait belong to the transport then and are not used.
  Armor(
    const std::string & client_name, std::shared_ptr<Transport> transport,
    const Options & options = {});

  const std::string & client_name() const;
  const Options & options() const;

  // The object for a reference that is loaded (or will be); nothing is sent.
  Reference reference(const std::string & name) const;
  Reference reference(const std::string & name, bool iris) const;

  // Load an ontology file on the node's machine as a new reference (LOAD FILE [MOUNTED]); a
  // relative path is this process's, sent made absolute (as every path argument here).
  // Loading a name loaded from the same file reuses it. Throws FileError, ReasonerError.
  Reference load_file(
    const std::string & name, const std::string & path, const std::string & iri = "",
    const LoadOptions & options = {}) const;
  // Load an ontology from a URL (LOAD WEB [MOUNTED]); the node must run with web_loading.
  Reference load_web(
    const std::string & name, const std::string & url, const std::string & iri = "",
    const LoadOptions & options = {}) const;
  // Create a reference holding a new, empty ontology (CREATE).
  Reference create(
    const std::string & name, const std::string & iri, const ReasonerOptions & options = {}) const;

  // The names of the loaded references (GET ALL REFS).
  std::vector<std::string> references() const;
  // The LOADs in flight, one line each (GET LOAD PROGRESS).
  std::vector<std::string> load_progress() const;
  // What the running node answers, as the core's catalogue JSON (GET CATALOGUE).
  std::string catalogue() const;
  // The client that holds a reference's mount, or empty (GET REF CLIENT).
  std::optional<std::string> mounted_by(const std::string & reference) const;
  // How many changes a reference has acknowledged (GET REF REVISION).
  std::uint64_t revision(const std::string & reference) const;
  // A reference's acknowledged changes after a revision, oldest first, one JSON object each:
  // {"revision": N, "directives": [{"client_name", "command", ..., "args"}]} (GET REF CHANGES).
  // How a client whose answer was lost learns whether its change was applied; -1: all kept;
  // a client name keeps only the changes with a directive of that client.
  std::vector<std::string> changes_since(
    const std::string & reference, std::int64_t revision = -1,
    const std::string & client = "") const;
  // A SHA-256 of a reference's asserted axioms, annotations and imports (GET REF DIGEST):
  // equal digests, equal ontologies.
  std::string digest(const std::string & reference) const;
  // What the state directory could not restore or cannot keep now, one JSON object each
  // (GET STATE DAMAGE; docs/durability.md); empty when nothing.
  std::vector<std::string> state_damage() const;
  // Turn the node's logging of directives to its screen on or off (LOG SCREEN ON/OFF).
  void log_to_screen(bool on) const;
  // Log directives to a file on the node's machine; empty stops it (LOG FILE ON/OFF).
  void log_to_file(const std::optional<std::string> & path) const;

  // Send any directive as this client; the raw response, also when it failed.
  armor_msgs::msg::ArmorDirectiveRes call(
    const std::string & reference, const std::string & command, const std::string & primary = "",
    const std::string & secondary = "", const std::vector<std::string> & args = {}) const;
  // Send an atomic list of directives; the raw list response.
  armor_msgs::srv::ArmorDirectiveList::Response call_list(
    const std::vector<armor_msgs::msg::ArmorDirectiveReq> & requests) const;

  // The raw response of a catalogue command with these arguments, or its error thrown.
  armor_msgs::msg::ArmorDirectiveRes execute(
    const std::string & reference, const contract::Command & command,
    const std::vector<std::string> & args) const;

private:
  struct Session;
  std::shared_ptr<const Session> session_;
};

// Holds a reference's mount while it lives (RAII): mounts when made, unmounts when destroyed.
// The destructor does not throw: a mount already lost (lease, DROP) is let go silently; call
// release() to unmount early and see its errors.
class [[nodiscard]] Mount
{
public:
  explicit Mount(const Reference & reference);
  ~Mount();
  Mount(Mount && other) noexcept;
  Mount & operator=(Mount &&) = delete;
  Mount(const Mount &) = delete;
  Mount & operator=(const Mount &) = delete;

  // Unmount now (UNMOUNT); throws MountError when this client does not hold the mount.
  void release();

private:
  std::unique_ptr<Reference> reference_;
};

// One loaded ontology: every command of the contract as a method. Copies share the state.
class Reference : public Manipulations<Reference>, public QueryFaces<Reference>
{
public:
  Reference(Armor armor, const std::string & name, bool iris);

  const std::string & name() const;
  const Armor & armor() const;
  // The consistency ARMOR reported with the last answer to this reference (empty before one).
  std::optional<bool> consistent() const;

  // Queries (never refused because of a mount; answers sorted by the service): those with a
  // face in the core's catalogue are generated (faces.hpp, QueryFaces), these are composites.

  // The classes of an individual (QUERY CLASS IND), only the most specific on request.
  std::vector<std::string> classes_of(
    const std::string & individual, bool most_specific = false) const;
  // A SPARQL SELECT or ASK over asserted and inferred knowledge (QUERY SPARQL FORMATTED);
  // an ASK answers one row {"ASK": true/false}.
  SparqlRows sparql(
    const std::string & query, std::optional<int> timeout_ms = std::nullopt) const;
  // A SPARQL query answered as ARMOR's text rows (QUERY SPARQL).
  SparqlLines sparql_lines(
    const std::string & query, std::optional<int> timeout_ms = std::nullopt) const;
  // A SPARQL ASK query as a bool.
  bool ask(const std::string & query) const;
  // Whether the ontology is consistent, and why not (QUERY CONSISTENCY).
  Consistency check_consistency() const;

  // Why a fact holds (docs/explanations.md): up to `justifications` minimal sets of axioms
  // that entail it, each a list of lines "<kind> <axiom>" (kind: asserted, axiom or rule);
  // a fact that does not hold is an ArmorError with code 227.
  Justifications explain_instance(
    const std::string & individual, const std::string & cls, int justifications = 1) const;
  Justifications explain_object_property(
    const std::string & prop, const std::string & subject, const std::string & object,
    int justifications = 1) const;
  Justifications explain_data_property(
    const std::string & prop, const std::string & individual, const std::string & type,
    const std::string & value, int justifications = 1) const;
  Justifications explain_subclass(
    const std::string & sub, const std::string & super, int justifications = 1) const;
  Justifications explain_inconsistency(int justifications = 1) const;

  // The reference itself (never refused because of a mount)

  // Write the ontology to a file on the node's machine (SAVE / SAVE INFERENCE): path ''
  // = the file it was loaded from; format rdfxml, owlxml, turtle, functional, manchester.
  void save(
    const std::string & path = "", const std::string & format = "",
    bool inferences = false) const;
  // Unload the reference (DROP).
  void drop() const;
  // Become the only client allowed to change it (MOUNT); MountError when another holds it.
  void mount() const;
  // Release the mount (UNMOUNT); MountError when this client does not hold it.
  void unmount() const;
  // The client that holds this reference's mount, or empty (GET REF CLIENT).
  std::optional<std::string> mounted_by() const;
  // How many changes this reference has acknowledged (GET REF REVISION).
  std::uint64_t revision() const;
  // Its acknowledged changes after a revision (GET REF CHANGES); see Armor::changes_since.
  std::vector<std::string> changes_since(
    std::int64_t revision = -1, const std::string & client = "") const;
  // Hold the mount until the returned guard is destroyed.
  Mount mounted() const;
  // A builder for changes sent together as one atomic list.
  Batch batch() const;

protected:
  // What generated methods call: the core's (faces.hpp) and plugins' (tools/faces.py
  // --cpp-plugins, whose Reference derives from this one).
  void send_change(const contract::Command & command, const std::vector<std::string> & args);
  // The answer shapes of the generated queries.
  std::vector<std::string> entities(
    const contract::Command & command, const std::vector<std::string> & args) const;
  std::vector<Value> values(
    const contract::Command & command, const std::vector<std::string> & args) const;
  std::vector<std::string> expressions(
    const contract::Command & command, const std::vector<std::string> & args) const;

private:
  friend class Changes<Reference>;
  friend class QueryFaces<Reference>;
  friend class Armor;
  void consistent_from(const armor_msgs::msg::ArmorDirectiveRes & response) const;
  armor_msgs::msg::ArmorDirectiveRes answer(
    const contract::Command & command, const std::vector<std::string> & args) const;

  struct State;
  Armor armor_;
  std::shared_ptr<State> state_;
};

// Manipulations of one reference, sent together as one atomic list: every manipulation
// method of Reference, each queueing its directive (and returning the batch, so calls chain).
// send() sends the list: all the changes happen, or none.
class Batch : public Manipulations<Batch>
{
public:
  Batch(Armor armor, std::string reference);

  // How many directives are queued.
  std::size_t size() const {return requests_.size();}
  const std::vector<armor_msgs::msg::ArmorDirectiveReq> & requests() const {return requests_;}
  // The consistency after the last list sent.
  std::optional<bool> consistent() const {return consistent_;}

  // Send the queued directives as one atomic list and empty the queue; the consistency after
  // it. When a directive fails nothing changed: throws the failing directive's error, with
  // index() and responses() set.
  bool send();

protected:
  Batch & send_change(const contract::Command & command, const std::vector<std::string> & args);

private:
  friend class Changes<Batch>;

  Armor armor_;
  std::string reference_;
  std::vector<armor_msgs::msg::ArmorDirectiveReq> requests_;
  std::optional<bool> consistent_;
};

// A path argument as every method here sends it (docs/commands.md#paths): a relative path is
// this process's, made absolute; '' and text given instead of a file (holding a line break or
// starting with '{', as a PDDL mapping) are sent as they are.
std::string path_argument(const std::string & path);

// Fill a batch and send it as one atomic list, unless `fill` throws (then nothing is sent):
// the Python client's `with ref.batch() as batch:`. The consistency after the list; empty
// when `fill` queued nothing (then nothing is sent either).
template<typename Fill>
std::optional<bool> atomically(const Reference & reference, Fill && fill)
{
  Batch batch = reference.batch();
  std::forward<Fill>(fill)(batch);
  if (batch.size() == 0) {
    return std::nullopt;
  }
  return batch.send();
}

}  // namespace armor

#endif  // ARMOR_CPP__ARMOR_HPP_
