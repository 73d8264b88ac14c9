"""The bus on the command line: bad input is one 'error:' line, exit 1."""

from __future__ import annotations

import subprocess
import sys
from pathlib import Path

import pytest

from hltl.bus.session import free_endpoint
from hltl.cli.main import main

ROOT = Path(__file__).resolve().parents[2]
FIG1 = str(ROOT / "examples" / "scenes" / "fig1.yaml")


def _run(argv: list[str], capsys: pytest.CaptureFixture[str]) -> tuple[int, str]:
    code = main(argv)
    return code, capsys.readouterr().err


def test_run_over_the_bus_leaves_the_simulator_to_the_node(
    capsys: pytest.CaptureFixture[str],
) -> None:
    argv = ["run", "--scene", FIG1, "--instruction", "Give Person A the bottle"]
    code, err = _run([*argv, "--bus", "zenoh", "--sim", "mujoco"], capsys)
    assert code == 1 and "with --bus the node chooses it" in err and err.count("\n") == 1


@pytest.mark.parametrize(
    ("bus", "message"),
    [("dds", "unknown bus 'dds'"), ("zenoh:localhost:7447", "bad Zenoh endpoint")],
)
def test_bad_bus_option(capsys: pytest.CaptureFixture[str], bus: str, message: str) -> None:
    argv = ["run", "--scene", FIG1, "--instruction", "Give Person A the bottle", "--bus", bus]
    code, err = _run(argv, capsys)
    assert code == 1 and message in err and err.count("\n") == 1


def test_run_without_a_node_says_so(capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["run", "--scene", FIG1, "--instruction", "Give Person A the bottle", "--json"]
    argv += ["--bus", f"zenoh:{free_endpoint()}", "--bus-timeout", "0.05"]
    code, err = _run(argv, capsys)
    assert code == 1 and "error: no simulator node answers on hltl/default/sim/step" in err


def test_run_without_a_node_exits() -> None:
    """As a program, not only as a function: the session is closed after the failed episode,
    so its subscriptions' callback threads end and the process exits (it printed the error
    and then hung until session 25; in a test process it hung at the end of the run)."""
    argv = ["run", "--scene", FIG1, "--instruction", "Give Person A the bottle", "--json"]
    argv += ["--bus", f"zenoh:{free_endpoint()}", "--bus-timeout", "0.05"]
    code = "import sys; from hltl.cli.main import main; sys.exit(main(sys.argv[1:]))"
    try:  # (bounded: a hang is the failure this test is for)
        out = subprocess.run(
            [sys.executable, "-c", code, *argv], capture_output=True, text=True, timeout=120
        )
    except subprocess.TimeoutExpired:
        pytest.fail("hltl run --bus with no node did not exit within 120 s")
    err = out.stderr
    assert out.returncode == 1 and "error: no simulator node answers" in err
    assert err.count("\n") == 1


def test_node_rejects_bad_episode_count(capsys: pytest.CaptureFixture[str]) -> None:
    code, err = _run(["node", "sim", "--scene", FIG1, "--episodes", "0"], capsys)
    assert code == 1 and "--episodes must be at least 1" in err


def test_node_motion_is_for_the_discrete_simulator(capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["node", "sim", "--scene", FIG1, "--sim", "mujoco", "--motion", "--episodes", "1"]
    code, err = _run(argv, capsys)
    assert code == 1 and "always follows the joint trajectories" in err and err.count("\n") == 1


def test_bad_bus_perception_endpoint(capsys: pytest.CaptureFixture[str]) -> None:
    argv = ["run", "--scene", FIG1, "--instruction", "Give Person A the bottle", "--bus", "zenoh"]
    code, err = _run([*argv, "--bus-perception", "zenoh:localhost"], capsys)
    assert code == 1 and "bad Zenoh endpoint 'localhost'" in err and err.count("\n") == 1


@pytest.mark.parametrize(
    ("argv", "message"),
    [
        (["--repeats", "0"], "error: --repeats must be at least 1, got 0"),
        (["--episodes", "-2"], "error: --episodes must be at least 1, got -2"),
        (["--sim", "mujoco", "--repeats", "-1"], "error: --repeats must be at least 1, got -1"),
    ],
)
def test_bench_bus_refuses_bad_counts(
    capsys: pytest.CaptureFixture[str], argv: list[str], message: str
) -> None:
    code, err = _run(["bench", "bus", *argv], capsys)
    assert code == 1 and message in err and err.count("\n") == 1
