# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Random and malformed directives over ROS 2: the node must answer every one with a defined code.

    python tests/integration/fuzz.py --directives 100000

Directives are drawn from ARMOR's vocabulary, mangled (case, arity, unicode, huge strings,
IRIs, Manchester and SPARQL garbage) and sent to a reference loaded from robotics.owl. Every
directive that succeeds there is replayed on a shadow copy; at the end both are saved and must
hold the same axioms, so a rejected directive that changed anything shows up as a difference.
"""

import argparse
import pathlib
import random
import sys
import tempfile
import time

sys.path.insert(0, str(pathlib.Path(__file__).resolve().parent))

from conftest import ONTOLOGIES, start_node  # noqa: E402

DEFINED_CODES = {0, 101, 102, 201, 202, 203, 205} | set(range(206, 221))
COMMANDS = ['ADD', 'REMOVE', 'REPLACE', 'QUERY', 'DISJOINT', 'MAKE', 'RENAME', 'REASON', 'APPLY',
            'GET', 'LOG', 'SAVE', 'DROP', 'MOUNT', 'UNMOUNT', 'LOAD', 'CREATE', 'FLY', '']
SPECS = ['IND', 'CLASS', 'DATAPROP', 'OBJECTPROP', 'SPARQL', 'FORMATTED', 'AXIOM', 'SWRL', 'DL',
         'CARDINALITY', 'MIN', 'EQUIVALENT', 'DISJOINT', 'SAME', 'INVERSE', 'CHARACTERISTIC',
         'DOMAIN', 'RANGE', 'SUPER', 'RESTRICTIONS', 'CONSISTENCY', 'ALL', 'REFS', 'REF', 'CLIENT',
         'FILE', 'WEB', 'MOUNTED', 'INFERENCE', 'SCREEN', 'ON', 'OFF', '-', '', 'XYZZY']
# Commands that act on references as wholes go to a sacrificial reference only, so that the
# compared reference changes through manipulations alone.
WHOLE_REFERENCE = {'DROP', 'MOUNT', 'UNMOUNT', 'LOAD', 'CREATE', 'SAVE', 'LOG'}
NAMES = ['robot1', 'kitchen', 'bedroom', 'alice', 'Robot', 'Room', 'Agent', 'isIn', 'contains',
         'batteryLevel', 'visitedAt', 'newThing', 'Location', 'OccupiedRoom', 'corridor1']
TYPES = ['INT', 'INTEGER', 'FLOAT', 'LONG', 'DOUBLE', 'BOOL', 'BOOLEAN', 'STRING', 'xsd:dateTime',
         'xsd:nonsense', 'COLOUR', '']
GARBAGE = [
    '', ' ', '-1', '0', '3.14', '1e999', 'NaN', 'true', 'yes', '99999999999999999999999',
    '<http://www.example.org/robotics#robot1>', 'http://www.example.org/robotics#Room',
    '<not an iri>', '<http://unbalanced', 'ex:Foo', ':::', 'owl:Thing', 'owl:Nothing',
    'Robot and and', 'isIn some (', 'not not not', 'Room SubClassOf isIn exactly 1 Location',
    'SubClassOf(:A :B)', 'ClassAssertion(', 'Robot(?r) -> Room(?r)', 'Robot(?r), -> ',
    'SELECT ?x WHERE { ?x a :Robot }', 'SELECT * WHERE {', 'ASK { :kitchen a :Room }',
    'DROP ALL', 'ünïcødé', '机器人', '🤖', '\u0000', 'a\nb', '\\', '"quoted"', "'", '%s%n',
    '../../etc/passwd', '/etc/passwd', 'x' * 100_000,
]


# Real combinations with their usual arity, so that many directives reach the handlers.
VALID = {
    'ADD IND': 1, 'ADD IND CLASS': 2, 'REMOVE IND CLASS': 2, 'ADD CLASS': 1, 'ADD CLASS CLASS': 2,
    'REMOVE CLASS CLASS': 2, 'ADD DATAPROP IND': 4, 'REMOVE DATAPROP IND': 4,
    'ADD OBJECTPROP IND': 3, 'REMOVE OBJECTPROP IND': 3, 'REPLACE DATAPROP IND': 5,
    'REPLACE OBJECTPROP IND': 4, 'ADD CARDINALITY MIN': 4, 'DISJOINT IND': 2, 'DISJOINT CLASS': 2,
    'DISJOINT IND CLASS': 1, 'DISJOINT CLASS CLASS': 1, 'MAKE EQUIVALENT CLASS': 1,
    'REMOVE IND': 1, 'REMOVE CLASS': 1, 'RENAME IND': 2, 'RENAME CLASS': 2,
    'ADD OBJECTPROP CHARACTERISTIC': 2, 'ADD OBJECTPROP DOMAIN': 2, 'ADD DATAPROP RANGE': 2,
    'ADD IND SAME': 2, 'ADD CLASS EQUIVALENT': 2, 'ADD AXIOM': 1, 'REMOVE AXIOM': 1,
    'ADD SWRL': 2, 'APPLY': 0, 'REASON': 0, 'QUERY IND': 1, 'QUERY IND CLASS': 1,
    'QUERY IND DL': 1, 'QUERY CLASS IND': 1, 'QUERY DATAPROP IND': 2, 'QUERY OBJECTPROP IND': 2,
    'QUERY CLASS CLASS': 1, 'QUERY CLASS SUPER': 1, 'QUERY CLASS RESTRICTIONS': 1,
    'QUERY SPARQL': 1, 'QUERY SPARQL FORMATTED': 1, 'QUERY CONSISTENCY': 0, 'QUERY IND SAME': 1,
    'GET ALL REFS': 0, 'DROP': 0, 'MOUNT': 0, 'UNMOUNT': 0, 'SAVE': 2,
}


def random_directive(rng: random.Random):
    if rng.random() < 0.6:
        key = rng.choice(sorted(VALID))
        words = (key.split() + ['', ''])[:3]
        arity = max(0, VALID[key] + rng.choice([0, 0, 0, 0, -1, 1]))
        pool = [NAMES, NAMES, NAMES, TYPES, GARBAGE]
        return words, [rng.choice(rng.choice(pool)) for _ in range(arity)]
    command = rng.choice(COMMANDS)
    primary = rng.choice(SPECS)
    secondary = rng.choice(SPECS)
    words = [command, primary, secondary]
    if rng.random() < 0.2:
        words = [''.join(c.upper() if rng.random() < 0.5 else c.lower() for c in w) for w in words]
    arity = rng.choice([0, 1, 1, 2, 2, 3, 4, 5, 8])
    pool = [NAMES, NAMES, TYPES, GARBAGE]
    args = [rng.choice(rng.choice(pool)) for _ in range(arity)]
    return words, args


def _mutates(words):
    return words[0].upper() in WHOLE_REFERENCE


class Fuzzer:
    def __init__(self, scratch: pathlib.Path, seed: int):
        from armor_client import ArmorTransport, directive
        self.directive = directive
        self.scratch = scratch
        self.rng = random.Random(seed)
        # Random axioms can send a reasoner into exponential work: as a deployment facing
        # untrusted input would, the run bounds reasoning, so such a directive answers 211.
        self.node = start_node(scratch, '-p', 'reasoner_timeout_ms:=10000',
                               '-p', 'request_timeout_s:=120.0', namespace='/fuzz')
        self.armor = ArmorTransport(namespace='/fuzz', service_wait_s=120.0)
        for name in ('target', 'shadow'):
            self._ok(name, 'LOAD', 'FILE', '', str(ONTOLOGIES / 'robotics.owl'),
                     'http://www.example.org/robotics', 'false', 'PELLET', 'true')
        self.codes = {}
        self.undefined = []
        self.slow = []
        self.sent = 0

    def _ok(self, reference, command, primary, secondary, *args):
        answer = self.armor.call(self.directive('fuzz-setup', reference, command, primary,
                                                secondary, args), timeout_s=300)
        assert answer.success, f'{command} {primary} {secondary}: {answer.error_description}'
        return answer

    def run(self, count: int) -> None:
        for _ in range(count):
            words, args = random_directive(self.rng)
            reference = 'sacrificial' if _mutates(words) else self.rng.choice(
                ['target', 'target', 'target', '', 'unknown_ref'])
            request = self.directive('fuzzer', reference, *words, args)
            if self.rng.random() < 0.05:
                extra_words, extra_args = random_directive(self.rng)
                second = self.directive('fuzzer', 'target' if not _mutates(extra_words)
                                        else 'sacrificial', *extra_words, extra_args)
                answer = self.armor.call_list([request, second], timeout_s=300)
                responses = list(answer.armor_responses)
                if answer.success:
                    for sent in (request, second):
                        self._shadow(sent)
            else:
                started = time.monotonic()
                responses = [self.armor.call(request, timeout_s=300)]
                if time.monotonic() - started > 5:
                    self.slow.append((round(time.monotonic() - started, 1), words, args[:4],
                                      responses[0].exit_code))
                if responses[0].success:
                    self._shadow(request)
            for response in responses:
                self.codes[response.exit_code] = self.codes.get(response.exit_code, 0) + 1
                if response.exit_code not in DEFINED_CODES:
                    self.undefined.append((words, args[:3], response.exit_code))
            self.sent += 1

    def _shadow(self, request) -> None:
        if request.reference_name == 'target':
            request.reference_name = 'shadow'
            answer = self.armor.call(request, timeout_s=300)
            request.reference_name = 'target'
            assert answer.success, f'a directive that succeeded on target failed on shadow: {request}'

    def differences(self) -> set:
        """Axioms in one of target and shadow but not the other."""
        contents = {}
        for name in ('target', 'shadow'):
            path = self.scratch / f'{name}.ofn'
            self._ok(name, 'SAVE', '', '', str(path), 'functional')
            contents[name] = {line for line in path.read_text().splitlines()
                              if line and not line.startswith(('Ontology(', 'Prefix(', '#'))}
        return contents['target'] ^ contents['shadow']

    def alive(self) -> bool:
        return self.node.process.poll() is None and self.armor.call(
            self.directive('fuzz', '', 'GET', 'ALL', 'REFS', []), timeout_s=60).success

    def close(self) -> None:
        self.armor.close()
        self.node.stop()


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--directives', type=int, default=100_000)
    parser.add_argument('--seed', type=int, default=1)
    options = parser.parse_args()
    fuzzer = Fuzzer(pathlib.Path(tempfile.mkdtemp(prefix='armor-fuzz-')), options.seed)
    started = time.monotonic()
    try:
        fuzzer.run(options.directives)
        alive = fuzzer.alive()
        differences = fuzzer.differences()
    finally:
        fuzzer.close()
    elapsed = time.monotonic() - started
    print(f'{fuzzer.sent} directives in {elapsed:.0f} s ({fuzzer.sent / elapsed:.0f}/s); '
          f'node alive: {alive}; undefined exit codes: {len(fuzzer.undefined)}; '
          f'axioms differing from the shadow: {len(differences)}')
    print('exit codes: ' + ', '.join(f'{c}: {n}' for c, n in sorted(fuzzer.codes.items())))
    for seconds, words, args, code in fuzzer.slow:
        print(f'slow: {seconds} s {" ".join(words)} {[a[:40] for a in args]} -> {code}')
    return 0 if alive and not fuzzer.undefined and not differences else 1


if __name__ == '__main__':
    sys.exit(main())
