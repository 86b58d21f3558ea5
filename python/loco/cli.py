"""The ``loco`` command line: one subcommand per module of :mod:`loco.commands`."""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from loco import __version__
from loco.commands import COMMAND_MODULES


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="loco", description="Railway vehicle dynamics toolkit")
    parser.add_argument("--version", action="version", version=f"loco {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    for module_name in COMMAND_MODULES:
        module = importlib.import_module(f"loco.commands.{module_name}")
        command = sub.add_parser(module.NAME, help=module.HELP, description=module.HELP)
        module.add_arguments(command)
        command.set_defaults(run=module.run)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    return int(args.run(args))


if __name__ == "__main__":
    sys.exit(main())
