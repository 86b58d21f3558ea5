"""The ``loco`` command line: one subcommand per module of :mod:`loco.commands`.

Exit codes: 0 done; 2 a usage error (an unknown option, a value out of range, an output path that
cannot be written: argparse's message, no traceback) or a parameter loco refuses
(:class:`loco.ParameterError`); 1 any other failure loco reports (a run that diverged, a file it
cannot read), with its message; 130 interrupted (Ctrl-C).
"""

from __future__ import annotations

import argparse
import importlib
import sys
from collections.abc import Sequence

from loco import __version__
from loco._loco import LocoError, ParameterError
from loco.commands import COMMAND_MODULES
from loco.commands.arguments import UsageError


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(prog="loco", description="Railway vehicle dynamics toolkit")
    parser.add_argument("--version", action="version", version=f"loco {__version__}")
    sub = parser.add_subparsers(dest="command", required=True)
    for module_name in COMMAND_MODULES:
        module = importlib.import_module(f"loco.commands.{module_name}")
        command = sub.add_parser(module.NAME, help=module.HELP, description=module.HELP)
        module.add_arguments(command)
        command.set_defaults(run=module.run, command_parser=command)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    args = build_parser().parse_args(argv)
    command: argparse.ArgumentParser = args.command_parser
    try:
        return int(args.run(args))
    except UsageError as e:
        command.error(str(e))  # exits with 2
    except ParameterError as e:
        print(f"{command.prog}: error: {e}", file=sys.stderr)
        return 2
    except (LocoError, OSError) as e:
        print(f"{command.prog}: error: {e}", file=sys.stderr)
        return 1
    except KeyboardInterrupt:
        print(f"{command.prog}: interrupted", file=sys.stderr)
        return 130
    return 1  # not reached: command.error exits


if __name__ == "__main__":
    sys.exit(main())
