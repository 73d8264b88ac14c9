"""A small fault soak in CI: random event mixes over the whole catalogue harm nothing."""

from __future__ import annotations

from hltl.bench.soak import random_events, run_soak, run_soak_episode, soak_jobs, summary
from hltl.sim.scenarios import catalogue


def test_a_small_soak_is_safe_loses_nothing_and_never_crashes() -> None:
    jobs = soak_jobs(len(catalogue()), seed=7)  # every scenario once
    s = summary(run_soak(jobs, workers=1))
    assert s["episodes"] == len(catalogue())
    assert (s["violations"], s["lost"], s["duplicated"], s["crash"], s["hang"]) == (0, 0, 0, 0, 0)
    # what fails is a situation without a plan, named as such
    for reason in s["failures_by_reason"]:
        assert "no plan" in reason or "consecutive failed actions" in reason, reason


def test_same_seed_same_mix_and_result() -> None:
    scenario = catalogue()[0]
    assert random_events(scenario, 5) == random_events(scenario, 5)
    job = soak_jobs(1, seed=5)[0]
    a, b = run_soak_episode(job), run_soak_episode(job)
    assert (a.outcome, a.reason, a.events) == (b.outcome, b.reason, b.events)


def test_every_event_type_is_drawn() -> None:
    kinds = {
        e.type
        for s in catalogue()
        for seed in range(6)
        for e in (*random_events(s, seed).timed, *random_events(s, seed).failures)
    }
    assert kinds == {"human_move", "object_move", "instruction", "robot_down", "skill_failure"}
