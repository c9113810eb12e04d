# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Plain rclpy clients with the default service QoS under load: what they lose, and the recovery.

    python bench/default_clients.py [--clients 8] [--directives 2000] [--flood 10000]
                                    [--quiet-s 20] [--timeout-s 30] [--json]

Ported ROS 1 code calls ARMOR with a plain rclpy client and the default service QoS (history
KEEP_LAST 10), not with armor_client. This measures such clients (issue 20, item 6):

1. sequential: --clients processes at once, each sending --directives directives one at a
   time (call_async + spin_until_future_complete, --timeout-s per call) to one reference: ADD
   IND CLASS of individuals of its own, every --query-every-th a QUERY IND CLASS;
2. flood: this process sends --flood ADD IND CLASS with call_async all at once (an executor
   thread collects the answers) and waits until no answer has come for --quiet-s; the
   individuals go to references of --flood-per-reference each, so that every reference's
   change history (the last 10,000 changes) holds all of them for the recovery;
3. the same flood against a bare rclpy echo server with the default QoS that counts what it
   receives (requests it never received, answers it sent that never arrived): the same losses
   with a server that does nothing but answer.

An unanswered ADD was either never received (request lost) or applied without its answer
reaching the client (answer lost); the reference's change history tells which. Then every
client with unanswered directives recovers as a retrying client should: GET REF CHANGES since
the revision it read before it started tells which of its changes were applied; it resends
only the others. Last, a QUERY must show every individual exactly once, and the history no
individual added twice. For the sequential run the audit follows the history during the run
(its 10,000 changes would not cover 8 x 2,000 directives), so the duplicate count is exact there
too; a sequential client's own question comes too late for the history (it reads the revision
once, before its 2,000 directives), so what it cannot decide is looked up with a QUERY and
counted apart.

Run as a script it prints a table; the suite (bench/suite.py) calls measure() at a small size.
"""

import argparse
import json
import pathlib
import subprocess
import sys
import tempfile
import threading
import time
from typing import Dict, Iterable, List, Optional, Tuple

from harness import BenchNode, CoreSnapshot, latency_summary, stop_process

ECHO_NODE = 'default_qos_echo'
CLASS = 'Marker'
SEQUENTIAL_REFERENCE = 'default_qos_sequential'
HISTORY_POLL_S = 0.5


_STARTED = time.monotonic()


def progress(text: str) -> None:
    print(f'[default_clients {time.monotonic() - _STARTED:6.0f} s] {text}', file=sys.stderr,
          flush=True)


def service_name(namespace: str) -> str:
    from armor_contract.services import DIRECTIVE_SERVICE
    return f'{namespace}/{DIRECTIVE_SERVICE}'


def request(client_name: str, reference: str, words: str, *args: str):
    """An ArmorDirective request built by hand, as ported ROS 1 code does."""
    from armor_msgs.msg import ArmorDirectiveReq
    from armor_msgs.srv import ArmorDirective
    command, primary, secondary = (words.split() + ['', '', ''])[:3]
    return ArmorDirective.Request(armor_request=ArmorDirectiveReq(
        client_name=client_name, reference_name=reference, command=command,
        primary_command_spec=primary, secondary_command_spec=secondary, args=list(args)))


class DefaultClient:
    """A plain rclpy service client with the default QoS, one request in flight at a time."""

    def __init__(self, service: str, node_name: str, executor=None):
        import rclpy
        from armor_msgs.srv import ArmorDirective
        self.node = rclpy.create_node(node_name)
        self.client = self.node.create_client(ArmorDirective, service)  # default QoS
        self.executor = executor
        if not self.client.wait_for_service(timeout_sec=120):
            raise RuntimeError(f'{service} did not come up')

    def call(self, message, timeout_s: float):
        """The response, or None when none came within timeout_s (the request is forgotten)."""
        import rclpy
        future = self.client.call_async(message)
        rclpy.spin_until_future_complete(self.node, future, executor=self.executor,
                                         timeout_sec=timeout_s)
        if not future.done():
            self.client.remove_pending_request(future)
            return None
        return future.result().armor_response

    def must(self, message, timeout_s: float = 120, attempts: int = 5):
        """A read-only call retried until answered (reads are safe to repeat)."""
        for _ in range(attempts):
            answer = self.call(message, timeout_s)
            if answer is not None:
                return answer
        raise RuntimeError(f'no answer to {message.armor_request.command} '
                           f'{message.armor_request.primary_command_spec} in {attempts} tries')

    def close(self):
        self.node.destroy_node()


def revision(caller: DefaultClient, client_name: str, reference: str) -> int:
    answer = caller.must(request(client_name, reference, 'GET REF REVISION', reference))
    if not answer.success:
        raise RuntimeError(f'GET REF REVISION: {answer.exit_code} {answer.error_description}')
    return int(answer.queried_objects[0])


def changes_since(caller: DefaultClient, client_name: str, reference: str,
                  since: int) -> Tuple[List[dict], int]:
    """The reference's changes after `since`, and how many of those the history no longer holds."""
    answer = caller.must(request(client_name, reference, 'GET REF CHANGES', reference, str(since)))
    if not answer.success:
        raise RuntimeError(f'GET REF CHANGES: {answer.exit_code} {answer.error_description}')
    changes = [json.loads(text) for text in answer.queried_objects]
    missed = changes[0]['revision'] - since - 1 if changes else 0
    return changes, max(0, missed)


def added_by(changes: Iterable[dict], client_name: Optional[str] = None) -> Dict[str, int]:
    """Individual -> how many ADD IND CLASS of it the changes hold (of one client, or of all)."""
    counts: Dict[str, int] = {}
    for change in changes:
        for directive in change['directives']:
            if (directive['command'].upper(), directive['primary_command_spec'].upper(),
                    directive['secondary_command_spec'].upper()) != ('ADD', 'IND', 'CLASS'):
                continue
            if client_name is None or directive['client_name'] == client_name:
                counts[directive['args'][0]] = counts.get(directive['args'][0], 0) + 1
    return counts


class HistoryFollower:
    """Reads a reference's change history while a run goes on, so that none of it rolls out.

    A thread with a default client of its own; reads are repeated until answered. `missed`
    counts revisions the history had dropped before they were read (0 makes the audit exact).
    """

    def __init__(self, service: str, reference: str, since: int):
        from rclpy.executors import SingleThreadedExecutor
        self.caller = DefaultClient(service, 'history_follower', SingleThreadedExecutor())
        self.reference, self.last = reference, since
        self.changes: List[dict] = []
        self.missed = 0
        # The run's own last catch_up may meet the thread's: one at a time, or both append a change.
        self._reading = threading.Lock()
        self._stop = threading.Event()
        self._thread = threading.Thread(target=self._follow, daemon=True)
        self._thread.start()

    def _follow(self):
        while not self._stop.wait(HISTORY_POLL_S):
            self.catch_up()

    def catch_up(self):
        with self._reading:
            changes, missed = changes_since(self.caller, 'auditor', self.reference, self.last)
            self.missed += missed
            self.changes += changes
            if changes:
                self.last = changes[-1]['revision']

    def stop(self):
        self._stop.set()
        self._thread.join()

    def close(self):
        self.stop()
        self.caller.executor.shutdown()
        self.caller.close()


# --- 1. sequential clients, each in its own process -------------------------------------------

# Seconds a client process may take to exit once it has written its results.
SHUTDOWN_GRACE_S = 30.0


def sequential_client(service: str, index: int, directives: int, query_every: int,
                      timeout_s: float, out: pathlib.Path) -> None:
    """One client process: `directives` calls, one at a time; what happened to each, in `out`."""
    import rclpy
    rclpy.init()
    me = f'sequential{index}'
    caller = DefaultClient(service, me)
    start_revision = revision(caller, me, SEQUENTIAL_REFERENCE)
    records = []
    started = time.monotonic()
    for k in range(directives):
        if query_every and k % query_every == query_every - 1:
            kind, message = 'QUERY', request(me, SEQUENTIAL_REFERENCE, 'QUERY IND CLASS', CLASS)
        else:
            kind = 'ADD'
            message = request(me, SEQUENTIAL_REFERENCE, 'ADD IND CLASS', f'{me}_{k}', CLASS)
        sent = time.perf_counter()
        answer = caller.call(message, timeout_s)
        records.append({'kind': kind, 'name': message.armor_request.args[0],
                        'answered': answer is not None,
                        'success': answer is not None and answer.success,
                        'seconds': time.perf_counter() - sent})
    out.write_text(json.dumps({'client': me, 'start_revision': start_revision,
                               'wall_s': time.monotonic() - started, 'records': records}))
    caller.close()
    rclpy.shutdown()


def run_sequential(namespace: str, scratch: pathlib.Path, clients: int, directives: int,
                   query_every: int, timeout_s: float, coordinator: DefaultClient) -> dict:
    """Sequential client processes on one reference; figures, recovery and audit."""
    service = service_name(namespace)
    create(coordinator, SEQUENTIAL_REFERENCE)
    follower = HistoryFollower(service, SEQUENTIAL_REFERENCE,
                               revision(coordinator, 'auditor', SEQUENTIAL_REFERENCE))
    started = time.monotonic()
    outs = [scratch / f'sequential{i}.json' for i in range(clients)]
    processes = [subprocess.Popen([sys.executable, __file__, '--as-sequential-client', str(i),
                                   '--service', service, '--directives', str(directives),
                                   '--query-every', str(query_every),
                                   '--timeout-s', str(timeout_s), '--out', str(out)])
                 for i, out in enumerate(outs)]
    deadline = time.monotonic() + max(900, directives)
    for process, out in zip(processes, outs):
        while process.poll() is None:
            if out.exists() and time.time() - out.stat().st_mtime > SHUTDOWN_GRACE_S:
                # Its calls are done and written. Fast DDS can spin for good in
                # DomainParticipant::set_listener while rclpy destroys the node (seen once in a
                # clean-clone run): the client's exit is not what is measured here.
                process.kill()
                process.wait()
                break
            if time.monotonic() > deadline:
                raise RuntimeError(f'a sequential client did not finish within '
                                   f'{max(900, directives)} s')
            time.sleep(0.5)
        else:
            if process.returncode != 0:
                raise RuntimeError(f'a sequential client failed (exit {process.returncode})')
    wall_s = time.monotonic() - started
    progress('sequential clients done; recovery and audit')
    results = [json.loads(out.read_text()) for out in outs]
    follower.catch_up()
    applied = added_by(follower.changes)
    records = [r for result in results for r in result['records']]
    figures = count(records, applied, wall_s)
    recovery = {'unanswered_adds': 0, 'applied_via_history': 0, 'resent': 0, 'undecidable': 0,
                'window_missed': 0}
    for result in results:
        unanswered = [r['name'] for r in result['records']
                      if r['kind'] == 'ADD' and not r['answered']]
        if unanswered:
            add_up(recovery, recover(coordinator, result['client'], SEQUENTIAL_REFERENCE,
                                     result['start_revision'], unanswered, timeout_s))
    follower.close()
    expected = [r['name'] for r in records if r['kind'] == 'ADD']
    figures['recovery'] = {**recovery, **audit(coordinator, SEQUENTIAL_REFERENCE, expected,
                                               added_by(follower.changes), follower.missed)}
    return figures


# --- 2 and 3. one process flooding ---------------------------------------------------------------

def flood(service: str, messages: List, quiet_s: float) -> Tuple[List[Optional[float]], float]:
    """Sends every message at once; seconds to each answer (None: never came), and wall time."""
    import rclpy
    from armor_msgs.srv import ArmorDirective
    from rclpy.executors import SingleThreadedExecutor
    node = rclpy.create_node('default_qos_flood')
    client = node.create_client(ArmorDirective, service)  # default QoS
    if not client.wait_for_service(timeout_sec=120):
        raise RuntimeError(f'{service} did not come up')
    executor = SingleThreadedExecutor()
    executor.add_node(node)
    stop = threading.Event()

    def spin():
        while not stop.is_set():
            executor.spin_once(timeout_sec=0.05)

    spinner = threading.Thread(target=spin, daemon=True)
    spinner.start()
    answered_after: List[Optional[float]] = [None] * len(messages)
    last_answer = [time.monotonic()]
    futures = []
    started = time.monotonic()
    for i, message in enumerate(messages):
        sent = time.perf_counter()

        def done(_, i=i, sent=sent):
            answered_after[i] = time.perf_counter() - sent
            last_answer[0] = time.monotonic()
        future = client.call_async(message)
        future.add_done_callback(done)
        futures.append(future)
    while (time.monotonic() - last_answer[0] < quiet_s
           and any(seconds is None for seconds in answered_after)):
        time.sleep(0.1)
    wall_s = last_answer[0] - started
    stop.set()
    spinner.join()
    for future in futures:
        if not future.done():
            client.remove_pending_request(future)
    executor.remove_node(node)
    executor.shutdown()
    node.destroy_node()
    return answered_after, wall_s


def run_flood(namespace: str, directives: int, per_reference: int, quiet_s: float,
              timeout_s: float, coordinator: DefaultClient) -> dict:
    """One flood of ADDs from this process; figures, recovery and audit."""
    me = 'flooder'
    references = [f'default_qos_flood{i}' for i in range(-(-directives // per_reference))]
    start_revisions = {}
    for reference in references:
        create(coordinator, reference)
        start_revisions[reference] = revision(coordinator, me, reference)
    targets = [(references[k // per_reference], f'{me}_{k}') for k in range(directives)]
    messages = [request(me, reference, 'ADD IND CLASS', name, CLASS)
                for reference, name in targets]
    answered_after, wall_s = flood(service_name(namespace), messages, quiet_s)
    progress('flood done; recovery and audit')
    applied: Dict[str, int] = {}
    for reference in references:
        applied.update(added_by(changes_since(coordinator, 'auditor', reference,
                                              start_revisions[reference])[0]))
    records = [{'kind': 'ADD', 'name': name, 'answered': seconds is not None,
                'success': seconds is not None, 'seconds': seconds}
               for (_, name), seconds in zip(targets, answered_after)]
    figures = count(records, applied, wall_s)
    recovery = {'unanswered_adds': 0, 'applied_via_history': 0, 'resent': 0, 'undecidable': 0,
                'window_missed': 0}
    final = {'missing': 0, 'unexpected': 0, 'listed_twice': 0, 'applied_twice': 0,
             'history_missed': 0}
    for reference in references:
        unanswered = [name for (ref, name), seconds in zip(targets, answered_after)
                      if ref == reference and seconds is None]
        if unanswered:
            add_up(recovery, recover(coordinator, me, reference, start_revisions[reference],
                                     unanswered, timeout_s))
        history, missed = changes_since(coordinator, 'auditor', reference,
                                        start_revisions[reference])
        add_up(final, audit(coordinator, reference,
                            [name for ref, name in targets if ref == reference],
                            added_by(history), missed))
    figures['recovery'] = {**recovery, **final}
    figures['references'] = len(references)
    return figures


def echo_server(namespace: str) -> None:
    """A bare rclpy service with the default QoS; COUNT answers how many requests came before."""
    import rclpy
    from armor_msgs.srv import ArmorDirective
    rclpy.init()
    node = rclpy.create_node(ECHO_NODE, namespace=namespace)
    received = [0]

    def answer(message, response):
        if message.armor_request.command == 'COUNT':
            response.armor_response.queried_objects = [str(received[0])]
        else:
            received[0] += 1
        response.armor_response.success = True
        return response

    node.create_service(ArmorDirective, 'echo', answer)  # default QoS
    from rclpy.executors import ExternalShutdownException
    try:
        rclpy.spin(node)
    except (KeyboardInterrupt, ExternalShutdownException):
        pass  # terminated by the benchmark


def run_echo_flood(namespace: str, directives: int, quiet_s: float) -> dict:
    namespace = f'{namespace}_echo'
    server = subprocess.Popen([sys.executable, __file__, '--as-echo-server', namespace])
    try:
        service = f'{namespace}/echo'
        messages = [request('flooder', 'echo', 'ADD IND CLASS', f'e{k}', CLASS)
                    for k in range(directives)]
        answered_after, wall_s = flood(service, messages, quiet_s)
        counter = DefaultClient(service, 'echo_counter')
        received = int(counter.must(request('flooder', '', 'COUNT')).queried_objects[0])
        counter.close()
    finally:
        stop_process(server)
    answered = [s for s in answered_after if s is not None]
    return {'sent': directives, 'answered': len(answered), 'errors': 0,
            'requests_lost': directives - received, 'answers_lost': received - len(answered),
            'unanswered_queries': 0, 'wall_s': wall_s, **_latency(answered)}


# --- what happened, recovery, audit ------------------------------------------------------------

def create(caller: DefaultClient, reference: str) -> None:
    answer = caller.must(request('coordinator', reference, 'CREATE',
                                 f'http://example.org/{reference}', 'false', 'PELLET', 'true'))
    if not answer.success:
        raise RuntimeError(f'CREATE {reference}: {answer.exit_code} {answer.error_description}')


def _latency(seconds: List[float]) -> dict:
    if not seconds:
        return {'p50_ms': None, 'p99_ms': None}
    summary = latency_summary(seconds)
    return {'p50_ms': summary['p50_ms'], 'p99_ms': summary['p99_ms']}


def count(records: List[dict], applied: Dict[str, int], wall_s: float) -> dict:
    """Sent, answered, and for unanswered ADDs whether the core applied them (history)."""
    unanswered_adds = [r['name'] for r in records if r['kind'] == 'ADD' and not r['answered']]
    answered = [r for r in records if r['answered']]
    return {'sent': len(records), 'answered': len(answered),
            'errors': sum(1 for r in answered if not r['success']),
            'requests_lost': sum(1 for name in unanswered_adds if name not in applied),
            'answers_lost': sum(1 for name in unanswered_adds if name in applied),
            'unanswered_queries': sum(1 for r in records
                                      if r['kind'] == 'QUERY' and not r['answered']),
            'wall_s': wall_s, **_latency([r['seconds'] for r in answered])}


def add_up(total: dict, part: dict) -> None:
    for key, value in part.items():
        total[key] = total.get(key, 0) + value


def recover(caller: DefaultClient, client_name: str, reference: str, since: int,
            unanswered: List[str], timeout_s: float, rounds: int = 5) -> dict:
    """What a client that never got some answers does: the history says which ADDs applied;
    the others are resent, one at a time, with a default client acting as that client.

    A resend that goes unanswered in its turn is checked the same way in the next round. When
    the history no longer reaches back to `since`, an ADD it does not show is undecidable from
    the history; those are looked up with a QUERY (sound here only because each individual is
    added by its own client alone) and counted apart.
    """
    figures = {'unanswered_adds': len(unanswered), 'applied_via_history': 0, 'resent': 0,
               'undecidable': 0, 'window_missed': 0}
    pending = list(unanswered)
    for _ in range(rounds):
        if not pending:
            break
        changes, missed = changes_since(caller, client_name, reference, since)
        figures['window_missed'] += missed
        applied = added_by(changes, client_name)
        found = [name for name in pending if name in applied]
        figures['applied_via_history'] += len(found)
        pending = [name for name in pending if name not in applied]
        if missed and pending:
            figures['undecidable'] += len(pending)
            present = set(caller.must(request(client_name, reference, 'QUERY IND CLASS',
                                              CLASS)).queried_objects)
            pending = [name for name in pending
                       if not any(entity.endswith(f'#{name}>') for entity in present)]
        since = revision(caller, client_name, reference)
        unanswered_again = []
        for name in pending:
            figures['resent'] += 1
            answer = caller.call(request(client_name, reference, 'ADD IND CLASS', name, CLASS),
                                 timeout_s)
            if answer is None:
                unanswered_again.append(name)
            elif not answer.success:
                raise RuntimeError(f'resent ADD {name}: {answer.exit_code} '
                                   f'{answer.error_description}')
        pending = unanswered_again
    return figures


def audit(caller: DefaultClient, reference: str, expected: List[str], adds: Dict[str, int],
          history_missed: int) -> dict:
    """The final check: a QUERY lists every individual once, the history adds none twice."""
    reasoned = caller.must(request('auditor', reference, 'REASON'))
    if not reasoned.success:
        raise RuntimeError(f'REASON: {reasoned.exit_code} {reasoned.error_description}')
    listed = caller.must(request('auditor', reference, 'QUERY IND CLASS', CLASS)).queried_objects
    names = [entity.rsplit('#', 1)[-1].rstrip('>') for entity in listed]
    return {'missing': len(set(expected) - set(names)),
            'unexpected': len(set(names) - set(expected)),
            'listed_twice': len(names) - len(set(names)),
            'applied_twice': sum(1 for n in expected if adds.get(n, 0) > 1),
            'history_missed': history_missed}


# The suite's short variant (make bench) and its smoke run; the script's defaults are the long run.
SUITE_SIZES = {
    'full': {'clients': 8, 'directives': 300, 'flood_directives': 3000, 'quiet_s': 10},
    'smoke': {'clients': 2, 'directives': 20, 'flood_directives': 200, 'quiet_s': 2},
}


# --- the whole measurement, and the table -----------------------------------------------------

def measure(scratch: pathlib.Path, snapshot: CoreSnapshot, clients: int = 8,
            directives: int = 2000, query_every: int = 8, flood_directives: int = 10000,
            flood_per_reference: int = 800, quiet_s: float = 20, timeout_s: float = 30,
            echo: bool = True) -> dict:
    """Figures of the sequential run, the flood on ARMOR and the flood on the bare echo server."""
    import rclpy
    node = BenchNode(scratch, snapshot)  # its ArmorTransport may have started rclpy already
    owns_rclpy = not rclpy.ok()
    if owns_rclpy:
        rclpy.init()
    coordinator = None
    try:
        coordinator = DefaultClient(service_name(node.namespace), 'coordinator')
        results = {'settings': {'clients': clients, 'directives': directives,
                                'query_every': query_every, 'flood': flood_directives,
                                'flood_per_reference': flood_per_reference,
                                'quiet_s': quiet_s, 'timeout_s': timeout_s}}
        progress(f'{clients} sequential clients x {directives} directives')
        results['sequential'] = run_sequential(node.namespace, scratch, clients, directives,
                                               query_every, timeout_s, coordinator)
        progress(f'flood of {flood_directives} on ARMOR')
        results['flood'] = run_flood(node.namespace, flood_directives, flood_per_reference,
                                     quiet_s, timeout_s, coordinator)
        if echo:
            progress(f'flood of {flood_directives} on a bare echo server')
            results['echo_flood'] = run_echo_flood(node.namespace, flood_directives, quiet_s)
        return results
    finally:
        if coordinator is not None:
            coordinator.close()
        node.stop()
        if owns_rclpy:
            rclpy.try_shutdown()


ROWS = (('sequential', 'sequential clients, ARMOR'), ('flood', 'flood, ARMOR'),
        ('echo_flood', 'flood, bare rclpy echo'))


def _cell(value) -> str:
    if value is None:
        return '-'
    return f'{value:,.1f}' if isinstance(value, float) else f'{value:,}'


def _table(header: List[str], rows: List[List[str]]) -> List[str]:
    return ['| ' + ' | '.join(header) + ' |', '|' + '---|' * len(header),
            *['| ' + ' | '.join(row) + ' |' for row in rows]]


def render(results: dict) -> str:
    """The figures as Markdown tables with the ratios that matter."""
    s = results['settings']
    lines = [f'Default service QoS (KEEP_LAST 10), plain rclpy: {s["clients"]} sequential '
             f'clients x {s["directives"]} directives (every {s["query_every"]}th a QUERY, '
             f'{s["timeout_s"]:.0f} s per call); a flood of {s["flood"]:,} ADDs from one '
             f'process, over until no answer for {s["quiet_s"]:.0f} s.', '']
    columns = ('sent', 'answered', 'errors', 'requests_lost', 'answers_lost',
               'unanswered_queries', 'wall_s', 'p50_ms', 'p99_ms')
    lines += _table(['run', 'sent', 'answered', 'answered with an error',
                     'requests lost (never reached the server)',
                     'answers lost (applied, answer never came)', 'queries unanswered',
                     'wall s', 'p50 ms', 'p99 ms'],
                    [[label, *(_cell(results[key][c]) for c in columns)]
                     for key, label in ROWS if key in results])
    lines += ['', 'Recovery of the unanswered ADDs (GET REF CHANGES since the revision read '
              'before starting; resend only what it does not show), then the check:', '']
    columns = ('unanswered_adds', 'applied_via_history', 'resent', 'undecidable',
               'window_missed', 'missing', 'unexpected', 'listed_twice', 'applied_twice',
               'history_missed')
    lines += _table(['run', 'unanswered ADDs', 'found applied via history', 'resent',
                     'undecidable from history (looked up by QUERY)',
                     'revisions no longer kept when the client asked (sum)', 'final missing',
                     'unexpected', 'listed twice by QUERY', 'applied twice (history)',
                     'revisions the audit did not see'],
                    [[label, *(_cell(results[key]['recovery'][c]) for c in columns)]
                     for key, label in ROWS[:2] if key in results])
    lines += ['']
    for key, label in ROWS:
        if key in results:
            r = results[key]
            lines.append(f'- {label}: answered/sent {r["answered"] / r["sent"]:.3f}, '
                         f'{r["answered"] / r["wall_s"]:,.0f} answers/s until the last answer')
    if 'echo_flood' in results:
        armor, echo = results['flood'], results['echo_flood']
        armor_lost = armor['sent'] - armor['answered']
        echo_lost = echo['sent'] - echo['answered']
        lines.append(f'- unanswered in the flood, ARMOR / bare echo: {armor_lost:,} / '
                     f'{echo_lost:,} = {armor_lost / echo_lost:.2f}' if echo_lost else
                     f'- unanswered in the flood, ARMOR / bare echo: {armor_lost:,} / 0')
    return '\n'.join(lines)


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--clients', type=int, default=8)
    parser.add_argument('--directives', type=int, default=2000, help='per sequential client')
    parser.add_argument('--query-every', type=int, default=8,
                        help='every n-th directive of a sequential client is a QUERY (0: none)')
    parser.add_argument('--flood', type=int, default=10000)
    parser.add_argument('--flood-per-reference', type=int, default=800)
    parser.add_argument('--quiet-s', type=float, default=20)
    parser.add_argument('--timeout-s', type=float, default=30)
    parser.add_argument('--no-echo', action='store_true')
    parser.add_argument('--json', action='store_true', help='print the raw figures too')
    parser.add_argument('--as-sequential-client', type=int, help=argparse.SUPPRESS)
    parser.add_argument('--as-echo-server', help=argparse.SUPPRESS)
    parser.add_argument('--service', help=argparse.SUPPRESS)
    parser.add_argument('--out', type=pathlib.Path, help=argparse.SUPPRESS)
    options = parser.parse_args()
    if options.as_echo_server is not None:
        echo_server(options.as_echo_server)
        return
    if options.as_sequential_client is not None:
        sequential_client(options.service, options.as_sequential_client, options.directives,
                          options.query_every, options.timeout_s, options.out)
        return
    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-default-clients-'))
    results = measure(scratch, CoreSnapshot(scratch), options.clients, options.directives,
                      options.query_every, options.flood, options.flood_per_reference,
                      options.quiet_s, options.timeout_s, not options.no_echo)
    if options.json:
        print(json.dumps(results, indent=2))
    print(render(results))


if __name__ == '__main__':
    main()
