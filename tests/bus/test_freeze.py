"""A set-up process's heap is frozen before its episodes (docs/bus.md, "Where the time goes
(session 27)"): the collector's full collections no longer walk it. Only as the program (a
process of its own): called from a process that goes on (tests), nothing is frozen."""

from __future__ import annotations

import gc
import sys
import threading
from collections.abc import Iterator
from pathlib import Path

import pytest

from hltl.bus.node import CellNode, serve
from hltl.cli.main import main
from hltl.sim.scenarios import get
from tests.bus.helpers import Loopback

ROOT = Path(__file__).resolve().parents[2]
RUN = ["run", "--scene", str(ROOT / "examples" / "scenes" / "two_arms.yaml")]
RUN += ["--instruction", "Give Person A the bottle", "--json"]


@pytest.fixture
def unfrozen() -> Iterator[None]:
    """No frozen objects before the test, and none left after it (this process goes on)."""
    gc.unfreeze()
    try:
        yield
    finally:
        gc.unfreeze()


@pytest.mark.parametrize("freeze", [True, False])
def test_a_node_freezes_its_heap_once_set_up(
    loopback: Loopback, unfrozen: None, freeze: bool
) -> None:
    frozen: list[int] = []
    stop = threading.Event()

    def ready(node: CellNode) -> None:
        frozen.append(gc.get_freeze_count())
        stop.set()

    serve(loopback._node_session, get("fig1").scene, stop=stop, on_ready=ready, freeze=freeze)
    assert frozen and (frozen[0] > 0) is freeze


def test_hltl_run_as_the_program_freezes_its_heap(
    unfrozen: None, monkeypatch: pytest.MonkeyPatch, capsys: pytest.CaptureFixture[str]
) -> None:
    monkeypatch.setattr(sys, "argv", ["hltl", *RUN])
    assert main() == 0, capsys.readouterr().err
    assert gc.get_freeze_count() > 0


def test_hltl_run_called_in_a_process_that_goes_on_does_not(
    unfrozen: None, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(RUN) == 0, capsys.readouterr().err
    assert gc.get_freeze_count() == 0
