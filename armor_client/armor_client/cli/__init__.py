# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The ``armor`` command. Its verbs are entry points of the group ``armor.verbs``.

A verb is a module: its docstring (the first line is the summary), ``add_arguments(parser)``,
``run(args) -> int``, and optionally ``TRAILING``, a word after which the command line goes to
the verb unparsed as ``args.directive_args`` (``--`` for directive arguments, ``--ros-args``
for ROS arguments). armor_client registers call, load, query, sparql, save, refs, shell and
watch; armor_service registers serve, so this package never imports the server. Another
package adds a verb by declaring one more entry point in its setup.py.
"""

import argparse
import functools
import os
import signal
import sys
from importlib.metadata import entry_points, EntryPoint
from typing import Dict

VERB_GROUP = 'armor.verbs'

# The exit statuses of every verb (scripts test them; README "From the command line").
EXIT_OK = 0
EXIT_FAILED = 1         # ARMOR answered: the directive failed (code and description on stderr)
EXIT_USAGE = 2          # the command line was wrong (as for argparse's own errors)
EXIT_NO_SERVICE = 3     # no ARMOR service answered


@functools.lru_cache(maxsize=1)
def verbs() -> Dict[str, EntryPoint]:
    """Every installed verb, by name (nothing is imported yet; the installed set is read once)."""
    return {point.name: point for point in entry_points(group=VERB_GROUP)}


VERBS = tuple(sorted(verbs()))


def _version() -> str:
    """The one version of the repository (CHANGELOG.md): the installed armor_client's."""
    from importlib.metadata import PackageNotFoundError, version
    try:
        return version('armor_client')
    except PackageNotFoundError:
        return 'unknown (armor_client is not installed)'


def build_parser(only: str = '') -> argparse.ArgumentParser:
    """The parser of every verb, or only of verb `only` (its module alone is imported)."""
    parser = argparse.ArgumentParser(
        prog='armor', description='ARMOR for ROS 2: OWL ontologies with reasoners, as a ROS 2 '
        'service. Run "armor VERB --help" for the details of a verb.')
    parser.add_argument('--version', action='version', version=f'armor {_version()}',
                        help='print the version of ARMOR for ROS 2 and exit')
    subparsers = parser.add_subparsers(dest='verb', metavar='VERB', required=True)
    installed = verbs()
    for name in ([only] if only in installed else sorted(installed)):
        module = installed[name].load()
        summary = module.__doc__.strip().splitlines()[0]
        sub = subparsers.add_parser(name, help=summary, description=module.__doc__.strip(),
                                    formatter_class=argparse.RawDescriptionHelpFormatter)
        module.add_arguments(sub)
        sub.set_defaults(run=module.run)
    return parser


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    # After the verb's marker come arguments that may start with "-": they bypass argparse.
    trailing = []
    point = verbs().get(argv[0]) if argv else None
    marker = getattr(point.load(), 'TRAILING', None) if point is not None else None
    if marker in argv:
        split = argv.index(marker)
        argv, trailing = argv[:split], argv[split + (marker == '--'):]
    # Only the verb's own module: the others import rclpy, which a relayed call never needs.
    args = build_parser(point.name if point is not None else '').parse_args(argv)
    args.directive_args = trailing
    _end_on_sigterm()
    try:
        return args.run(args)
    except KeyboardInterrupt:
        return 128 + signal.SIGINT
    except BrokenPipeError:
        # The reader went away (armor call ... | head): stop quietly, as other tools do; stdout
        # goes nowhere from here, so that flushing it at exit raises nothing either.
        os.dup2(os.open(os.devnull, os.O_WRONLY), sys.stdout.fileno())
        return 128 + signal.SIGPIPE
    except RuntimeError as error:
        print(f'armor {args.verb}: {error}', file=sys.stderr)
        return EXIT_USAGE


def _end_on_sigterm() -> None:
    """SIGTERM ends a verb as Ctrl-C does (`timeout 60 armor call ...` must end at 60 s).

    The verbs start ROS without rclpy's signal handlers (ArmorTransport, the relay, watch):
    this handler leaves through SystemExit, so `with` blocks close the transport in order.
    """
    def terminate(signum, frame):
        raise SystemExit(128 + signum)
    if signal.getsignal(signal.SIGTERM) == signal.SIG_DFL:
        signal.signal(signal.SIGTERM, terminate)


if __name__ == '__main__':
    sys.exit(main())
