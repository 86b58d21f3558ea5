"""``loco info``: version and build information."""

from __future__ import annotations

import argparse
import platform

import loco

NAME = "info"
HELP = "print the version of loco and of its native core"


def add_arguments(parser: argparse.ArgumentParser) -> None:
    del parser  # no options


def run(args: argparse.Namespace) -> int:
    del args
    print(f"loco {loco.__version__} (Python {platform.python_version()}, {platform.machine()})")
    return 0
