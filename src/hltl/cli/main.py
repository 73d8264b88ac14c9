"""Entry point of the ``hltl`` command: argument parsing, error reporting, exit codes."""

from __future__ import annotations

import argparse
import gc
import importlib
import os
import sys
from collections.abc import Sequence
from typing import Any

from hltl import __version__
from hltl.errors import HltlError, error_line

# One entry per subcommand: name -> (its module under hltl.cli, the one-line help `hltl --help`
# lists). The module, which exposes ``register(subparsers)`` adding its parser with
# ``func=run(args) -> int``, is imported only when its command runs or its --help is asked for,
# so `hltl --help` and a small `hltl plan` start fast (docs/benchmarks.md, "Start-up").
COMMANDS: dict[str, tuple[str, str]] = {
    "check-spec": ("check_spec", "validate H-LTLf specification files"),
    "ground": ("ground", "turn an instruction into an H-LTLf spec"),
    "plan": ("plan", "find a makespan-optimal plan"),
    "run": ("run", "run one closed-loop episode in the simulator"),
    "score": ("score", "recompute metrics from an execution log"),
    "demo": ("demo", "run the paper's Fig. 1 episode and draw it"),
    "viz": ("viz", "draw a plan, an execution log or a spec"),
    "bench": ("bench", "benchmarks"),
    "render": (
        "render",
        "render a scene's RGB-D camera (RGB, depth, segmentation) to a frame folder",
    ),
    "perception": ("perception", "train and evaluate the trajectory predictors"),
    "perceive": ("perceive", "objects in 3D and tracked people from an RGB-D frame folder"),
    "motion": (
        "motion",
        "arm kinematics: handover poses, comfort zones, skill motions, reachability maps",
    ),
    "node": ("node", "run the simulator or the perception stage as a node on the Zenoh bus"),
}

EXIT_OK, EXIT_FAILURE, EXIT_USAGE = 0, 1, 2

# Commands after which `hltl` (the program, not a ``main(argv)`` call) leaves its objects to
# the OS: ``gc.freeze()`` as the command returns, so Python's collections at exit walk none of
# them (~25 ms of a small `hltl plan`, docs/planner.md "Start-up"). Only commands that hold no
# resource whose release waits for the collector (a bus session, a simulator): atexit
# handlers still run and stdout is still flushed, only cyclic garbage is not collected.
FREEZE_AT_EXIT = frozenset({"plan", "check-spec"})


def _columns() -> int:
    # shutil.get_terminal_size().columns, as argparse asks it, without importing shutil (with
    # bz2 and lzma, ~3 ms of every start): $COLUMNS, else stdout's terminal, else 80
    try:
        columns = int(os.environ["COLUMNS"])
    except (KeyError, ValueError):
        columns = 0
    if columns <= 0:
        try:
            columns = os.get_terminal_size(sys.__stdout__.fileno()).columns  # type: ignore[union-attr]
        except (AttributeError, ValueError, OSError):
            columns = 0
    return columns or 80


class _Formatter(argparse.HelpFormatter):
    """argparse's help layout, its width found without shutil (``_columns``)."""

    def __init__(
        self,
        prog: str,
        indent_increment: int = 2,
        max_help_position: int = 24,
        width: int | None = None,
    ) -> None:
        super().__init__(
            prog, indent_increment, max_help_position, _columns() - 2 if width is None else width
        )


class _Parser(argparse.ArgumentParser):
    """An ArgumentParser (and its subcommands' parsers) with ``_Formatter``."""

    def __init__(self, *args: Any, **kwargs: Any) -> None:
        kwargs.setdefault("formatter_class", _Formatter)
        super().__init__(*args, **kwargs)


def build_parser(command: str | None = None, *, others: bool = True) -> argparse.ArgumentParser:
    """The parser; only ``command``'s module is imported (the others are listed by name, or,
    with ``others`` false and a ``command``, left out)."""
    parser = _Parser(
        prog="hltl",
        description="Instructions to makespan-optimal multi-robot handover plans via H-LTLf.",
    )
    parser.add_argument("--version", action="version", version=f"hltl {__version__}")
    parser.add_argument("--debug", action="store_true", help="show tracebacks for errors")
    sub = parser.add_subparsers(dest="command", metavar="COMMAND")
    for name, (module_name, help_) in COMMANDS.items():
        if name == command:
            importlib.import_module(f"hltl.cli.{module_name}").register(sub)
        elif others or command is None:
            sub.add_parser(name, help=help_, add_help=False)
    return parser


def chosen_command(argv: Sequence[str]) -> str | None:
    """The subcommand in ``argv``: its first word that is not a top-level option."""
    for arg in argv:
        if not arg.startswith("-"):
            return arg if arg in COMMANDS else None
    return None


def main(argv: Sequence[str] | None = None) -> int:
    """Run the CLI; returns the exit code (0 ok, 1 failure, 2 usage)."""
    program = argv is None  # (the process ends when this returns)
    argv = sys.argv[1:] if argv is None else list(argv)
    # Importing the command's modules allocates ~100k objects that live as long as the process
    # and none is garbage: the collector, left on, walks them ~40 times (~10 ms of `hltl plan`)
    collecting = gc.isenabled()
    gc.disable()
    try:
        command = chosen_command(argv)
        # the other commands show only in the top-level help (`hltl --help plan`): a command
        # line with nothing but --debug before its command needs none of their 13 parsers
        # (~2 ms of start-up, docs/planner.md "Start-up")
        others = command is None or any(a != "--debug" for a in argv[: argv.index(command)])
        parser = build_parser(command, others=others)
        args = parser.parse_args(argv)
    except SystemExit as exc:  # argparse exits 2 on usage errors, 0 on --help/--version
        return int(exc.code or 0)
    finally:
        if collecting:
            gc.enable()
    if args.command is None:
        parser.print_help(sys.stderr)
        return EXIT_USAGE
    args.program = program  # (a command run as the program may freeze its heap once set up)
    if not (program and args.command in FREEZE_AT_EXIT):
        return _run(args)
    try:
        return _run(args)
    finally:
        gc.freeze()


def _run(args: argparse.Namespace) -> int:
    """The chosen command, its errors reported as one line."""
    try:
        return int(args.func(args))
    except HltlError as exc:
        if args.debug:
            _print_traceback()
        print(f"error: {error_line(str(exc))}", file=sys.stderr)
        return EXIT_FAILURE
    except KeyboardInterrupt:
        print("error: interrupted", file=sys.stderr)
        return 130
    except BrokenPipeError:
        # the reader went away (e.g. '| head'): stop quietly, as Unix tools do
        devnull = os.open(os.devnull, os.O_WRONLY)
        os.dup2(devnull, sys.stdout.fileno())
        return EXIT_OK
    except (RecursionError, MemoryError, UnicodeError, OSError) as exc:
        # a defect (input that should have been refused with a clear message earlier), still
        # reported as one line; --debug shows where
        if args.debug:
            _print_traceback()
        text = error_line(f"{type(exc).__name__}: {exc}")
        print(f"error: {text} (unexpected; rerun with --debug and report it)", file=sys.stderr)
        return EXIT_FAILURE


def _print_traceback() -> None:
    import traceback  # (only --debug prints one: a few ms of every start-up otherwise)

    traceback.print_exc()


if __name__ == "__main__":
    raise SystemExit(main())
