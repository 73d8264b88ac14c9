"""``hltl bench latency`` and the ablation's latency and variant options."""

from __future__ import annotations

from dataclasses import replace
from pathlib import Path

import pytest

from hltl.bench.pmp import DEFAULT_PMP, load_pmp_latency, write_pmp_latency
from hltl.bench.suite import AblationOptions
from hltl.cli.main import main
from hltl.errors import HltlError
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
        (["bench", "pmp", "--workers", "1"], "--workers"),
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
    assert serial.plan_latency == 0.2  # the planner is the same; its motion is serial
    assert "--plan-latency 0.2" in opts.command()


def test_no_pmp_runs_the_serial_candidate_planner() -> None:
    opts = AblationOptions(trials=1, variants_text="full,no-pp,no-pmp,antic-gru")
    full, no_pp, no_pmp, antic = opts.variants()
    assert full.motion == no_pp.motion == antic.motion == "parallel"
    assert no_pmp.motion == "serial"
    assert full.r2r_motion_s == no_pmp.r2r_motion_s == 0.0  # measured, not a fixed latency
    assert full.latency == no_pmp.latency and no_pmp.predict
    assert "--pmp" not in opts.command()


def test_the_fixed_pmp_latency_model_is_still_available(tmp_path: Path) -> None:
    pmp = load_pmp_latency(DEFAULT_PMP)
    assert pmp.source.startswith("`hltl bench pmp") and pmp.candidates >= 8
    assert pmp.serial_cpu_s > 0 and pmp.parallel_s > 0
    opts = AblationOptions(trials=1, variants_text="full,no-pp,no-pmp", pmp_mode="model")
    full, no_pp, no_pmp = opts.variants()
    assert full.r2r_motion_s == no_pp.r2r_motion_s == pmp.parallel_s
    assert no_pmp.r2r_motion_s == pmp.serial_s
    assert full.motion == no_pmp.motion == ""
    assert "--pmp model" in opts.command()
    # another measurement file, named in the command
    other = tmp_path / "pmp.json"
    write_pmp_latency(other, replace(pmp, serial_s=2.0, parallel_s=1.0))
    opts = AblationOptions(
        trials=1, variants_text="full,no-pmp", pmp_latency=other, pmp_mode="model"
    )
    assert [v.r2r_motion_s for v in opts.variants()] == [1.0, 2.0]
    assert f"--pmp-latency {other}" in opts.command()
    with pytest.raises(HltlError, match="--pmp-latency"):
        AblationOptions(pmp_latency=other)
    with pytest.raises(HltlError, match="--pmp: unknown mode 'fast'"):
        AblationOptions(pmp_mode="fast")


@pytest.mark.parametrize(
    ("text", "needle"),
    [("{", "cannot read"), ("[]", "expected a JSON object"), ('{"x": 1}', "unknown keys")],
)
def test_bad_pmp_files_are_one_error_line(
    tmp_path: Path, text: str, needle: str, capsys: pytest.CaptureFixture[str]
) -> None:
    bad = tmp_path / "pmp.json"
    bad.write_text(text)
    argv = ["bench", "ablation", "--trials", "1", "--pmp", "model", "--pmp-latency", str(bad)]
    assert main(argv) == 1
    line = _error_line(capsys)
    assert needle in line and "P.M.P. latency" in line
