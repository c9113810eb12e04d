# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Grammar-aware fuzzing over ROS 2: every directive answered with a defined code, none lost.

    python tests/integration/fuzz.py --directives 1000000 [--clients 4] [--seconds S] [--epoch N]

Directives are built from the core's catalogue (every command, its argument names): valid ones
(names of the ontology, values of the right type), almost valid ones (one thing wrong: an
argument more or less, a value of the wrong type, a misspelt word, an unknown name) and hostile
ones (huge or control-character strings, unicode, path traversal, shell and SPARQL injection,
IRIs holding < or >). They go to a reference loaded from robotics.owl; after every rejected
directive its state (GET REF DIGEST, revision, mount holder) must be what it was. Every
directive acknowledged there is replayed on a shadow copy; at the end both are saved and must
hold the same axioms. Commands acting on whole references go to a sacrificial one. Several
clients fuzz at once (--clients), each with a target, shadow and sacrificial reference of its
own: the core serialises each reference, so a client's state checks see only its own changes,
and the node's round trips overlap instead of adding up.
"""

import argparse
import json
import pathlib
import random
import sys
import tempfile
import threading
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

from conftest import ONTOLOGIES, start_node  # noqa: E402

WHOLE_REFERENCE_KINDS = {'creating', 'dropping', 'mounting', 'reference', 'global'}
NS = 'http://www.example.org/robotics#'
INDIVIDUALS = ['robot1', 'kitchen', 'bedroom', 'alice', 'corridor1']
CLASSES = ['Robot', 'Room', 'Agent', 'Location', 'OccupiedRoom', 'Person', 'Corridor']
OBJECT_PROPS = ['isIn', 'contains', 'connectedTo']
DATA_PROPS = ['batteryLevel', 'visitedAt']
TYPES = ['INT', 'INTEGER', 'FLOAT', 'LONG', 'DOUBLE', 'BOOL', 'BOOLEAN', 'STRING',
         'xsd:dateTime', 'DECIMAL']
HOSTILE = [
    '', ' ', '\u0000', 'a\nb', '\r\n', '\t', '\x1b[31m', '\\', '"', "'", '%s%n', '{}', '[]',
    'x' * 100_000, 'é' * 5000, '机器人', '🤖', '\ud7ff', '﻿', '../../etc/passwd', '/etc/passwd',
    '~/.bashrc', '$(touch /tmp/armor-fuzz-pwned)', '`id`', '; rm -rf /', '<http://x/a>b>',
    '<http://x/a<b>', 'http://x/a>b', '<not an iri>', '<http://unbalanced', 'ex:Foo', ':::',
    'owl:Thing', 'owl:Nothing', '_:b0', 'Robot and and', 'isIn some (', 'not not not',
    'Room SubClassOf isIn exactly 1 Location', 'SubClassOf(:A :B)', 'ClassAssertion(',
    'Robot(?r) -> Room(?r)', 'Robot(?r), -> ', 'SELECT ?x WHERE { ?x a :Robot }',
    'SELECT * WHERE {', 'ASK { :kitchen a :Room }', 'DROP ALL', 'INSERT DATA { <a> <b> <c> }',
    'SELECT * WHERE { SERVICE <http://127.0.0.1:1/> { ?s ?p ?o } }',
    '<!DOCTYPE x [<!ENTITY e SYSTEM "file:///etc/passwd">]>', '-1', '0', '1e999', 'NaN',
    '99999999999999999999999', '-9223372036854775809', 'true', 'yes',
]


def load_catalogue():
    path = pathlib.Path(__file__).resolve().parents[2] / 'armor_contract' / 'armor_contract'
    return json.loads((path / 'catalogue.json').read_text())['commands']


class Grammar:
    """Directives from the catalogue: valid, almost valid or hostile, in that proportion."""

    def __init__(self, rng: random.Random, scratch: pathlib.Path, references=('target', 'sacrificial')):
        self.rng = rng
        self.scratch = scratch
        self.references = references
        self.commands = [c for c in load_catalogue() if c['words'][0]]

    def value_for(self, name: str) -> str:
        r = self.rng
        if name in ('ind', 'value ind', 'sub', 'super') and r.random() < 0.7:
            return r.choice(INDIVIDUALS if name != 'sub' and name != 'super' else CLASSES)
        if name in ('class', 'value class', 'sub', 'super'):
            return r.choice(CLASSES)
        if name in ('prop', 'object prop', 'inverse prop'):
            return r.choice(OBJECT_PROPS + DATA_PROPS)
        if name in ('type', 'datatype'):
            return r.choice(TYPES)
        if name in ('value', 'new value', 'old value', 'n', 'since revision'):
            return r.choice(['0', '1', '42', '3.5', 'true', '2024-01-01T00:00:00Z', 'text'])
        if name in ('new name', 'old name', 'rule name', 'client name'):
            return r.choice(INDIVIDUALS + CLASSES + [f'new{r.randrange(50)}'])
        if name == 'characteristic':
            return r.choice(['TRANSITIVE', 'SYMMETRIC', 'FUNCTIONAL', 'REFLEXIVE', 'NONE'])
        if name == 'class expression':
            return r.choice(['Robot and (isIn some Room)', 'Room', 'isIn some Location',
                             'Robot or Person', 'not Room'])
        if name == 'query':
            return r.choice(['SELECT ?x WHERE { ?x a <http://www.example.org/robotics#Robot> }',
                             'ASK { ?s ?p ?o }'])
        if name == 'axiom':
            return r.choice([f'ClassAssertion(<{NS}Robot> <{NS}new{r.randrange(50)}>)',
                             f'SubClassOf(<{NS}Robot> <{NS}Agent>)'])
        if name == 'rule':
            return 'Robot(?r) ^ isIn(?r, ?x) -> Agent(?r)'
        if name in ('path',):
            return str(self.scratch / r.choice(['out.owl', 'sub/out.ttl', 'robotics.owl']))
        if name == 'format':
            return r.choice(['', 'functional', 'turtle', 'rdfxml', 'owlxml', 'bogus'])
        if name == 'reasoner':
            return r.choice(['HERMIT', 'PELLET', 'ELK', 'JFACT', 'NONE'])
        if name in ('buffered manipulation', 'buffered reasoner', 'most specific only'):
            return r.choice(['true', 'false'])
        if name in ('ontology IRI', 'URL'):
            return r.choice(['', 'http://www.example.org/robotics', 'http://127.0.0.1:1/x.owl'])
        if name == 'reference name':
            return r.choice([*self.references, 'nothere'])
        return r.choice(INDIVIDUALS)

    def valid(self):
        command = self.rng.choice(self.commands)
        args = [self.value_for(n) for n in command['args']['required']]
        args += [self.value_for(n) for n in command['args']['optional'] if self.rng.random() < 0.5]
        return command, list(command['words']), args

    def almost_valid(self):
        command, words, args = self.valid()
        r = self.rng
        mutation = r.randrange(6)
        if mutation == 0 and args:
            args.pop(r.randrange(len(args)))
        elif mutation == 1:
            args.insert(r.randrange(len(args) + 1), self.value_for('ind'))
        elif mutation == 2 and args:
            args[r.randrange(len(args))] = r.choice(TYPES + ['robot9', 'Robt', '1.5.5', 'maybe'])
        elif mutation == 3:
            i = r.randrange(3)
            words[i] = ''.join(c.lower() if r.random() < 0.5 else c for c in words[i])
        elif mutation == 4:
            i = r.randrange(3)
            words[i] = words[i][:-1] if words[i] else 'X'
        else:
            args = [a + r.choice(['', ' ', '#', '>', '"']) for a in args]
        return command, words, args

    def hostile(self):
        r = self.rng
        if r.random() < 0.5:
            command, words, args = self.valid()
            args = [r.choice(HOSTILE) if r.random() < 0.6 else a for a in args]
        else:
            command = None
            words = [r.choice(['ADD', 'QUERY', 'GET', 'REMOVE', '', 'X' * 300, 'ＡＤＤ', 'add\n']),
                     r.choice(['IND', 'CLASS', '', '-', 'ALL', '\u0000']),
                     r.choice(['CLASS', '', 'REFS', '🤖'])]
            args = [r.choice(HOSTILE) for _ in range(r.choice([0, 1, 3, 8, 40]))]
        return command, words, args

    def next(self):
        roll = self.rng.random()
        if roll < 0.4:
            return ('valid',) + self.valid()
        if roll < 0.75:
            return ('almost',) + self.almost_valid()
        return ('hostile',) + self.hostile()


class Lane:
    """One client fuzzing its own references (target, shadow, sacrificial) over its own
    transport, so that lanes run side by side without one's acknowledged changes moving the
    state another lane checks."""

    def __init__(self, fuzzer: 'Fuzzer', index: int, seed: int):
        from armor_client import ArmorTransport
        self.fuzzer = fuzzer
        self.directive = fuzzer.directive
        self.rng = random.Random(seed)
        self.target, self.shadow, self.sacrificial = (f'{name}{index}' for name in
                                                      ('target', 'shadow', 'sacrificial'))
        self.grammar = Grammar(self.rng, fuzzer.scratch, (self.target, self.sacrificial))
        self.armor = ArmorTransport(namespace=fuzzer.namespace, service_wait_s=120.0)
        self.codes = {}
        self.kinds = {}
        self.undefined = []
        self.changed_by_rejected = []
        self.unanswered = 0
        self.timed_out = 0
        self.slow = []
        self.sent = 0
        self.rejected = 0
        self.state_waits = 0
        self.epochs = 0
        self.shadow_reasoned = 0
        self.stale_consistency = []
        self.differing = set()
        self.acknowledged = []
        self.failure = None

    def load(self, names=None) -> None:
        # Buffered reasoners: a change does not wait for reasoning (REASON in the stream does it).
        for name in names or (self.target, self.shadow, self.sacrificial):
            self._ok(name, 'LOAD', 'FILE', '', str(ONTOLOGIES / 'robotics.owl'),
                     'http://www.example.org/robotics', 'false', 'PELLET', 'true')
        self.state = self.target_state()

    def start_epoch(self, compare: bool = True) -> None:
        """Compares target and shadow, then loads both afresh from robotics.owl.

        Without it the target only grows: after 13,000 directives a client's random axioms made
        every reasoning slower and the run's rate fell from 250 to 179 directives a second."""
        if compare:
            found = self.differences() - self.differing
            if found:
                print(f'TARGET AND SHADOW DIFFER ({self.target}, epoch {self.epochs}): {sorted(found)[:6]}; '
                      f'the last directives the target acknowledged: {self.acknowledged[-8:]}', flush=True)
            self.differing |= found
        for name in (self.target, self.shadow):
            self._ok(name, 'DROP', '', '')
        self.load((self.target, self.shadow))
        self.epochs += 1

    def _ok(self, reference, command, primary, secondary, *args):
        answer = self.armor.call(self.directive('fuzz-setup', reference, command, primary,
                                                secondary, args), timeout_s=300)
        assert answer.success, f'{command} {primary} {secondary}: {answer.error_description}'
        return answer

    def target_state(self):
        """What a rejected directive must not change: digest, revision, mount holder."""
        # A reasoner the time limit interrupted may hold the reference a while longer: wait it out.
        deadline = time.monotonic() + 900
        while True:
            answer = self.armor.call_list([self.directive('fuzz-state', '', 'GET', 'REF', word,
                                                          [self.target])
                                           for word in ('DIGEST', 'REVISION', 'CLIENT')], timeout_s=300)
            if answer.success or time.monotonic() > deadline:
                break
            self.state_waits += 1
        assert answer.success, [r.error_description for r in answer.armor_responses]
        return tuple(tuple(r.queried_objects) for r in answer.armor_responses)

    def _call(self, request):
        from armor_client import ArmorError
        try:
            return self.armor.call(request, timeout_s=300)
        except ArmorError:
            self.unanswered += 1
            return None

    def _reference_for(self, command) -> str:
        whole = command is not None and command['kind'] in WHOLE_REFERENCE_KINDS
        return self.sacrificial if whole else self.rng.choice(
            [self.target, self.target, self.target, '', 'unknown_ref'])

    def run(self, count: int, deadline: float = float('inf'), epoch: int = 0) -> None:
        try:
            for sent in range(count):
                if time.monotonic() > deadline:
                    return
                if epoch and sent and sent % epoch == 0:
                    self.start_epoch()
                self.step()
        except BaseException as e:  # noqa: BLE001 - the lane's thread reports it to the run
            self.failure = e
            raise

    def step(self) -> None:
        kind, command, words, args = self.grammar.next()
        self.kinds[kind] = self.kinds.get(kind, 0) + 1
        request = self.directive('fuzzer', self._reference_for(command), *words, args)
        started = time.monotonic()
        if self.rng.random() < 0.05:
            _, extra_command, extra_words, extra_args = self.grammar.next()
            extra_whole = extra_command is not None and extra_command['kind'] in WHOLE_REFERENCE_KINDS
            second = self.directive('fuzzer', self.sacrificial if extra_whole else self.target,
                                    *extra_words, extra_args)
            try:
                answer = self.armor.call_list([request, second], timeout_s=300)
            except Exception:  # noqa: BLE001 - counted, the run goes on
                self.unanswered += 1
                return
            responses = list(answer.armor_responses)
            acknowledged = answer.success
            sent = [request, second]
        else:
            response = self._call(request)
            if response is None:
                return
            responses = [response]
            acknowledged = response.success
            sent = [request]
        if time.monotonic() - started > 5:
            self.slow.append((round(time.monotonic() - started, 1), words, args[:4],
                              responses[0].exit_code))
        for response in responses:
            self.codes[response.exit_code] = self.codes.get(response.exit_code, 0) + 1
            if response.exit_code == 220:
                print(f'INTERNAL ERROR: {" ".join(words)} {[a[:60] for a in args[:4]]}: '
                      f'{response.error_description[:300]!r}', flush=True)
            if response.exit_code not in self.fuzzer.defined_codes:
                self.undefined.append((words, args[:3], response.exit_code))
                print(f'UNDEFINED EXIT CODE {response.exit_code}: {" ".join(words)} '
                      f'{[a[:60] for a in args[:4]]}', flush=True)
        touches_target = any(r.reference_name == self.target for r in sent)
        query = command is not None and command['kind'] == 'query' and len(sent) == 1
        if any(getattr(r, 'timeout', False) for r in responses):
            # The node stopped waiting ("the directive may still complete"): neither
            # acknowledged nor rejected. The core serialises the reference, so the state read
            # next comes after it; a revision that moved means it was applied.
            self.timed_out += 1
            if touches_target:
                now = self.target_state()
                if now[1] != self.state[1]:
                    self._shadow(sent)
                self.state = now
        elif acknowledged and not query:
            if touches_target:
                self._shadow(sent)
                self.state = self.target_state()
        elif touches_target:
            self.rejected += 1
            now = self.target_state()
            if now != self.state:
                self.changed_by_rejected.append((words, [a[:40] for a in args[:4]]))
                print(f'CHANGED BY A REJECTED DIRECTIVE: {" ".join(words)} '
                      f'{[a[:60] for a in args[:6]]} -> {[r.exit_code for r in responses]} '
                      f'{responses[0].error_description[:200]!r}; state {self.state} -> {now}',
                      flush=True)
                self.state = now
        self.sent += 1

    def _shadow(self, sent) -> None:
        """Replays on the shadow what the target acknowledged, the way the target got it: a
        list as a list, a directive alone (a list brings a buffered reasoner's consistency mark
        up to date, a directive alone does not)."""
        self.acknowledged = self.acknowledged[-7:] + [[
            f'{r.command} {r.primary_command_spec} {r.secondary_command_spec} {[a[:40] for a in r.args][:3]}'
            for r in sent if r.reference_name == self.target]]
        replay = [type(request)(
            client_name=request.client_name, reference_name=self.shadow, command=request.command,
            primary_command_spec=request.primary_command_spec,
            secondary_command_spec=request.secondary_command_spec, args=list(request.args))
            for request in sent if request.reference_name == self.target]
        from armor_contract.exit_codes import ExitCode
        answer = self._replay(replay, as_list=len(sent) > 1)
        if not answer.success and any(r.exit_code == ExitCode.INCONSISTENT
                                      for r in answer.armor_responses):
            # The shadow gets the target's changes only, not the queries and reasoner time
            # limits that refresh a buffered reference's consistency: a change whose checks read
            # it (DISJOINT CLASS CLASS of one class asks for the siblings) can find the shadow
            # still marked inconsistent after a removal the target has reasoned past. REASON
            # makes the shadow's mark true again; a refusal after it is a disagreement.
            self._ok(self.shadow, 'REASON', '', '')
            self.shadow_reasoned += 1
            answer = self._replay(replay, as_list=len(sent) > 1)
            refused = (ExitCode.INCONSISTENT, ExitCode.ROLLED_BACK)
            if not answer.success and all(r.exit_code in refused for r in answer.armor_responses):
                # The target took it although it is as inconsistent as its shadow says: its
                # consistency mark was stale (a finding, reported). The shadow cannot follow, so
                # this client compares what it has and starts afresh.
                self.stale_consistency.append([f'{r.command} {r.primary_command_spec} '
                                               f'{r.secondary_command_spec} {list(r.args)[:3]}'
                                               for r in replay])
                print(f'TARGET TOOK WHILE INCONSISTENT: {self.stale_consistency[-1]}', flush=True)
                self.start_epoch(compare=False)
                return
        assert answer.success, (f'a directive that succeeded on target failed on shadow: {replay}: '
                                f'{[r.error_description for r in answer.armor_responses]}')

    def _replay(self, replay, as_list: bool):
        """The shadow's answer, as a list's (armor_responses, success)."""
        if as_list:
            return self.armor.call_list(replay, timeout_s=300)
        response = self.armor.call(replay[0], timeout_s=300)
        return type('Replayed', (), {'armor_responses': [response],
                                     'success': response.success})

    def differences(self) -> set:
        """Axioms in one of target and shadow but not the other (in an earlier epoch, or now)."""
        contents = {}
        for name in (self.target, self.shadow):
            path = self.fuzzer.scratch / f'{name}.ofn'
            self._ok(name, 'SAVE', '', '', str(path), 'functional')
            contents[name] = {line for line in path.read_text().splitlines()
                              if line and not line.startswith(('Ontology(', 'Prefix(', '#'))}
        return self.differing | (contents[self.target] ^ contents[self.shadow])


class Fuzzer:
    """A node under fuzzing by ``lanes`` clients at once, each on references of its own."""

    def __init__(self, scratch: pathlib.Path, seed: int, lanes: int = 1):
        from armor_client import ArmorTransport, directive
        from armor_contract.exit_codes import ExitCode
        self.defined_codes = {int(code) for code in ExitCode}
        self.directive = directive
        self.scratch = scratch
        self.namespace = '/fuzz'
        # Random axioms can send a reasoner into exponential work: as a deployment facing
        # untrusted input would, the run bounds reasoning, so such a directive answers 211.
        self.node = start_node(scratch, '-p', 'reasoner_timeout_ms:=10000',
                               '-p', 'request_timeout_s:=120.0', namespace=self.namespace)
        self.armor = ArmorTransport(namespace=self.namespace, service_wait_s=120.0)
        self.lanes = [Lane(self, i, seed * 1000 + i) for i in range(lanes)]
        for lane in self.lanes:
            lane.load()

    def run(self, count: int, deadline: float = float('inf'), progress=None,
            progress_every_s: float = 60.0, epoch: int = 0) -> None:
        """Sends ``count`` directives, shared among the lanes, which run side by side (none
        waits for another) until done or ``deadline`` (time.monotonic()); ``progress`` is called
        every ``progress_every_s`` meanwhile. With ``epoch``, each lane starts afresh (its target
        compared with its shadow, both loaded again) after every ``epoch`` of its directives."""
        shares = [count // len(self.lanes) + (1 if i < count % len(self.lanes) else 0)
                  for i in range(len(self.lanes))]
        threads = [threading.Thread(target=lane.run, args=(share, deadline, epoch), daemon=True)
                   for lane, share in zip(self.lanes, shares)]
        for thread in threads:
            thread.start()
        for thread in threads:
            while thread.is_alive():
                thread.join(progress_every_s)
                if progress is not None and thread.is_alive():
                    progress()
        for lane in self.lanes:
            if lane.failure is not None:
                raise lane.failure

    def _total(self, counter: str):
        values = [getattr(lane, counter) for lane in self.lanes]
        if isinstance(values[0], dict):
            total = {}
            for value in values:
                for key, n in value.items():
                    total[key] = total.get(key, 0) + n
            return total
        return sum(values, [] if isinstance(values[0], list) else 0)

    codes = property(lambda self: self._total('codes'))
    kinds = property(lambda self: self._total('kinds'))
    undefined = property(lambda self: self._total('undefined'))
    changed_by_rejected = property(lambda self: self._total('changed_by_rejected'))
    unanswered = property(lambda self: self._total('unanswered'))
    timed_out = property(lambda self: self._total('timed_out'))
    slow = property(lambda self: self._total('slow'))
    sent = property(lambda self: self._total('sent'))
    rejected = property(lambda self: self._total('rejected'))
    epochs = property(lambda self: self._total('epochs'))
    shadow_reasoned = property(lambda self: self._total('shadow_reasoned'))
    stale_consistency = property(lambda self: self._total('stale_consistency'))

    def differences(self) -> set:
        """Axioms in one lane's target but not in its shadow, or the other way round."""
        return set().union(*(lane.differences() for lane in self.lanes))

    def alive(self) -> bool:
        return self.node.process.poll() is None and self.armor.call(
            self.directive('fuzz', '', 'GET', 'ALL', 'REFS', []), timeout_s=60).success

    def summary(self, elapsed_s: float, alive: bool, differences: set) -> str:
        codes = self.codes
        return (f'{self.sent} directives ({", ".join(f"{k}: {n}" for k, n in sorted(self.kinds.items()))}) '
                f'in {elapsed_s:.0f} s ({self.sent / max(elapsed_s, 1e-9):.1f}/s, {len(self.lanes)} '
                f'clients at once); node alive: {alive}; '
                f'crashes (core restarts, 216): {codes.get(216, 0)}; '
                f'answers lost: {self.unanswered}; timed out at the node (applied or not, as the '
                f'revision said): {self.timed_out}; undefined exit codes: {len(self.undefined)}; '
                f'internal errors (220): {codes.get(220, 0)}; '
                f'rejected on the target: {self.rejected}, of which changed its state: '
                f'{len(self.changed_by_rejected)}; axioms differing from the shadow: '
                f'{len(differences)}' + (f' (over {self.epochs} fresh starts and the last state)'
                                         if self.epochs else '')
                + f'; shadow reasoned before a replay: {self.shadow_reasoned}; taken by the '
                f'target while inconsistent: {len(self.stale_consistency)}')

    def close(self) -> None:
        for lane in self.lanes:
            lane.armor.close()
        self.armor.close()
        self.node.stop()


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--directives', type=int, default=1_000_000)
    parser.add_argument('--seed', type=int, default=1)
    parser.add_argument('--clients', type=int, default=4,
                        help='clients fuzzing at once, each on references of its own')
    parser.add_argument('--seconds', type=float, default=None,
                        help='stop after this many seconds (each client finishes its directive)')
    parser.add_argument('--progress-every-s', type=float, default=60.0)
    parser.add_argument('--epoch', type=int, default=0,
                        help='each client compares its target with its shadow and loads both '
                             'afresh after this many of its directives (0: never)')
    options = parser.parse_args()
    fuzzer = Fuzzer(pathlib.Path(tempfile.mkdtemp(prefix='armor-fuzz-')), options.seed, options.clients)
    started = time.monotonic()
    try:
        fuzzer.run(options.directives,
                   deadline=started + options.seconds if options.seconds else float('inf'),
                   progress=lambda: print(fuzzer.summary(time.monotonic() - started, True, set()),
                                          flush=True),
                   progress_every_s=options.progress_every_s, epoch=options.epoch)
        alive = fuzzer.alive()
        differences = fuzzer.differences()
    finally:
        fuzzer.close()
    elapsed = time.monotonic() - started
    print('final: ' + fuzzer.summary(elapsed, alive, differences))
    if fuzzer.sent < options.directives:
        print(f'stopped after {fuzzer.sent} of {options.directives} directives; at this rate the '
              f'{options.directives} take {options.directives * elapsed / max(fuzzer.sent, 1) / 3600:.1f} h')
    print('exit codes: ' + ', '.join(f'{c}: {n}' for c, n in sorted(fuzzer.codes.items())))
    for words, args in fuzzer.changed_by_rejected[:20]:
        print(f'CHANGED BY A REJECTED DIRECTIVE: {" ".join(words)} {args}')
    for replay in fuzzer.stale_consistency[:20]:
        print(f'TAKEN BY THE TARGET WHILE INCONSISTENT: {replay}')
    for seconds, words, args, code in fuzzer.slow[:20]:
        print(f'slow: {seconds} s {" ".join(words)} {[a[:40] for a in args]} -> {code}')
    ok = (alive and not fuzzer.undefined and not differences and not fuzzer.changed_by_rejected
          and fuzzer.unanswered == 0 and fuzzer.codes.get(216, 0) == 0
          and fuzzer.codes.get(220, 0) == 0)
    return 0 if ok else 1


if __name__ == '__main__':
    sys.exit(main())
