"""Subcommands of the ``loco`` CLI.

Each module listed here defines ``NAME`` (the subcommand), ``HELP`` (one line),
``add_arguments(parser)`` and ``run(args) -> int`` (the exit code).
"""

COMMAND_MODULES: list[str] = [
    "contact_report",
    "info",
    "simulate",
    "batch",
    "assess",
    "damper_bench",
    "frf",
    "reproduce",
    "campaign",
    "curving",
]
