"""--executor: the same seeds give the same results on local processes and on a Dask cluster."""

from __future__ import annotations

import dataclasses
import json
import threading
import time
from collections.abc import Iterator
from pathlib import Path
from typing import Any

import pytest

from hltl.bench import sweep
from hltl.bench.soak import SoakResult, _Hang, _hang_guard, run_soak, soak_jobs
from hltl.bench.suite import AblationOptions, SuiteOptions, TrialResult, run_suite
from hltl.bench.sweep import SweepExecutor
from hltl.cli.main import main
from hltl.errors import HltlError


@pytest.fixture(scope="module")
def dask_address() -> Iterator[str]:
    """A small in-process Dask cluster (one worker, one thread)."""
    distributed = pytest.importorskip("dask.distributed")
    with distributed.LocalCluster(
        n_workers=1,
        threads_per_worker=1,
        processes=False,
        dashboard_address=None,
        silence_logs=50,
    ) as cluster:
        yield cluster.scheduler_address


def _soak(r: SoakResult) -> SoakResult:
    return dataclasses.replace(r, wall_s=0.0)  # wall clock is the one thing that may differ


def _trial(r: TrialResult) -> dict[str, Any]:
    return {**r.to_dict(), "wall_s": 0.0}


def test_parse() -> None:
    assert SweepExecutor.parse("local") == SweepExecutor()
    assert SweepExecutor.parse("dask") == SweepExecutor("dask")
    assert SweepExecutor.parse("dask:tcp://10.0.0.5:8786") == SweepExecutor(
        "dask", "tcp://10.0.0.5:8786"
    )
    assert str(SweepExecutor.parse("dask:tcp://h:1")) == "dask:tcp://h:1"
    for bad in ("", "ray", "dask:", "dask: ", "Dask", "x" * 5000):
        with pytest.raises(HltlError, match="expected local, dask, or dask:SCHEDULER_ADDRESS") as e:
            SweepExecutor.parse(bad)
        assert len(str(e.value)) < 300


def test_soak_results_equal_on_dask_and_local(dask_address: str) -> None:
    jobs = soak_jobs(4, seed=3)
    local = run_soak(jobs, workers=1)
    seen: list[SoakResult] = []
    on_dask = run_soak(jobs, 1, seen.append, SweepExecutor("dask", dask_address))
    assert [_soak(r) for r in on_dask] == [_soak(r) for r in local]
    assert sorted(r.seed for r in seen) == sorted(j.seed for j in jobs)


def test_suite_and_ablation_results_equal_on_dask_and_local(dask_address: str) -> None:
    dask = SweepExecutor("dask", dask_address)
    suite = SuiteOptions(trials=1, configs="1-2", methods="greedy").trial_jobs()
    ablation = AblationOptions(trials=1, configs="1-1", variants_text="full,no-pmp").trial_jobs()
    for jobs in (suite, ablation):
        local = run_suite(jobs, workers=1)
        remote = run_suite(jobs, workers=1, executor=dask)
        assert [_trial(r) for r in remote] == [_trial(r) for r in local]
        assert all(r.status == "ok" for r in local)


def test_the_executor_is_part_of_the_recorded_command() -> None:
    opts = SuiteOptions(trials=1, methods="hltl", executor="dask:tcp://h:8786")
    assert "--executor dask:tcp://h:8786" in opts.command()
    assert "--executor" not in SuiteOptions(trials=1, methods="hltl").command()
    assert "--executor dask" in AblationOptions(trials=1, executor="dask").command()
    with pytest.raises(HltlError, match="--executor"):
        AblationOptions(executor="spark")


def test_an_unreachable_scheduler_is_one_clear_error(
    capsys: pytest.CaptureFixture[str], monkeypatch: pytest.MonkeyPatch
) -> None:
    pytest.importorskip("dask.distributed")
    monkeypatch.setattr(sweep, "DASK_CONNECT_TIMEOUT", 1.0)
    # port 9 on this machine: nothing listens, the connection is refused at once
    code = main(
        ["bench", "soak", "--episodes", "1", "--jobs", "1", "--executor", "dask:tcp://127.0.0.1:9"]
    )
    err = capsys.readouterr().err.strip().splitlines()
    assert code == 1
    assert err[-1].startswith("error: --executor dask:'tcp://127.0.0.1:9': cannot reach"), err
    assert "within 1 s" in err[-1]


def test_a_bad_executor_is_one_clear_error(capsys: pytest.CaptureFixture[str]) -> None:
    for cmd in (["soak", "--episodes", "1"], ["suite", "--trials", "1"], ["ablation"]):
        assert main(["bench", *cmd, "--executor", "ray"]) == 1
        err = capsys.readouterr().err.strip().splitlines()
        assert len(err) == 1 and err[0].startswith("error: --executor 'ray': expected"), err


def test_the_hang_guard_stops_a_job_running_in_a_worker_thread() -> None:
    # a Dask worker runs jobs in threads, where SIGALRM cannot reach: the guard still fires
    outcome: list[str] = []

    def job() -> None:
        try:
            with _hang_guard(1):
                deadline = time.monotonic() + 30.0
                while time.monotonic() < deadline:
                    pass
            outcome.append("ran to the end")
        except _Hang:
            outcome.append("hang")

    th = threading.Thread(target=job)
    th.start()
    th.join(30.0)
    assert outcome == ["hang"]


def test_the_hang_guard_does_not_fire_after_the_job() -> None:
    outcome: list[str] = []

    def job() -> None:
        try:
            with _hang_guard(1):
                pass
            time.sleep(1.5)  # the timer's moment passes outside the guard
            outcome.append("ok")
        except _Hang:
            outcome.append("late hang")

    th = threading.Thread(target=job)
    th.start()
    th.join(30.0)
    assert outcome == ["ok"]


def test_the_cli_on_a_local_dask_cluster_matches_local_processes(tmp_path: Path) -> None:
    # `--executor dask` without an address starts its own cluster (one worker process here)
    pytest.importorskip("dask.distributed")
    out: dict[str, list[dict[str, Any]]] = {}
    for executor in ("local", "dask"):
        path = tmp_path / f"{executor}.json"
        args = ["--episodes", "2", "--jobs", "1", "--seed", "4", "--json", str(path)]
        assert main(["bench", "soak", *args, "--executor", executor]) == 0
        out[executor] = [{**d, "wall_s": 0.0} for d in json.loads(path.read_text())]
    assert out["dask"] == out["local"]
    assert len(out["local"]) == 2
