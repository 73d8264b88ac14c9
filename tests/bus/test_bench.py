"""``hltl bench bus`` on a tiny run: the figures it reports are consistent."""

from __future__ import annotations

from hypothesis import given
from hypothesis import strategies as st

from hltl.bus.bench import bench_bus, format_bus
from hltl.bus.session import free_endpoint


def test_bench_bus_small() -> None:
    b = bench_bus(free_endpoint(), round_trips=20, episodes=1, repeats=2)
    assert b.same_logs == 1 and b.fault_same_logs == 1
    # the paired repeats: the bus first in the second pair, both sides timed
    s = b.repeats
    assert s.n == 2 and [p.b_first for p in s.pairs] == [False, True] and not s.judged
    assert all(p.a_s > 0 and p.b_s > 0 and p.a_cpu_s > 0 for p in s.pairs)
    assert s.min_ratio <= s.median_ratio <= s.max_ratio
    # the node in a process of its own: the same log, and its CPU time comes back
    assert b.apart.same_logs == 1 and b.apart.bus_s > 0 and b.apart.node_cpu_s > 0
    # the executor's loop: its CPU time on both sides, and it waited for the node's answers
    assert 0 < b.apart.main_cpu_s <= b.apart.cpu_s and b.apart.inproc_main_cpu_s > 0
    assert 0 < b.apart.waited_s < b.apart.bus_s
    # and with each stretch streamed instead of in one answer: the same log, queries counted
    assert b.streamed.same_logs == 1 and 0 < b.streamed.waited_s < b.streamed.bus_s
    assert b.apart.queries > 0 and b.streamed.queries > 0
    # and without the executor's hints: the same log, every step's commands in a query
    u = b.unhinted
    assert u is not None and u.same_logs == 1 and u.guessed == 0 and b.apart.guessed > 0
    # and with hints but without the node's foresight: the same log
    h = b.hinted
    assert h is not None and h.same_logs == 1
    # and with the node making the executor's background plans: the same log (1-1 #0 walks)
    g = b.background
    assert g is not None and g.same_logs == 1 and 0 <= g.given <= g.asked and g.asked > 0
    assert b.dispatched > 0 and b.lost == 0 and b.duplicated == 0
    assert 0 < b.round_trip_ms[0] <= b.round_trip_ms[1] <= b.round_trip_ms[2]
    r = b.realtime  # the same trial in real time: nothing lost or twice, the goals met
    assert r.episodes == 1 and r.dispatched > 0 and r.lost == 0 and r.duplicated == 0
    # (at 10x a loop stalled by a loaded machine can react late: a safety violation, counted,
    # is then why the formulas differ)
    assert (r.same_done == 1 or r.violations == 1) and r.ticks > 0 and r.cell_s > 0
    assert 0 <= r.lag_ms[0] <= r.lag_ms[1] <= r.lag_ms[2]
    text = format_bus(b, "hltl bench bus", "2026-01-01", "test")
    assert "## Bus" in text and "1/1" in text and "### Real time" in text
    assert "process of its own" in text and "waits" in text and "streamed instead" in text
    assert "without the executor's hints" in text
    assert "without the node's foresight" in text
    assert "background plans" in text
    assert "repeated in 2 pairs" in text and "(bus first)" in text and "IQR" in text
    assert "**not judged** on 2 pairs" in text and "at least 5" in text


def test_bench_bus_suite_with_the_3d_simulator() -> None:
    """``hltl bench bus --sim mujoco``: the suite simulated in 3D, in-process and on a node in
    a process of its own, with the same log."""
    import pytest

    pytest.importorskip("mujoco")
    from hltl.bus.bench import bench_bus_suite, format_bus_suite

    b = bench_bus_suite(1, "mujoco", repeats=1)
    assert b.sim == "mujoco" and b.episodes == 1 and b.same_logs == 1
    assert b.inproc_s > 0 and b.bus_s > 0 and b.node_cpu_s > 0 and b.inproc_cpu_s > 0
    assert 0 < b.waited_s < b.bus_s and 0 < b.queries < b.ticks
    assert b.repeats.n == 1 and b.repeats.a_median_s == b.inproc_s
    text = format_bus_suite(b, "hltl bench bus --sim mujoco --episodes 1", "2026-01-01", "test")
    assert "3D simulator" in text and "1/1" in text and "within 10 %" in text
    assert "**not judged** on 1 pair " in text


def test_the_verdict_is_judged_only_with_a_core_for_the_in_process_run() -> None:
    """An in-process yardstick that waited for a core (a loaded machine) judges nothing."""
    from hltl.bus.bench import verdict

    assert verdict(5.0, 1.0, 0.98) == "met on this run"
    assert verdict(5.0, 1.0, 0.98, on="the median of 5 pairs") == "met on the median of 5 pairs"
    assert verdict(51.1, 1.23, 1.20) == "**not met** on this run"  # session 10's official run
    text = verdict(5.5, 3.67, 1.72)  # session 12's: the in-process runs 47 % on a core
    assert text.startswith("**not judged**") and "47%" in text


@given(
    over=st.floats(-50, 200),
    wall=st.floats(0.01, 100),
    share=st.floats(0, 1),
)
def test_the_verdict_follows_the_share_on_a_core_and_the_target(
    over: float, wall: float, share: float
) -> None:
    from hltl.bus.bench import ON_CORE, verdict

    text = verdict(over, wall, share * wall)
    if share * wall / wall < ON_CORE:
        assert text.startswith("**not judged**")
    else:
        assert text == ("met on this run" if over <= 10 else "**not met** on this run")


@given(
    ratios=st.lists(st.floats(-50, 200), min_size=1, max_size=9),
    share=st.floats(0, 1),
)
def test_the_repeats_are_judged_on_their_median_of_at_least_five(
    ratios: list[float], share: float
) -> None:
    from hltl.bus.bench import ON_CORE, repeats_verdict
    from hltl.bus.paired import MIN_REPEATS, Pair, paired_stats

    s = paired_stats([Pair(1.0, 1.0 + r / 100, False, share) for r in ratios])
    text = repeats_verdict(s)
    if len(ratios) < MIN_REPEATS:
        assert text.startswith(f"**not judged** on {len(ratios)} pair")
    elif share < ON_CORE:
        assert text.startswith("**not judged**") and "on a core" in text
    else:
        on = f"the median of {len(ratios)} pairs"
        met = s.median_ratio <= 10
        assert text == (f"met on {on}" if met else f"**not met** on {on}")
