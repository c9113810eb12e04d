# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Round-trip latency of one QUERY over ROS 2 between two processes, against the echo floor.

    python bench/query_latency.py [--calls 1000]

Starts an ARMOR node (robotics.owl preloaded) and a bare rclpy echo service using the same
ArmorDirective message, then alternates calls to both from this process and prints the
median, p99 and the ratio service/floor.
"""

import argparse
import os
import pathlib
import random
import statistics
import subprocess
import sys
import tempfile
import threading
import time

REPO = pathlib.Path(__file__).resolve().parents[1]
os.environ.setdefault('ROS_DOMAIN_ID', str(random.Random(os.getpid()).randint(1, 100)))


def percentile(samples, fraction):
    ordered = sorted(samples)
    return ordered[min(len(ordered) - 1, int(fraction * len(ordered)))]


def main():
    parser = argparse.ArgumentParser(description=__doc__.strip().splitlines()[0])
    parser.add_argument('--calls', type=int, default=1000)
    options = parser.parse_args()

    from armor_client import ArmorTransport, directive
    from armor_client.launch import ArmorNodeProcess
    from armor_msgs.srv import ArmorDirective

    scratch = pathlib.Path(tempfile.mkdtemp(prefix='armor-bench-'))
    node = ArmorNodeProcess(scratch / 'node.log', [
        '-p', f'preload_file:={REPO / "ontologies" / "robotics.owl"}',
        '-p', 'preload_reference:=robotics'])
    echo = subprocess.Popen([sys.executable, str(REPO / 'bench' / 'echo_service.py')])
    armor = ArmorTransport(service_wait_s=120)
    echo_client = armor.node.create_client(ArmorDirective, 'armor_echo_srv')
    try:
        query = directive('bench', 'robotics', 'QUERY', 'IND', 'CLASS', ['OccupiedRoom'])
        assert armor.call(query, timeout_s=120).queried_objects, node.log()
        if not echo_client.wait_for_service(timeout_sec=60):
            raise RuntimeError('echo service did not come up')
        echo_request = ArmorDirective.Request(armor_request=query)

        def call_echo():
            # Waits exactly as ArmorTransport does: the same executor thread, an Event.
            done = threading.Event()
            future = echo_client.call_async(echo_request)
            future.add_done_callback(lambda _: done.set())
            done.wait()
            return future.result()

        for _ in range(50):  # warm-up: discovery, JIT, caches
            armor.call(query)
            call_echo()
        service, floor = [], []
        for _ in range(options.calls):
            start = time.perf_counter()
            armor.call(query)
            service.append(time.perf_counter() - start)
            start = time.perf_counter()
            call_echo()
            floor.append(time.perf_counter() - start)
    finally:
        armor.close()
        echo.terminate()
        echo.wait()
        node.stop()

    def ms(value):
        return f'{value * 1000:.3f} ms'

    print(f'QUERY IND CLASS round trip over ROS 2, two processes, {options.calls} calls each')
    print(f'| path | p50 | p99 |\n|---|---|---|')
    print(f'| ARMOR service | {ms(statistics.median(service))} | {ms(percentile(service, 0.99))} |')
    print(f'| bare rclpy echo (floor) | {ms(statistics.median(floor))} | '
          f'{ms(percentile(floor, 0.99))} |')
    print(f'ratio p50 service/floor: {statistics.median(service) / statistics.median(floor):.2f}')


if __name__ == '__main__':
    main()
