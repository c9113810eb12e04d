# Copyright 2026 The ARMOR for ROS 2 authors. Licensed under the Apache License 2.0.
"""The ``armor`` command: one verb per module, each with add_arguments() and run()."""

import argparse
import importlib
import signal
import sys

VERBS = ('serve', 'call', 'load', 'query', 'sparql', 'save', 'refs', 'shell')


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
    verbs = parser.add_subparsers(dest='verb', metavar='VERB', required=True)
    for name in ([only] if only in VERBS else VERBS):
        module = importlib.import_module(f'armor_client.cli.{name}')
        summary = module.__doc__.strip().splitlines()[0]
        sub = verbs.add_parser(name, help=summary, description=module.__doc__.strip(),
                               formatter_class=argparse.RawDescriptionHelpFormatter)
        module.add_arguments(sub)
        sub.set_defaults(run=module.run)
    return parser


def main(argv=None) -> int:
    argv = list(sys.argv[1:] if argv is None else argv)
    # After a lone "--" come directive arguments, after "--ros-args" ROS arguments: either may
    # start with "-", so they bypass argparse.
    trailing = []
    marker = {'call': '--', 'query': '--', 'serve': '--ros-args'}.get(argv[0] if argv else '')
    if marker in argv:
        split = argv.index(marker)
        argv, trailing = argv[:split], argv[split + (marker == '--'):]
    # Only the verb's own module: the others import rclpy, which a relayed call never needs.
    args = build_parser(argv[0] if argv and argv[0] in VERBS else '').parse_args(argv)
    args.directive_args = trailing
    try:
        return args.run(args)
    except KeyboardInterrupt:
        return 128 + signal.SIGINT
    except RuntimeError as error:
        print(f'armor {args.verb}: {error}', file=sys.stderr)
        return 2


if __name__ == '__main__':
    sys.exit(main())
