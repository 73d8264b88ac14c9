"""Every ``hltl`` command shown in the README and docs/ runs and succeeds, in document order."""

from __future__ import annotations

import re
import shlex
from pathlib import Path

import pytest

from hltl.bench.grounding import PARTS
from hltl.cli.main import main
from tests.grounding.test_paraphrase import MEASURED_ONLY

ROOT = Path(__file__).resolve().parents[1]
DOCS = [ROOT / "README.md", *sorted((ROOT / "docs").glob("*.md"))]
FENCE = re.compile(r"```(?:bash|sh|console)\n(.*?)```", re.DOTALL)
SKIP_PREFIXES = ("./setup.sh", ".venv/bin/python", "pip ", "export ", "HLTL_")
SYNOPSIS_MARKS = ("[-", "…", "...", " | ", "<")


def commands(doc: Path) -> list[list[str]]:
    """The hltl command lines of a document's shell blocks, as argv lists without 'hltl'."""
    out: list[list[str]] = []
    for block in FENCE.findall(doc.read_text(encoding="utf-8")):
        for raw in block.replace("\\\n", " ").splitlines():
            line = raw.strip()
            if not line or line.startswith("#"):
                continue
            if any(mark in line for mark in SYNOPSIS_MARKS):
                continue  # a usage synopsis such as "hltl plan --scene S [--json]", not a command
            for part in line.split("&&"):
                if part.strip().startswith(SKIP_PREFIXES):
                    continue
                argv = shlex.split(part.strip())
                if argv and argv[0] in (".venv/bin/hltl", "hltl"):
                    out.append(argv[1:])
    return out


DOCS_WITH_COMMANDS = [d for d in DOCS if commands(d)]


def test_the_readme_opens_with_install_and_test_commands() -> None:
    text = (ROOT / "README.md").read_text(encoding="utf-8")
    first = FENCE.search(text)
    assert first is not None and text.index(first.group(0)) < 200
    lines = [ln for ln in first.group(1).splitlines() if ln.strip()]
    assert lines == [
        "./setup.sh && .venv/bin/hltl demo",
        ".venv/bin/python -m pytest -q -n 2",
    ]
    ci = (ROOT / ".ci" / "run").read_text(encoding="utf-8")
    assert "./setup.sh" in ci and ".venv/bin/python -m pytest -q -n 2" in ci


def _option(argv: list[str], name: str, value: str) -> list[str]:
    if name in argv:
        argv[argv.index(name) + 1] = value
        return argv
    return [*argv, name, value]


def _small(argv: list[str], tmp_path: Path) -> list[str]:
    """A benchmark as documented, shrunk to one trial of one small configuration (the full runs
    are what docs/benchmarks.md records), writing into tmp_path."""
    argv = list(argv)
    if "--write" in argv:
        argv[argv.index("--write") + 1] = str(tmp_path / "bench.md")
    if argv[1] in ("suite", "ablation"):
        argv = _option(argv, "--trials", "1")
        argv = _option(argv, "--configs", "1-2")
        argv = _option(argv, "--jobs", "1")
    if argv[1] == "motion":
        argv = [*argv, "--quick"]
    if argv[1] == "grounding" and "--write" not in argv:
        # the held-back part is measured once, at its session's end, by the one engineer who
        # may: never by a test (a --show would print its misses into a failure's log)
        argv = _option(argv, "--parts", ",".join(p for p in PARTS if p not in MEASURED_ONLY))
    if argv[1] == "suite":
        argv = _option(argv, "--flat-sweep", "1,2")
        argv = _option(argv, "--flat-trials", "1")
    for flag in ("--figures", "--json"):
        if flag in argv:
            argv[argv.index(flag) + 1] = str(tmp_path / flag.strip("-"))
    return argv


@pytest.mark.parametrize("doc", DOCS_WITH_COMMANDS, ids=lambda d: d.name)
def test_documented_commands_run(
    doc: Path, tmp_path: Path, monkeypatch: pytest.MonkeyPatch
) -> None:
    # run where the docs expect to be (repository root) but write outputs under tmp_path
    (tmp_path / "examples").symlink_to(ROOT / "examples")
    (tmp_path / "docs").mkdir()
    monkeypatch.chdir(tmp_path)
    # motion commands: coarse reachability maps, cached under tmp_path
    monkeypatch.setenv("HLTL_CACHE", str(tmp_path / "cache"))
    monkeypatch.setenv("HLTL_REACH_RESOLUTION", "0.1")
    for argv in commands(doc):
        if argv[:1] == ["demo"]:
            argv = [*argv, "--short", "--out", str(tmp_path / "demo")]
        if argv[:1] == ["bench"]:
            argv = _small(argv, tmp_path)
        code = main(argv)
        assert code == 0, f"{doc.name}: 'hltl {shlex.join(argv)}' exited {code}"
