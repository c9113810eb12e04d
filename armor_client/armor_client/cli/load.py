# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""Load an ontology file (or URL, with --web) as a new reference.

  armor load REF PATH [--reasoner PELLET] [--iri IRI] [--mount] ...

PATH is made absolute against the current directory, as every client's paths are; the node
reads only inside its allowed_dirs. Loading a name that is loaded from the same file reuses
it. Examples:
  armor load map ontologies/robotics.owl --reasoner PELLET
  armor load web https://example.org/onto.owl --web
Exit status: 0 loaded, 1 refused, 2 usage error, 3 no service.
"""

import argparse
import sys
import threading
import time

from armor_client.cli.common import add_connection_arguments, connect, reporting_errors
from armor_client.paths import absolute


def add_arguments(parser: argparse.ArgumentParser) -> None:
    """Declare the options of armor load.

    Args:
        parser: the verb's parser.
    """
    parser.add_argument('reference', metavar='REF', help='name of the new reference')
    parser.add_argument('source', metavar='PATH', help='ontology file (URL with --web)')
    parser.add_argument('--web', action='store_true',
                        help='PATH is a URL (the node needs web_loading:=true)')
    parser.add_argument('--iri', default='',
                        help='ontology IRI plain names resolve against (default: its own)')
    parser.add_argument('--reasoner', default='',
                        help='HERMIT, PELLET, JFACT, ELK (default: the node\'s)')
    parser.add_argument('--buffered-manipulation', action='store_true',
                        help='queue changes until APPLY or REASON')
    parser.add_argument('--buffered-reasoner', action='store_true',
                        help='the reasoner sees changes only at REASON')
    parser.add_argument('--mount', action='store_true', help='also mount the --client on it')
    add_connection_arguments(parser)


@reporting_errors('load')
def run(args: argparse.Namespace) -> int:
    """Load and say what was loaded.

    Args:
        args: the parsed command line.

    Returns:
        The exit status.
    """
    options = dict(reasoner=args.reasoner, buffered_manipulation=args.buffered_manipulation,
                   buffered_reasoner=args.buffered_reasoner, mount=args.mount)
    with connect(args) as armor:
        bar = _ProgressBar(armor, args.reference) if sys.stderr.isatty() else None
        try:
            if args.web:
                reference = armor.load_web(args.reference, args.source, args.iri, **options)
            else:
                source = absolute(args.source)
                reference = armor.load_file(args.reference, source, args.iri, **options)
        finally:
            if bar:
                bar.stop()
    state = 'consistent' if reference.consistent else 'INCONSISTENT'
    print(f'loaded {args.source} as {args.reference} ({state})')
    return 0


class _ProgressBar:
    """Draws the LOAD's progress on the terminal while it runs (GET LOAD PROGRESS, 2 per s)."""

    WIDTH = 30

    def __init__(self, armor, reference: str):
        self._armor = armor
        self._reference = reference
        self._done = threading.Event()
        self._drawn = False
        self._thread = threading.Thread(target=self._draw, daemon=True)
        self._thread.start()

    def stop(self) -> None:
        self._done.set()
        self._thread.join()
        if self._drawn:
            sys.stderr.write('\r' + ' ' * 79 + '\r')
            sys.stderr.flush()

    def _draw(self) -> None:
        started = time.monotonic()
        while not self._done.wait(0.5):
            try:
                lines = self._armor.load_progress()
            except Exception:  # a progress bar never fails the load it shows
                continue
            mine = [line.split() for line in lines if line.split()[0] == self._reference]
            if not mine or self._done.is_set():
                continue
            _, phase, done, total = mine[0][:4]
            elapsed = time.monotonic() - started
            if phase == 'reading' and int(total) > 0:
                share = min(1.0, int(done) / int(total))
                filled = int(share * self.WIDTH)
                bar = '#' * filled + '-' * (self.WIDTH - filled)
                text = (f'loading {self._reference}: [{bar}] {share:4.0%} '
                        f'{int(done) / 1e6:.1f}/{int(total) / 1e6:.1f} MB {elapsed:.0f} s')
            else:
                text = f'loading {self._reference}: {phase.replace("-", " ")}... {elapsed:.0f} s'
            sys.stderr.write('\r' + text[:79].ljust(79))
            sys.stderr.flush()
            self._drawn = True
