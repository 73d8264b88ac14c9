"""The paper's simulation suite (§V-A, Table II) with dynamics, run through the closed loop."""

from __future__ import annotations

import math
import shlex
import statistics
import time
from collections.abc import Callable, Iterable, Sequence
from dataclasses import asdict, dataclass, field, replace
from pathlib import Path
from typing import Any

from hltl.bench.baselines.flat import compare, sweep
from hltl.bench.baselines.greedy import GreedyPolicy
from hltl.bench.baselines.loop import LoopConfig, run_baseline_episode
from hltl.bench.baselines.pddl import fd_unavailable, solve
from hltl.bench.baselines.policy import Policy
from hltl.bench.baselines.smart_llm import SmartLLMPolicy, llm_unavailable
from hltl.bench.latency import DEFAULT_MODEL as DEFAULT_LATENCY_MODEL
from hltl.bench.pmp import DEFAULT_PMP, PmpLatency, load_pmp_latency
from hltl.bench.sweep import SweepExecutor
from hltl.errors import HltlError
from hltl.execution.executor import Executor, ExecutorConfig
from hltl.execution.latency import LatencyModel, MotionTimer, load_latency_model
from hltl.execution.log import Anticipate, EpisodeEnd, EventLog, Grounding, LogRecord, Replan
from hltl.execution.predict import TrajectoryPredictor
from hltl.grounding.offline import OfflineGrounder
from hltl.grounding.tokens import estimate_grounding_tokens
from hltl.perception.forecast import stop_places
from hltl.perception.gru import load_model
from hltl.perception.predict import GRUPredictor, make_predictor
from hltl.planner import plan
from hltl.sim.dynamic import (
    WALKS,
    Trial,
    config_names,
    config_of,
    full_spec,
    make_trial,
    trial_seed,
)
from hltl.sim.episode import Cell, EpisodeConfig, run_episode
from hltl.sim.invariants import check_invariants
from hltl.sim.metrics import Metrics

METHODS = ("hltl", "greedy", "smart-llm")
ONE_SHOT = ("flat", "fd")


# -- results ---------------------------------------------------------------------------------------


@dataclass(frozen=True, slots=True)
class TrialResult:
    """What one method scored on one trial (plain data: it crosses process boundaries).

    ``status`` is ``ok`` (the episode ran; ``success`` says how it ended), ``not_run`` (the
    method's backend is not configured here; ``reason`` says which) or ``error`` (the method
    crashed; ``reason`` holds the exception, the trial counts as a failure).
    """

    method: str
    config: str
    index: int
    seed: int
    status: str
    success: bool = False
    goals_met: bool = False
    reason: str = ""
    time_cost: float | None = None
    tokens: int = 0
    queries: int = 0
    est_tokens: int = 0
    replans: int = 0
    violations: int = 0
    kinematic: int = 0
    conflicts: int = 0
    stale: int = 0
    invariant_problems: int = 0
    halts: int = 0
    h_idle: float | None = None
    r_idle: float | None = None
    c_act: float | None = None
    f_del: float | None = None
    f_del_union: float | None = None
    c_act_hr: float | None = None
    h_idle_walk_active: float | None = None
    wall_s: float = 0.0
    variant: str = "full"
    details: tuple[str, ...] = field(default=())
    extra: dict[str, Any] = field(default_factory=dict)

    @property
    def tokens_per_query(self) -> float | None:
        return self.tokens / self.queries if self.queries else None

    @property
    def est_tokens_per_query(self) -> float | None:
        return self.est_tokens / self.queries if self.queries else None

    def to_dict(self) -> dict[str, Any]:
        d = asdict(self)
        d["details"] = list(self.details)
        d["extra"] = dict(self.extra)
        d["tokens_per_query"] = self.tokens_per_query
        d["est_tokens_per_query"] = self.est_tokens_per_query
        return d

    @classmethod
    def from_dict(cls, data: dict[str, Any]) -> TrialResult:
        d = {k: v for k, v in data.items() if k not in ("tokens_per_query", "est_tokens_per_query")}
        d["details"] = tuple(d.get("details", ()))
        return cls(**d)


@dataclass(frozen=True, slots=True)
class Variant:
    """An executor variant for the ablation (Table III).

    Attributes:
        name: ``full``, ``no-pp`` (without predictive planning), ``no-pmp`` (serial
            replanning computation), ``goal`` (the goal-directed predictor), ``antic-goal`` /
            ``antic-gru`` (anticipatory execution with the goal-directed / learned predictor);
            see docs/evaluation.md.
        predict: the executor's predictive planning and takeover.
        plan_latency: a constant charged on every planner call (used only without
            ``latency``).
        latency: computation charged where it occurs (:mod:`hltl.execution.latency`).
        r2r_motion_s: motion planning charged per robot-to-robot handover in a new plan's first
            step (``ExecutorConfig.r2r_motion_s``): the parallel candidate planner's measured
            latency, the serial one's for ``no-pmp``; used only without ``motion``.
        motion: ``parallel`` or ``serial``: the motion layer plans each robot-to-robot
            handover of a new plan's first step (its candidate goal sets on a pool of
            PMP_WORKERS processes, or one after the other) and the call costs the measured
            seconds (:class:`hltl.motion.pmp.HandoverMotionTimer`); ``""``: ``r2r_motion_s``.
        predictor: ``cv``, ``goal`` or ``gru`` (:func:`hltl.perception.predict.make_predictor`).
        anticipate: anticipatory execution.
    """

    name: str = "full"
    predict: bool = True
    plan_latency: float = 0.0
    latency: LatencyModel | None = None
    predictor: str = "cv"
    anticipate: bool = False
    r2r_motion_s: float = 0.0
    motion: str = ""


MOTION_MODES = ("", "parallel", "serial")
PMP_WORKERS = 2  # the parallel candidate planner's processes (the machine's two cores)


@dataclass(frozen=True, slots=True)
class TrialJob:
    """One unit of work for a worker process."""

    method: str
    config: str
    index: int
    suite_seed: int = 0
    variant: Variant = field(default_factory=Variant)
    max_time: float = 120.0
    walks: str = "random"


def run_trial(job: TrialJob) -> TrialResult:
    """Run one job; never raises (a crash is an ``error`` result naming the exception)."""
    t0 = time.perf_counter()
    try:
        trial = make_trial(job.config, job.index, job.suite_seed, job.walks)
    except HltlError as exc:
        return TrialResult(
            job.method,
            job.config,
            job.index,
            trial_seed(job.suite_seed, job.index),
            "error",
            reason=f"trial generation failed: {exc}",
            variant=job.variant.name,
        )
    try:
        if job.method == "hltl":
            res = _run_hltl(trial, job)
        elif job.method in ("greedy", "smart-llm"):
            res = run_baseline_trial(job.method, trial, max_time=job.max_time)
        elif job.method in ONE_SHOT:
            res = _run_one_shot(trial, job)
        else:
            raise HltlError(f"unknown method {job.method!r}; expected one of {', '.join(METHODS)}")
    except Exception as exc:  # a crash is a failed trial, reported with its cause
        res = TrialResult(
            job.method,
            job.config,
            job.index,
            trial.seed,
            "error",
            reason=f"{type(exc).__name__}: {exc}",
            variant=job.variant.name,
        )
    if res.status == "ok":
        res = replace(res, extra={**res.extra, "walk": trial.walk})
    return replace(res, wall_s=round(time.perf_counter() - t0, 4))


def _scored(
    method: str,
    trial: Trial,
    records: Sequence[LogRecord],
    m: Metrics,
    *,
    variant: str = "full",
    notes: Sequence[str] = (),
    **counts: Any,
) -> TrialResult:
    """A closed-loop episode's result: its metrics, judged with the log's invariants."""
    problems = check_invariants(records)
    end = [r for r in records if isinstance(r, EpisodeEnd)][-1]
    goals_met = bool(end.success)
    return TrialResult(
        method=method,
        config=trial.config,
        index=trial.index,
        seed=trial.seed,
        status="ok",
        success=m.success and not problems,
        goals_met=goals_met,
        reason=m.reason,
        time_cost=m.time_cost if goals_met else None,
        replans=m.replans,
        violations=m.violations,
        invariant_problems=len(problems),
        halts=m.halts,
        h_idle=m.h_idle,
        r_idle=m.r_idle,
        c_act=m.c_act,
        f_del=m.f_del,
        f_del_union=m.f_del_union,
        c_act_hr=m.c_act_hr,
        h_idle_walk_active=m.h_idle_walk_active,
        variant=variant,
        details=tuple([*notes[:5], *problems[:5]]),
        **counts,
    )


def _run_hltl(trial: Trial, job: TrialJob) -> TrialResult:
    v = job.variant
    if v.motion not in MOTION_MODES:
        raise HltlError(f"variant {v.name}: unknown motion mode {v.motion[:40]!r}")
    timer: Any = None
    if v.motion:
        # why: the motion extra (Pinocchio, coal, the maps) is needed only with real P.M.P.
        from hltl.motion.pmp import HandoverMotionTimer

        timer = HandoverMotionTimer(
            trial.scene, workers=PMP_WORKERS if v.motion == "parallel" else 0
        )
    try:
        return _run_hltl_episode(trial, job, timer)
    finally:
        if timer is not None:
            timer.close()


def _run_hltl_episode(trial: Trial, job: TrialJob, timer: MotionTimer | None) -> TrialResult:
    v = job.variant
    cfg = EpisodeConfig(
        max_time=job.max_time,
        executor=ExecutorConfig(
            predict=v.predict,
            plan_latency=v.plan_latency,
            latency=v.latency,
            r2r_motion_s=v.r2r_motion_s,
            anticipate=v.anticipate,
        ),
    )
    predictor = _predictor(v.predictor, trial)

    def agent(sim: Cell, log: EventLog) -> Executor:
        return Executor(
            trial.scene,
            None,
            sim,
            log=log,
            predictor=predictor,
            config=cfg.executor,
            motion=timer,
        )

    ep = run_episode(
        trial.scene,
        instruction=trial.instruction,
        events=trial.events,
        seed=trial.seed,
        config=cfg,
        grounder=OfflineGrounder(),
        predictor=predictor,
        agent=agent,
    )
    m = ep.metrics
    charged = [float(r.charged_s or 0.0) for r in ep.records if isinstance(r, Replan | Grounding)]
    motion = [float(r.motion_s) for r in ep.records if isinstance(r, Replan) and r.motion_s]
    groundings = [r for r in ep.records if isinstance(r, Grounding) and r.error is None]
    est = sum(estimate_grounding_tokens(str(r.text), trial.scene) for r in groundings)
    return _scored(
        "hltl",
        trial,
        ep.records,
        m,
        variant=v.name,
        tokens=m.tokens,
        queries=len(groundings),
        est_tokens=est,
        extra={
            "takeovers": m.takeovers,
            "planner_calls": m.planner_calls,
            "charged_s": round(sum(charged), 6),
            "charged_calls": sum(1 for c in charged if c > 0),
            "motion_s": round(sum(motion), 6),
            "motion_calls": len(motion),
            "anticipations": sum(1 for r in ep.records if isinstance(r, Anticipate) and r.differs),
        },
    )


_GRU: list[Any] = []  # the GRU weights, loaded once per worker process


def _predictor(name: str, trial: Trial) -> TrajectoryPredictor | None:
    """The variant's trajectory predictor (None: the executor's default, constant velocity)."""
    if name == "cv":
        return None
    if name == "gru":
        if not _GRU:
            _GRU.append(load_model())
        return GRUPredictor(stop_places(trial.scene), model=_GRU[0])
    return make_predictor(name, trial.scene)


def make_policy(method: str, **options: Any) -> Policy:
    """The policy of a closed-loop baseline (``greedy`` or ``smart-llm``)."""
    if method == "greedy":
        return GreedyPolicy()
    if method == "smart-llm":
        return SmartLLMPolicy(**options)
    raise HltlError(f"unknown baseline {method!r}; expected greedy or smart-llm")


def run_baseline_trial(
    method: str, trial: Trial, *, max_time: float = 120.0, **options: Any
) -> TrialResult:
    """Run a closed-loop baseline on a suite trial and score it like hltl."""
    ep = run_baseline_episode(
        make_policy(method, **options),
        trial.scene,
        trial.instruction,
        events=trial.events,
        seed=trial.seed,
        config=LoopConfig(max_time=max_time),
    )
    return _scored(
        method,
        trial,
        ep.records,
        ep.metrics,
        notes=ep.violations,
        tokens=ep.tokens,
        queries=ep.queries,
        kinematic=ep.kinematic,
        conflicts=ep.conflicts,
        stale=ep.stale,
    )


def _run_one_shot(trial: Trial, job: TrialJob) -> TrialResult:
    """Planning-only comparisons on the trial's whole task from the initial world."""
    spec = full_spec(trial)
    base = TrialResult(
        job.method, trial.config, trial.index, trial.seed, "ok", variant=job.variant.name
    )
    if job.method == "flat":
        cmp = compare(trial.scene, spec, limit=60.0)
        return replace(base, success=cmp.flat.status == "ok", extra=cmp.to_dict())
    missing = fd_unavailable()
    if missing is not None:
        return replace(base, status="not_run", reason=missing)
    fd = solve(trial.scene, spec, timeout=60.0)
    t0 = time.perf_counter()
    ours = plan(trial.scene, spec, timeout=60.0)
    seconds = time.perf_counter() - t0
    d = trial.scene.duration_map() or {}
    work = sum(d.get(a.skill, 0.0) for s in ours.steps for a in s.actions)
    extra = {
        "fd": fd.to_dict(),
        "hltl": {
            "status": ours.status.value,
            "seconds": seconds,
            "makespan": ours.makespan,
            "work": round(work, 6),
            "actions": sum(len(s.actions) for s in ours.steps),
        },
    }
    return replace(base, success=fd.status == "solved", extra=extra)


# -- running many ----------------------------------------------------------------------------------


def jobs_for(
    configs: Sequence[str],
    trials: int,
    methods: Sequence[str],
    suite_seed: int = 0,
    variants: Sequence[Variant] = (Variant(),),
    max_time: float = 120.0,
    walks: str = "random",
) -> list[TrialJob]:
    """Every (method, variant, configuration, trial) job, configurations outermost."""
    return [
        TrialJob(m, c, i, suite_seed, v, max_time, walks)
        for c in configs
        for i in range(trials)
        for m in methods
        for v in variants
    ]


def run_suite(
    jobs: Sequence[TrialJob],
    *,
    workers: int = 2,
    on_result: Callable[[TrialResult], None] | None = None,
    executor: SweepExecutor | None = None,
) -> list[TrialResult]:
    """Run ``jobs`` on ``executor`` (default: ``workers`` local processes; 1: in this process);
    results in job order.

    Methods whose backend is not configured are answered without starting a process.
    """
    results: list[TrialResult | None] = [None] * len(jobs)
    todo: list[int] = []
    missing = {
        "smart-llm": llm_unavailable() if any(j.method == "smart-llm" for j in jobs) else None,
        "fd": fd_unavailable(),
    }
    for k, job in enumerate(jobs):
        why = missing.get(job.method)
        if why is not None:
            res = TrialResult(
                job.method,
                job.config,
                job.index,
                trial_seed(job.suite_seed, job.index),
                "not_run",
                reason=why,
                variant=job.variant.name,
            )
            results[k] = res
            if on_result is not None:
                on_result(res)
        else:
            todo.append(k)
    ran = (executor or SweepExecutor()).run(run_trial, [jobs[k] for k in todo], workers, on_result)
    for k, res in zip(todo, ran, strict=True):
        results[k] = res
    return [r for r in results if r is not None]


def results_to_json(results: Iterable[TrialResult]) -> list[dict[str, Any]]:
    return [r.to_dict() for r in results]


# -- the commands ---------------------------------------------------------------------------------


def configs_from(text: str) -> list[str]:
    """Configuration names from a comma-separated list (empty: all twelve).

    Raises:
        HltlError: a name that is not a Table II configuration.
    """
    if not text.strip():
        return list(config_names())
    names = [c.strip() for c in text.split(",") if c.strip()]
    for c in names:
        config_of(c)
    return names


@dataclass(frozen=True, slots=True)
class SuiteOptions:
    """What ``hltl bench suite`` runs (its command-line options)."""

    trials: int = 100
    configs: str = ""
    methods: str = "hltl,greedy,smart-llm,flat,fd"
    jobs: int = 2
    seed: int = 0
    max_time: float = 120.0
    flat_trials: int = 2
    flat_sweep: str = "1,2,4,6,8,10,12"
    flat_limit: float = 60.0
    write: Path | None = None
    figures: Path | None = None
    json: Path | None = None
    executor: str = "local"
    walks: str = "random"

    def __post_init__(self) -> None:
        if self.trials < 1 or self.jobs < 1:
            raise HltlError("--trials and --jobs must be at least 1")
        SweepExecutor.parse(self.executor)
        _check_walks(self.walks)
        for m in self.method_list:
            if m not in (*METHODS, *ONE_SHOT):
                raise HltlError(
                    f"--methods: unknown method {m!r}; expected some of "
                    f"{', '.join((*METHODS, *ONE_SHOT))}"
                )

    @property
    def method_list(self) -> list[str]:
        return [m.strip() for m in self.methods.split(",") if m.strip()]

    @property
    def loop_methods(self) -> list[str]:
        return [m for m in self.method_list if m in METHODS]

    def trial_jobs(self) -> list[TrialJob]:
        """Closed-loop jobs first, then Fast Downward, then flat LTLf (fewer trials)."""
        configs = configs_from(self.configs)
        methods = self.method_list
        w = self.walks
        jobs = jobs_for(
            configs, self.trials, self.loop_methods, self.seed, max_time=self.max_time, walks=w
        )
        if "fd" in methods:
            jobs += jobs_for(configs, self.trials, ["fd"], self.seed, walks=w)
        if "flat" in methods:
            jobs += jobs_for(
                configs, min(self.flat_trials, self.trials), ["flat"], self.seed, walks=w
            )
        return jobs

    def sweep_sizes(self) -> list[int]:
        """Task counts of the flat-LTLf growth sweep (none when flat is not run)."""
        if "flat" not in self.method_list:
            return []
        return [int(x) for x in self.flat_sweep.split(",") if x.strip()]

    def command(self) -> str:
        parts = [
            f"hltl bench suite --trials {self.trials}",
            f"--methods {self.methods}",
            f"--jobs {self.jobs} --seed {self.seed}",
        ]
        if self.executor != "local":
            parts.append(f"--executor {shlex.quote(self.executor)}")
        if self.configs:
            parts.append(f"--configs {self.configs}")
        if self.max_time != 120.0:
            parts.append(f"--max-time {self.max_time:g}")
        if self.walks != "random":
            parts.append(f"--walks {self.walks}")
        if "flat" in self.methods:
            parts.append(
                f"--flat-trials {self.flat_trials} --flat-sweep {shlex.quote(self.flat_sweep)}"
            )
        for flag, v in (("write", self.write), ("figures", self.figures), ("json", self.json)):
            if v is not None:
                parts.append(f"--{flag} {shlex.quote(str(v))}")
        return " ".join(parts)


@dataclass(frozen=True, slots=True)
class SuiteRun:
    """What a suite run measured."""

    options: SuiteOptions
    results: list[TrialResult]
    wall_s: float
    sweep_rows: list[dict[str, Any]]
    sweep_s: float

    @property
    def configs(self) -> list[str]:
        return configs_from(self.options.configs)

    @property
    def shown(self) -> list[str]:
        """Closed-loop methods of Table II, in the paper's order."""
        return [m for m in ("hltl", "greedy", "smart-llm") if m in self.options.loop_methods]

    def to_json(self) -> dict[str, Any]:
        return {
            "command": self.options.command(),
            "wall_s": self.wall_s,
            "results": results_to_json(self.results),
            "flat_sweep": self.sweep_rows,
        }


def run_suite_command(
    options: SuiteOptions, on_result: Callable[[TrialResult], None] | None = None
) -> SuiteRun:
    """Run every job of ``options`` and the flat-LTLf sweep."""
    jobs = options.trial_jobs()
    t0 = time.perf_counter()
    results = run_suite(
        jobs,
        workers=options.jobs,
        on_result=on_result,
        executor=SweepExecutor.parse(options.executor),
    )
    wall = time.perf_counter() - t0
    sweep_rows: list[dict[str, Any]] = []
    sweep_s = 0.0
    sizes = options.sweep_sizes()
    if sizes:
        t1 = time.perf_counter()
        sweep_rows = [
            c.to_dict() for c in sweep(sizes, limit=options.flat_limit, seed=options.seed)
        ]
        sweep_s = time.perf_counter() - t1
    return SuiteRun(options, results, wall, sweep_rows, sweep_s)


def _check_walks(walks: str) -> None:
    if walks not in WALKS:
        raise HltlError(f"--walks: unknown kind {walks[:40]!r}; expected one of {', '.join(WALKS)}")


ABLATION_VARIANTS = ("full", "no-pp", "no-pmp", "goal", "antic-goal", "antic-gru")
PMP_MODES = ("measured", "model")


@dataclass(frozen=True, slots=True)
class AblationOptions:
    """What ``hltl bench ablation`` runs (its command-line options).

    ``plan_latency`` None charges the latency model (``latency_model``, default the shipped
    measurement) where computation occurs; a number charges that constant on every planner
    call instead (the old, assumed model, kept for comparison). Either way each robot-to-robot
    handover in a new plan's first step adds the motion layer's candidate planning: with
    ``pmp`` ``measured`` (the default) the motion layer plans it there and then, on a process
    pool, or serially for ``no-pmp``, and the measured seconds are charged; with ``model`` a
    fixed latency per handover (``pmp_latency``, default the shipped ``hltl bench pmp``
    measurement of the Fig. 1 handover), parallel or serial.
    """

    trials: int = 20
    configs: str = ""
    jobs: int = 2
    seed: int = 0
    plan_latency: float | None = None
    pmp_latency: Path | None = None
    latency_model: Path | None = None
    pmp_mode: str = "measured"
    variants_text: str = ",".join(ABLATION_VARIANTS)
    walks: str = "random"
    write: Path | None = None
    json: Path | None = None
    executor: str = "local"

    def __post_init__(self) -> None:
        if self.trials < 1 or self.jobs < 1:
            raise HltlError("--trials and --jobs must be at least 1")
        SweepExecutor.parse(self.executor)
        if self.plan_latency is not None and self.plan_latency < 0:
            raise HltlError("--plan-latency must be >= 0")
        _check_walks(self.walks)
        if self.pmp_mode not in PMP_MODES:
            modes = ", ".join(PMP_MODES)
            raise HltlError(f"--pmp: unknown mode {self.pmp_mode[:40]!r}; expected one of {modes}")
        if self.pmp_latency is not None and self.pmp_mode != "model":
            raise HltlError("--pmp-latency is the latency charged with --pmp model: give both")
        for name in self.variant_names:
            if name not in ABLATION_VARIANTS:
                raise HltlError(
                    f"--variants: unknown variant {name[:40]!r}; expected some of "
                    f"{', '.join(ABLATION_VARIANTS)}"
                )

    @property
    def variant_names(self) -> list[str]:
        return [v.strip() for v in self.variants_text.split(",") if v.strip()]

    def latency(self) -> LatencyModel | None:
        """The latency model charged (None when a constant ``plan_latency`` is)."""
        if self.plan_latency is not None:
            return None
        return load_latency_model(
            self.latency_model if self.latency_model is not None else DEFAULT_LATENCY_MODEL
        )

    def pmp(self) -> PmpLatency:
        """The candidate-planning latencies charged for robot-to-robot handovers."""
        return load_pmp_latency(self.pmp_latency if self.pmp_latency is not None else DEFAULT_PMP)

    def variants(self) -> list[Variant]:
        """Table III's rows: full, without predictive planning, serial candidate planning, and
        the predictor / anticipatory-execution rows (docs/evaluation.md#ablations)."""
        lat = self.latency()
        const = 0.0 if self.plan_latency is None else self.plan_latency
        if self.pmp_mode == "measured":
            par = ser = 0.0
            pm, sm = "parallel", "serial"
        else:
            pmp = self.pmp()
            par, ser = pmp.parallel_s, pmp.serial_s
            pm = sm = ""
        table = {
            "full": Variant("full", True, const, lat, r2r_motion_s=par, motion=pm),
            "no-pp": Variant("no-pp", False, const, lat, r2r_motion_s=par, motion=pm),
            "no-pmp": Variant("no-pmp", True, const, lat, r2r_motion_s=ser, motion=sm),
            "goal": Variant("goal", True, const, lat, "goal", r2r_motion_s=par, motion=pm),
            "antic-goal": Variant(
                "antic-goal", True, const, lat, "goal", True, r2r_motion_s=par, motion=pm
            ),
            "antic-gru": Variant(
                "antic-gru", True, const, lat, "gru", True, r2r_motion_s=par, motion=pm
            ),
        }
        return [table[n] for n in self.variant_names]

    def trial_jobs(self) -> list[TrialJob]:
        return jobs_for(
            configs_from(self.configs),
            self.trials,
            ["hltl"],
            self.seed,
            self.variants(),
            walks=self.walks,
        )

    def command(self) -> str:
        parts = [
            f"hltl bench ablation --trials {self.trials} --jobs {self.jobs} --seed {self.seed}"
        ]
        if self.plan_latency is not None:
            parts.append(f"--plan-latency {self.plan_latency:g}")
        if self.latency_model is not None:
            parts.append(f"--latency-model {shlex.quote(str(self.latency_model))}")
        if self.pmp_mode != "measured":
            parts.append(f"--pmp {self.pmp_mode}")
        if self.pmp_latency is not None:
            parts.append(f"--pmp-latency {shlex.quote(str(self.pmp_latency))}")
        if self.executor != "local":
            parts.append(f"--executor {shlex.quote(self.executor)}")
        if self.walks != "random":
            parts.append(f"--walks {self.walks}")
        if self.variant_names != list(ABLATION_VARIANTS):
            parts.append(f"--variants {','.join(self.variant_names)}")
        if self.configs:
            parts.append(f"--configs {self.configs}")
        if self.write:
            parts.append(f"--write {shlex.quote(str(self.write))}")
        if self.json:
            parts.append(f"--json {shlex.quote(str(self.json))}")
        return " ".join(parts)


def solved_by_all(
    results: Iterable[TrialResult], variants: Sequence[Variant]
) -> set[tuple[str, int]]:
    """The (configuration, trial) pairs every variant solved: paired times compare those."""
    names = [v.name for v in variants]
    solved: dict[tuple[str, int], set[str]] = {}
    for r in results:
        if r.status == "ok" and r.success and r.time_cost is not None:
            solved.setdefault((r.config, r.index), set()).add(r.variant)
    return {k for k, vs in solved.items() if all(n in vs for n in names)}


def ablation_extra(
    results: Sequence[TrialResult], variants: Sequence[Variant]
) -> dict[str, dict[str, float]]:
    """Per variant (Table III's added columns): success rate, mean time cost over its
    successful trials and over the trials every variant solved (paired, so variants are
    compared on the same trials), takeovers, anticipatory dispatches and the computation time
    charged on the critical path per trial."""
    ok = [r for r in results if r.status == "ok"]
    common = solved_by_all(ok, variants)
    extra: dict[str, dict[str, float]] = {}
    for v in variants:
        rs = [r for r in ok if r.variant == v.name]
        times = [r.time_cost for r in rs if r.success and r.time_cost is not None]
        paired = [
            r.time_cost for r in rs if (r.config, r.index) in common and r.time_cost is not None
        ]

        def mean(key: str, rs: list[TrialResult] = rs) -> float:
            return statistics.fmean(float(r.extra.get(key, 0)) for r in rs) if rs else math.nan

        extra[v.name] = {
            "success %": 100.0 * sum(r.success for r in rs) / max(1, len(rs)),
            "time cost s": statistics.fmean(times) if times else math.nan,
            "time paired s": statistics.fmean(paired) if paired else math.nan,
            "takeovers/trial": mean("takeovers"),
            "anticip./trial": mean("anticipations"),
            "charged ms/trial": 1000.0 * mean("charged_s"),
            "motion ms/trial": 1000.0 * mean("motion_s"),
        }
    return extra
