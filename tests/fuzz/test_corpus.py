"""The bad-input corpus: every command and input kind ends in one clear, bounded error line.

Each case is a reproduction from issue 18 or its neighbour: files written into a fresh folder,
then ``hltl ARGV`` run in-process (exit 1, exactly one ``error:`` line naming the input, no
traceback, bounded length, memory and time; see conftest.py).
"""

from __future__ import annotations

import json
import subprocess
import sys
from collections.abc import Callable
from dataclasses import dataclass, field
from pathlib import Path

import pytest

from .conftest import ROOT, SCENE, SPEC, assert_one_error, run_cli

SCENE_TEXT = SCENE.read_text(encoding="utf-8")
SPEC_TEXT = SPEC.read_text(encoding="utf-8")
LATIN1 = 'root: p0\nformulas:\n  p0: "F delivered(bottle, A)"  # caf\xe9\n'.encode("latin-1")
BOMB = "a: &a [x, x, x, x, x, x, x, x, x]\n" + "".join(
    f"{b}: &{b} [{', '.join([f'*{a}'] * 9)}]\n" for a, b in zip("abcdefg", "bcdefgh", strict=False)
)
WORDS = " ".join(["bottle"] * 10_000)


def nested_x(n: int) -> str:
    return "X " * n + "delivered(bottle, A)"


def spec_with(formula: str) -> str:
    return f"root: p0\nformulas:\n  p0: {json.dumps(formula)}\n"


def events(*items: str) -> str:
    return "events:\n" + "".join(f"  - {i}\n" for i in items)


@dataclass(frozen=True)
class Case:
    """Files to write (name -> content) and the command line ({name} stands for a file)."""

    id: str
    argv: tuple[str, ...]
    files: dict[str, str | bytes] = field(default_factory=dict)
    needles: tuple[str, ...] = ()


RUN = ("run", "--scene", str(SCENE), "--instruction", "Give Person A the bottle")
GROUND = ("ground", "--scene", str(SCENE), "--instruction")
PLAN_SPEC = ("plan", "--scene", str(SCENE), "--spec")

CASES = [
    # -- encoding: every command that reads a file (issue 18, item 7) ---------------------------
    Case("utf8-plan-spec", (*PLAN_SPEC, "{s.yaml}"), {"s.yaml": LATIN1}, ("not UTF-8", "line 3")),
    Case("utf8-check-spec", ("check-spec", "{s.yaml}"), {"s.yaml": LATIN1}, ("not UTF-8",)),
    Case(
        "utf8-ground-running",
        (*GROUND, "also give B the chips", "--running", "{s.yaml}"),
        {"s.yaml": LATIN1},
        ("s.yaml", "not UTF-8"),
    ),
    Case("utf8-run-events", (*RUN, "--events", "{e.yaml}"), {"e.yaml": b"events: [\xff]"}),
    Case("utf8-score", ("score", "{l.jsonl}"), {"l.jsonl": b'{"t": 0, "type": "\xe9"}\n'}),
    Case("utf8-viz", ("viz", "{p.json}", "-o", "{out}"), {"p.json": b"\xfe\xff{}"}),
    Case("utf8-scene", ("plan", "--scene", "{sc.yaml}", "--spec", str(SPEC)), {"sc.yaml": b"\x81"}),
    # -- sizes and quoting (item 5) -------------------------------------------------------------
    Case("alias-bomb-spec", ("check-spec", "{s.yaml}"), {"s.yaml": BOMB}, ("expands to more",)),
    Case(
        "alias-bomb-in-formula",
        ("check-spec", "{s.yaml}"),
        {"s.yaml": BOMB + "root: p0\nformulas: {p0: *h}\n"},
        ("expands to more",),
    ),
    Case(
        "alias-bomb-scene", ("plan", "--scene", "{sc.yaml}", "--spec", str(SPEC)), {"sc.yaml": BOMB}
    ),
    Case("alias-bomb-events", (*RUN, "--events", "{e.yaml}"), {"e.yaml": BOMB}),
    Case("huge-file", ("check-spec", "{s.yaml}"), {"s.yaml": "# x\n" * 300_000}, ("larger than",)),
    Case("long-instruction-plan", ("plan", "--scene", str(SCENE), "--instruction", WORDS)),
    Case("long-instruction-ground", ("ground", "--scene", str(SCENE), "--instruction", WORDS)),
    Case(
        "long-instruction-event",
        (*RUN, "--events", "{e.yaml}"),
        {"e.yaml": events(f"{{t: 1, type: instruction, text: {json.dumps(WORDS)}}}")},
        ("at most 2,000 characters",),
    ),
    Case(
        "long-id-scene",
        ("plan", "--scene", "{sc.yaml}", "--spec", str(SPEC)),
        {"sc.yaml": SCENE_TEXT.replace("id: r1", "id: " + "r" * 50_000)},
    ),
    Case(
        "long-formula-name",
        ("check-spec", "{s.yaml}"),
        {"s.yaml": f"root: p0\nformulas:\n  p0: F {'q' * 50_000}\n"},
    ),
    Case("deep-yaml", ("check-spec", "{s.yaml}"), {"s.yaml": "[" * 5_000 + "]" * 5_000}, ("deep",)),
    Case("deep-json", ("check-spec", "{s.json}"), {"s.json": "[" * 5_000 + "]" * 5_000}, ("deep",)),
    Case("deep-log-line", ("score", "{l.jsonl}"), {"l.jsonl": "[" * 100_000 + "]" * 100_000}),
    # -- YAML strictness and values (item 9) ----------------------------------------------------
    Case(
        "duplicate-formula",
        ("check-spec", "{s.yaml}"),
        {"s.yaml": SPEC_TEXT + '  p100: "F delivered(chips, A)"\n'},
        ("duplicate key 'p100'", "line"),
    ),
    Case(
        "duplicate-json-key",
        ("check-spec", "{s.json}"),
        {"s.json": '{"root": "p0", "root": "p1", "formulas": {}}'},
        ("duplicate key 'root'",),
    ),
    Case(
        "duplicate-scene-key",
        ("plan", "--scene", "{sc.yaml}", "--spec", str(SPEC)),
        {"sc.yaml": SCENE_TEXT + "units: cm\n"},
        ("duplicate key 'units'",),
    ),
    Case(
        "bool-coordinate",
        ("plan", "--scene", "{sc.yaml}", "--spec", str(SPEC)),
        {
            "sc.yaml": SCENE_TEXT.replace(
                "position: [-0.4, 0.2, 0.05]", "position: [true, 0.2, 0.05]"
            )
        },
        ("objects[0].position", "expected a number, got true"),
    ),
    Case(
        "bool-reach",
        ("plan", "--scene", "{sc.yaml}", "--spec", str(SPEC)),
        {"sc.yaml": SCENE_TEXT.replace("reach: 0.7", "reach: yes")},
        ("robots[0].reach",),
    ),
    Case(
        "nan-scene",
        ("plan", "--scene", "{sc.yaml}", "--spec", str(SPEC)),
        {"sc.yaml": SCENE_TEXT.replace("reach: 0.7", "reach: .nan")},
        ("robots[0].reach",),
    ),
    Case(
        "unknown-duration-skill",
        ("plan", "--scene", "{sc.yaml}", "--spec", str(SPEC)),
        {"sc.yaml": SCENE_TEXT.replace("place: 0.5", "plase: 0.5")},
        ("sc.yaml", "durations", "unknown skill 'plase'"),
    ),
    Case(
        "huge-time-event",
        (*RUN, "--events", "{e.yaml}"),
        {"e.yaml": events("{t: 1.0e300, type: human_move, human: A, to: [0.2, 0.3, 0.0]}")},
        ("events[0].t", "must be <= 1e+06"),
    ),
    Case(
        "wander-forever",
        (*RUN, "--events", "{e.yaml}"),
        {"e.yaml": events("{t: 0, type: human_wander, human: A, duration: 1.0e7}")},
        ("events[0].duration", "must be <= 1e+06"),
    ),
    Case(
        "wander-tiny-legs",
        (*RUN, "--events", "{e.yaml}"),
        {"e.yaml": events("{t: 0, type: human_wander, human: A, duration: 100, leg: 1e-9}")},
        ("events[0].leg",),
    ),
    Case(
        "too-many-events",
        (*RUN, "--events", "{e.json}"),
        {"e.json": json.dumps({"events": [{"t": 1, "type": "robot_down"}] * 10_001})},
        ("at most 10,000",),
    ),
    Case("emoji-instruction", ("plan", "--scene", str(SCENE), "--instruction", "🍾🍾 ➡️ 👩")),
    Case("cyrillic-instruction", ("ground", "--scene", str(SCENE), "--instruction", "дай бутылку")),
    # -- options --------------------------------------------------------------------------------
    Case("nan-timeout", (*PLAN_SPEC, str(SPEC), "--timeout", "nan"), {}, ("--timeout", "nan")),
    Case("inf-timeout", (*PLAN_SPEC, str(SPEC), "--timeout", "inf"), {}, ("--timeout",)),
    Case("nan-max-time", (*RUN, "--max-time", "nan"), {}, ("--max-time",)),
    Case("inf-noise", (*RUN, "--noise", "inf"), {}, ("--noise",)),
    Case("negative-latency", (*RUN, "--latency", "-1"), {}, ("--latency",)),
    Case("nan-plan-latency", (*RUN, "--plan-latency", "nan"), {}, ("--plan-latency",)),
    # -- formulas (item 8) ----------------------------------------------------------------------
    Case("nested-x", ("check-spec", "{s.yaml}"), {"s.yaml": spec_with(nested_x(500))}, ("deep",)),
    Case(
        "parentheses",
        ("check-spec", "{s.yaml}"),
        {"s.yaml": spec_with("(" * 3000 + "F delivered(bottle, A)" + ")" * 3000)},
        ("deep",),
    ),
    Case(
        "disjuncts",
        ("check-spec", "{s.yaml}"),
        {"s.yaml": spec_with(" | ".join(["F delivered(bottle, A)"] * 1500))},
    ),
    Case(
        "long-bad-formula",
        ("check-spec", "{s.yaml}"),
        {"s.yaml": spec_with("F delivered(bottle, A) & " * 300 + "&")},
        ("unexpected",),
    ),
    # -- outputs (item 8) -----------------------------------------------------------------------
    Case("log-is-folder", (*RUN, "--log", "{dir}"), {}, ("it is a folder",)),
    Case("log-under-file", (*RUN, "--log", "{f.txt}/log.jsonl"), {"f.txt": "x"}, ("cannot write",)),
    Case("plan-out-folder", (*PLAN_SPEC, str(SPEC), "-o", "{dir}"), {}, ("it is a folder",)),
    Case(
        "ground-out-under-file",
        (*GROUND, "give A the bottle", "-o", "{f.txt}/x.yaml"),
        {"f.txt": "x"},
        ("cannot write",),
    ),
    # -- other bad files ------------------------------------------------------------------------
    Case("missing-spec", (*PLAN_SPEC, "{nothing.yaml}"), {}, ("nothing.yaml", "cannot read")),
    Case("spec-is-folder", ("check-spec", "{dir}"), {}, ("cannot read",)),
    Case("empty-log", ("score", "{l.jsonl}"), {"l.jsonl": ""}),
    Case(
        "garbage-log", ("score", "{l.jsonl}"), {"l.jsonl": '{"t": 0, "type": "episode_start"}\n}{'}
    ),
    Case("empty-viz", ("viz", "{p.json}", "-o", "{out}"), {"p.json": "   "}),
    Case(
        "spec-chain-5000",
        ("check-spec", "{s.yaml}"),
        {"s.yaml": "root: p0\nformulas:\n" + "".join(f"  p{i}: F p{i + 1}\n" for i in range(5000))},
        ("5,000 formulas",),
    ),
    Case(
        "spec-chain-1000",
        ("check-spec", "{s.yaml}"),
        {
            "s.yaml": "root: p0\nformulas:\n"
            + "".join(f"  p{i}: F p{i + 1}\n" for i in range(999))
            + "  p999: F delivered(bottle, A)\n"
        },
        ("1000 levels",),
    ),
    Case(
        "long-root",
        ("check-spec", "{s.yaml}"),
        {"s.yaml": SPEC_TEXT.replace("root: p0", "root: " + "x" * 5000)},
        ("root 'xxx",),
    ),
    Case(
        "events-type-list", (*RUN, "--events", "{e.yaml}"), {"e.yaml": events("{t: 1, type: []}")}
    ),
    Case("nul-byte-spec", ("check-spec", "{s.yaml}"), {"s.yaml": b"\x00"}, ("not valid YAML",)),
    Case("binary-events", (*RUN, "--events", "{e.yaml}"), {"e.yaml": bytes(range(256))}),
    Case("events-not-list", (*RUN, "--events", "{e.yaml}"), {"e.yaml": "events: 3\n"}),
]


def _materialise(case: Case, tmp_path: Path) -> list[str]:
    for name, content in case.files.items():
        p = tmp_path / name
        if isinstance(content, bytes):
            p.write_bytes(content)
        else:
            p.write_text(content, encoding="utf-8")
    (tmp_path / "dir").mkdir(exist_ok=True)
    names = {**{n: str(tmp_path / n) for n in case.files}, "dir": str(tmp_path / "dir")}
    names["out"] = str(tmp_path / "out")
    names["nothing.yaml"] = str(tmp_path / "nothing.yaml")
    argv = []
    for arg in case.argv:
        for name, path in names.items():
            arg = arg.replace("{" + name + "}", path)
        argv.append(arg)
    return argv


@pytest.mark.parametrize("case", CASES, ids=[c.id for c in CASES])
def test_bad_input_gives_one_clear_error(case: Case, tmp_path: Path) -> None:
    argv = _materialise(case, tmp_path)
    assert_one_error(run_cli(argv), *case.needles)


def test_quoted_values_show_start_and_length(tmp_path: Path) -> None:
    argv = _materialise(CASES[[c.id for c in CASES].index("long-id-scene")], tmp_path)
    line = assert_one_error(run_cli(argv))
    assert "(50,000 characters)" in line and len(line) < 400


def test_long_wander_runs_lazily(tmp_path: Path) -> None:
    """A wander of 1e6 s (the bound) costs what the episode lives through, not 1e6 legs."""
    e = tmp_path / "e.yaml"
    e.write_text(events("{t: 0, type: human_wander, human: B, duration: 1.0e6, leg: 0.01}"))
    result = run_cli([*RUN, "--events", str(e), "--max-time", "20", "--json"])
    assert result.code == 0, result.err
    assert result.peak < 100 << 20


def test_yaml_reads_exponent_floats_as_numbers(tmp_path: Path) -> None:
    """YAML 1.1 reads 1.0e2 as a string; hltl's files follow YAML 1.2 (and JSON) there."""
    e = tmp_path / "e.yaml"
    e.write_text(events("{t: 1.0e-1, type: human_move, human: A, to: [0.2, 0.3, 0.0]}"))
    result = run_cli([*RUN, "--events", str(e), "--json"])
    assert result.code == 0, result.err


Runner = Callable[[list[str]], subprocess.CompletedProcess[str]]


@pytest.mark.parametrize(
    "case_id", ["utf8-check-spec", "deep-log-line", "nested-x", "log-is-folder"]
)
def test_no_traceback_from_the_real_command(case_id: str, tmp_path: Path) -> None:
    """A few cases through a real process: what a user sees, including interpreter exit."""
    argv = _materialise(CASES[[c.id for c in CASES].index(case_id)], tmp_path)
    proc = subprocess.run(
        [sys.executable, "-m", "hltl.cli.main", *argv],
        capture_output=True,
        text=True,
        timeout=300,
        cwd=ROOT,
        check=False,
    )
    assert proc.returncode == 1, proc.stderr[-2000:]
    lines = [ln for ln in proc.stderr.splitlines() if ln.strip()]
    assert len(lines) == 1 and lines[0].startswith("error: "), proc.stderr[-2000:]
