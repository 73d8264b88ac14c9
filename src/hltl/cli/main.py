"""Entry point of the ``hltl`` command: argument parsing, error reporting, exit codes."""

from __future__ import annotations

import argparse
import importlib
import sys
import traceback
from collections.abc import Sequence

from hltl import __version__
from hltl.cli.common import error_line
from hltl.errors import HltlError

# Subcommands live in their own modules (``hltl.cli.<module>``), each exposing
# ``register(subparsers) -> None`` that adds its parser and sets ``func=run(args) -> int``.
# A module that is not there yet is simply not offered.
COMMAND_MODULES = (
    "check_spec",
    "ground",
    "plan",
    "run",
    "score",
    "demo",
    "viz",
    "bench",
    "render",
    "perception",
    "perceive",
    "motion",
)

EXIT_OK, EXIT_FAILURE, EXIT_USAGE = 0, 1, 2


def build_parser() -> argparse.ArgumentParser:
    parser = argparse.ArgumentParser(
        prog="hltl",
        description="Instructions to makespan-optimal multi-robot handover plans via H-LTLf.",
    )
    parser.add_argument("--version", action="version", version=f"hltl {__version__}")
    parser.add_argument("--debug", action="store_true", help="show tracebacks for errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name in COMMAND_MODULES:
        try:
            module = importlib.import_module(f"hltl.cli.{name}")
        except ModuleNotFoundError as exc:
            if exc.name == f"hltl.cli.{name}":
                continue
            raise
        module.register(sub)
    return parser


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; returns the exit code (0 ok, 1 failure, 2 usage)."""
    parser = build_parser()
    try:
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on usage errors, 0 on --help/--version
        return int(exc.code or 0)
    if args.command is None:
        parser.print_help(sys.stderr)
        return EXIT_USAGE
    try:
        return int(args.func(args))
    except HltlError as exc:
        if args.debug:
            traceback.print_exc()
        print(f"error: {error_line(str(exc))}", file=sys.stderr)
        return EXIT_FAILURE
    except KeyboardInterrupt:
        print("error: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # the reader went away (e.g. '| head'): stop quietly, as Unix tools do
        import os

        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return EXIT_OK
    except (RecursionError, MemoryError, UnicodeError, OSError) as exc:
        # a defect (input that should have been refused with a clear message earlier), still
        # reported as one line; --debug shows where
        if args.debug:
            traceback.print_exc()
        text = error_line(f"{type(exc).__name__}: {exc}")
        print(f"error: {text} (unexpected; rerun with --debug and report it)", file=sys.stderr)
        return EXIT_FAILURE


if __name__ == "__main__":
    raise SystemExit(main())
