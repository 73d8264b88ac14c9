"""Trajectory predictors: goal geometry, the GRU's features and shipped weights, ADE/FDE."""

from __future__ import annotations

import json
import math
from pathlib import Path

import numpy as np
import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.perception.evaluate import errors, score
from hltl.perception.forecast import (
    DT,
    T_OBS,
    T_PRED,
    choose_goal,
    goal_forecast,
    resample,
    stop_places,
)
from hltl.perception.predict import (
    ConstantVelocityPredictor,
    GoalDirectedPredictor,
    GRUPredictor,
    make_predictor,
)
from hltl.perception.walks import KINDS, generate_walks
from hltl.world.scene import Human, Robot, Scene, load_scene

torch = pytest.importorskip("torch")

from hltl.perception import gru  # noqa: E402  (needs torch)


def _feed(pred: object, start: tuple[float, float], v: tuple[float, float], t1: float) -> None:
    t = 0.0
    while t <= t1 + 1e-9:
        pos = (start[0] + v[0] * t, start[1] + v[1] * t, 0.0)
        pred.observe(t, [("A", pos)])  # type: ignore[attr-defined]
        t = round(t + 0.05, 9)


def _two_arm_scene() -> Scene:
    robots = (Robot("r1", (0.0, 0.0, 0.0), 0.6), Robot("r2", (1.0, 0.0, 0.0), 0.7))
    humans = (Human("A", "Person A", (-0.8, 0.0, 0.0)), Human("B", "Person B", (1.8, 0.0, 0.0)))
    return Scene(robots=robots, humans=humans)


def test_stop_places_ring_the_robots_at_the_people_distance() -> None:
    scene = _two_arm_scene()
    stops = stop_places(scene)
    bases = np.array([[0.0, 0.0], [1.0, 0.0]])
    d = np.linalg.norm(stops[:, None, :] - bases[None], axis=2).min(axis=1)
    # every place is 0.8 m from its nearest base (the registered people's distance) ...
    assert d == pytest.approx(np.full(len(stops), 0.8), abs=1e-3)
    # ... the registered positions are among them, and none lies inside the other robot's ring
    for h in scene.humans:
        assert np.min(np.linalg.norm(stops - np.array(h.position[:2]), axis=1)) < 1e-6
    # a ring point of r1 at angle a is kept when it is at least 0.9·0.8 m from r2 (and vice versa)
    kept = [
        a
        for a in range(16)
        if math.hypot(0.8 * math.cos(a * math.pi / 8) - 1.0, 0.8 * math.sin(a * math.pi / 8))
        >= 0.72
    ]
    assert len(stops) == 2 * len(kept) == 22


def test_goal_directed_stops_where_cv_overshoots() -> None:
    scene = _two_arm_scene()
    goal = GoalDirectedPredictor(stop_places(scene))
    cv = ConstantVelocityPredictor()
    # a walk along y = 0.8 past r1 toward r2: the first place ahead is r2's ring point at
    # 112.5°, (1 − 0.8·cos 67.5°, 0.8·sin 67.5°)
    for p in (goal, cv):
        _feed(p, (0.0, 0.8), (1.0, 0.0), 0.5)
    assert goal.moving("A")
    (g,) = goal.predict("A", [3.0])
    (c,) = cv.predict("A", [3.0])
    a = math.radians(67.5)
    assert g[:2] == pytest.approx((1.0 - 0.8 * math.cos(a), 0.8 * math.sin(a)), abs=1e-4)
    assert c[0] == pytest.approx(3.0, abs=0.05)  # CV walks on through the cell


def test_a_standing_person_stays_and_nothing_ahead_means_constant_velocity() -> None:
    stops = np.array([[5.0, 5.0]])
    g = GoalDirectedPredictor(stops)
    _feed(g, (0.3, 0.2), (0.0, 0.0), 1.0)
    assert not g.moving("A")
    assert g.predict("A", [4.0])[0][:2] == pytest.approx((0.3, 0.2))
    g2 = GoalDirectedPredictor(stops)
    _feed(g2, (0.0, 0.0), (-1.0, 0.0), 1.0)  # walking away from the only place
    (p,) = g2.predict("A", [2.0])
    assert p[:2] == pytest.approx((-2.0, 0.0), abs=0.02)


def test_choose_goal_needs_the_place_ahead() -> None:
    stops = np.array([[1.0, 0.0], [-1.0, 0.0], [0.5, 1.0]])
    assert choose_goal(np.zeros(2), np.array([1.0, 0.0]), stops) == pytest.approx([1.0, 0.0])
    assert choose_goal(np.zeros(2), np.array([0.0, -1.0]), stops) is None
    assert choose_goal(np.zeros(2), np.zeros(2), stops) is None


def _rot(a: float) -> np.ndarray:
    return np.array([[math.cos(a), -math.sin(a)], [math.sin(a), math.cos(a)]])


walk_params = st.tuples(
    st.floats(0.3, 1.5),  # speed
    st.floats(-math.pi, math.pi),  # heading
    st.floats(-math.pi, math.pi),  # frame rotation
    st.floats(-3, 3),
    st.floats(-3, 3),  # frame translation
)


def _obs_and_stops(speed: float, heading: float) -> tuple[np.ndarray, np.ndarray]:
    u = np.array([math.cos(heading), math.sin(heading)])
    obs = np.array([u * speed * DT * k for k in range(T_OBS)])
    stops = np.array([u * 2.0 + [0.1, -0.1], u * 0.9 + [0.3, 0.2], -u, [0.5, 0.5]])
    return obs, stops


@settings(max_examples=25, deadline=None)
@given(walk_params)
def test_goal_forecast_is_equivariant_under_rigid_motions(p: tuple[float, ...]) -> None:
    speed, heading, a, tx, ty = p
    obs, stops = _obs_and_stops(speed, heading)
    r, t = _rot(a), np.array([tx, ty])
    base = goal_forecast(obs, stops)
    moved = goal_forecast(obs @ r.T + t, stops @ r.T + t)
    assert moved == pytest.approx(base @ r.T + t, abs=1e-6)


@settings(max_examples=10, deadline=None)
@given(walk_params)
def test_gru_forecast_is_equivariant_under_rigid_motions(p: tuple[float, ...]) -> None:
    speed, heading, a, tx, ty = p
    model = gru.load_model()
    obs, stops = _obs_and_stops(speed, heading)
    r, t = _rot(a), np.array([tx, ty])
    base = model.forecast(obs, stops)
    moved = model.forecast(obs @ r.T + t, stops @ r.T + t)
    assert moved == pytest.approx(base @ r.T + t, abs=2e-3)  # float32 inside


def test_an_untrained_gru_is_exactly_the_goal_directed_forecast() -> None:
    net = gru._build(torch)
    state = {k: v.detach().numpy() for k, v in net.state_dict().items()}
    model = gru.GRUModel(state, {})
    obs, stops = _obs_and_stops(1.0, 0.7)
    assert model.forecast(obs, stops) == pytest.approx(goal_forecast(obs, stops), abs=1e-5)


def test_shipped_weights_record_their_training_command_and_seed() -> None:
    model = gru.load_model()
    assert model.meta["command"].startswith("hltl perception train-predictor")
    assert isinstance(model.meta["seed"], int)
    assert gru.SHIPPED.stat().st_size < 1_000_000
    # trained: better than the goal-directed forecast it corrects, on its validation windows
    assert model.meta["val_ade"] < model.meta["val_goal_ade"]


def test_bad_weights_files_are_rejected(tmp_path: Path) -> None:
    with pytest.raises(FileNotFoundError):
        gru.load_model(tmp_path / "missing.npz")
    bad = tmp_path / "bad.npz"
    bad.write_text("not a zip")
    with pytest.raises(ValueError, match="not a GRU predictor weights file"):
        gru.load_model(bad)
    other = tmp_path / "other.npz"
    np.savez(other, meta=np.array(json.dumps({"t_obs": 3, "t_pred": 5, "dt": 0.2})))
    with pytest.raises(ValueError, match="another grid"):
        gru.load_model(other)


def test_walks_are_seeded_and_walk_at_human_speeds() -> None:
    a = generate_walks(7, 3, duration=10.0)
    b = generate_walks(7, 3, duration=10.0)
    for wa, wb in zip(a, b, strict=True):
        assert np.array_equal(wa.observed, wb.observed)
        steps = np.hypot(*np.diff(wa.true, axis=0).T)
        assert steps.max() <= 1.4 * DT + 1e-9
        assert set(wa.kinds) <= set(KINDS)
    assert not np.array_equal(a[0].true, a[1].true)


def test_resample_clamps_a_short_track() -> None:
    out = resample([0.0, 0.1], np.array([[0.0, 0.0], [0.1, 0.0]]), 0.1)
    assert out.shape == (T_OBS, 2)
    assert out[:-1, 0] == pytest.approx(np.zeros(T_OBS - 1))


def test_all_three_predictors_on_held_out_walks() -> None:
    walks = generate_walks(4242, 4, duration=15.0)
    data = [(w.observed, w.true, w.stops) for w in walks]
    model = gru.load_model()
    cv = score("cv", lambda s: ConstantVelocityPredictor(), data, 3)
    goal = score("goal", GoalDirectedPredictor, data, 3)
    learned = score("gru", lambda s: GRUPredictor(s, model=model), data, 3)
    assert cv.samples == goal.samples == learned.samples > 50
    # on these walks, the goal-directed forecast beats CV at 2 s and the GRU beats both
    assert goal.ade[1] < cv.ade[1]
    assert learned.ade[1] < goal.ade[1]
    assert learned.fde[1] < cv.fde[1]


def test_errors_are_zero_for_a_perfect_oracle() -> None:
    (w,) = generate_walks(5, 1, duration=8.0)

    class Oracle:
        def __init__(self, stops: np.ndarray) -> None:
            self.t = 0.0

        def observe(self, t: float, humans: object) -> None:
            self.t = t

        def predict(self, human: str, times: list[float]) -> list[tuple[float, float, float]]:
            out = []
            for t in times:
                i = round(t / DT)
                out.append((float(w.true[i, 0]), float(w.true[i, 1]), 0.0))
            return out

        def moving(self, human: str) -> bool:
            return True

    e = errors(Oracle, w.observed, w.true, w.stops)
    assert e.shape[1] == T_PRED and len(e) > 0
    assert e.max() == pytest.approx(0.0)


def test_make_predictor_by_name(two_arms_path: Path) -> None:
    scene = load_scene(two_arms_path)
    assert isinstance(make_predictor("cv", scene), ConstantVelocityPredictor)
    assert isinstance(make_predictor("goal", scene), GoalDirectedPredictor)
    assert isinstance(make_predictor("gru", scene), GRUPredictor)
    with pytest.raises(ValueError, match="unknown predictor"):
        make_predictor("kalman", scene)
