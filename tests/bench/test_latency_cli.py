"""``hltl bench latency`` and the ablation's latency and variant options."""

from __future__ import annotations

from pathlib import Path

import pytest

from hltl.bench.suite import AblationOptions
from hltl.cli.main import main
from hltl.execution.latency import load_latency_model


def _error_line(capsys: pytest.CaptureFixture[str]) -> str:
    err = capsys.readouterr().err.strip().splitlines()
    assert len(err) == 1 and err[0].startswith("error: ")
    return err[0]


def test_latency_measures_and_writes_a_loadable_model(tmp_path: Path) -> None:
    out = tmp_path / "model.json"
    argv = ["bench", "latency", "--trials", "1", "--configs", "1-2", "--write-model", str(out)]
    assert main(argv) == 0
    m = load_latency_model(out)
    assert "hltl bench latency --trials 1 --seed 0 --configs 1-2" in m.source
    opts = AblationOptions(trials=1, configs="1-2", latency_model=out, variants_text="full")
    assert opts.variants()[0].latency == m
    assert "--latency-model" in opts.command() and "--variants full" in opts.command()


@pytest.mark.parametrize(
    ("argv", "needle"),
    [
        (["bench", "latency", "--trials", "0"], "--trials"),
        (["bench", "ablation", "--trials", "1", "--variants", "full,warp"], "warp"),
        (["bench", "ablation", "--trials", "1", "--latency-model", "/nonexistent.json"], "latency"),
        (["bench", "ablation", "--trials", "1", "--plan-latency", "-1"], "--plan-latency"),
    ],
)
def test_bad_options_are_one_error_line(
    argv: list[str], needle: str, capsys: pytest.CaptureFixture[str]
) -> None:
    assert main(argv) == 1
    assert needle in _error_line(capsys)


def test_a_constant_latency_is_still_available_for_comparison() -> None:
    opts = AblationOptions(trials=1, plan_latency=0.2, variants_text="full,no-pmp")
    full, serial = opts.variants()
    assert full.latency is None and full.plan_latency == 0.2
    assert serial.plan_latency == pytest.approx(0.6)
    assert "--plan-latency 0.2" in opts.command()
