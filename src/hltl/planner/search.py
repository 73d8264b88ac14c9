"""Exact search over the unified graph: on-the-fly Dijkstra and A* to the accepting set F."""

from __future__ import annotations

import functools
import gc
import heapq
import itertools
import math
from collections.abc import Callable, Iterator, Sequence
from typing import Any, ParamSpec, TypeVar

from hltl.planner.bindings import derive_bindings
from hltl.planner.clock import WALL, Clock
from hltl.planner.explain import explain_infeasible
from hltl.planner.heuristic import NO_HOT, Heuristic, Hot
from hltl.planner.problem import Instance, Node, Problem, to_seconds
from hltl.planner.result import PlanResult, PlanStatus, PlanStep, SearchStats
from hltl.spec.monitor import DONE

ALGORITHMS = ("astar", "dijkstra")
PAIRS_AFTER = 300  # expansions before A* also uses the pairwise bound
CHECK_EVERY = 64  # successors generated between two looks at the clock inside one expansion

# The step that reached a node, as (robots acting: bit mask, objects moved: bit mask, duration in
# ticks, places left: bit mask over (object, place) pairs, see ``_Search.undoes``). Left-shift
# rule: an instance no monitor can see, whose robots were idle and whose object stayed put in
# that step, and that would not have made it longer, could have run in it instead (it was
# applicable then: only a step's own robots change what they hold). Moving it there keeps every
# symbol, every later precondition and every later duration and makes no step longer, so some
# optimal plan never delays such an instance, and the search need not generate it. A node
# reached by several equally cheap steps keeps all their tags; an instance is skipped only when
# every tag allows it to shift. Undone steps: an instance that takes an object straight back to
# where an instance of the step before took it from (both invisible, fixed durations) is never
# generated either (docs/planner.md, "Undone steps"), again only when every tag says so.
Tag = tuple[int, int, int, int]
# A node's labels as the search stores them, against the labels it had when a step reached it:
# ``perm[o]`` is the object whose place canonical object ``o`` took (``None``: no relabelling).
Perm = tuple[int, ...] | None


class Live:
    """What another thread may tell a running ``search`` (its ``live``): a smaller ``upper``
    (only plans cheaper than it are wanted from then on) or to stop (``stopped``: the search
    returns ``timeout`` at its next expansion)."""

    def __init__(self, upper: int | None = None) -> None:
        self.upper = upper
        self.stopped = False


class _Search:
    """One search run; kept as an object so successor generation can reuse its memo tables."""

    def __init__(self, problem: Problem) -> None:
        self.p = problem
        self.monitor = problem.monitor
        self._step_memo: dict[tuple[object, int], object] = {}
        self._after: dict[object, dict[int, object]] = {}
        self._done_memo: dict[object, frozenset[str]] = {}
        self.heuristic = Heuristic(problem, self.done)
        self._dead_memo: dict[object, frozenset[int]] = {}
        self._sym_memo: dict[object, tuple[tuple[int, ...], ...]] = {}
        self._classes = problem.symmetry.classes
        self._sym_objects = sum(1 << o for members in self._classes for o, _ in members)
        # per instance, the robots that must hold nothing for it (``Instance.free``) as a mask
        self._free_mask = [0] * len(problem.instances)
        for inst in problem.instances:
            self._free_mask[inst.index] = sum(1 << r for r in set(inst.free))
        # undone steps (see ``Tag``): per instance, the bit a step with it sets in its tag (its
        # object's place before it) and the bit that, set in every tag of a node, means it would
        # take its object straight back (its object's place after it); 0 where the rule does
        # not hold (``undoes``)
        self._n_locs = len(problem.locs)
        self._back_bit = [0] * len(problem.instances)
        self._undo_bit = [0] * len(problem.instances)
        for inst in problem.instances:
            if self.undoes(inst):
                self._back_bit[inst.index] = 1 << (inst.obj * self._n_locs + inst.pre)
                self._undo_bit[inst.index] = 1 << (inst.obj * self._n_locs + inst.post)
        # (child index, parent index), parents first: once a node is done its descendants can
        # no longer matter, so they are marked done too and equivalent states merge
        index = {n: i for i, n in enumerate(self.monitor.nodes)}
        spec = problem.spec
        self._links = tuple(
            (index[c], index[spec.parent[c]]) for c in self.monitor.nodes if c in spec.parent
        )

    def undoes(self, inst: Instance) -> bool:
        """Whether ``inst`` takes part in the undone-steps rule: with fixed durations, an
        instance no monitor can see whose robots include whoever holds its object before it and
        after it. If such an instance j moves an object from X to Y in a step and such an
        instance i moves it from Y straight back to X in the next one, leaving both out keeps
        every other instance of the two steps applicable (the robots holding the object at X
        and Y act in i and j, so no other instance of those steps needs their hands), every
        symbol (the steps stay, emptied or not), the node after them, and makes neither step
        longer: an optimal plan has fewer instances, and so one without such a pair exists
        (docs/planner.md, "Undone steps")."""
        p = self.p
        if p.track_hands or not p.invisible[inst.index]:
            return False
        for code in (inst.pre, inst.post):
            r = p.code_holder.get(code)
            if r is not None and not inst.executors >> r & 1:
                return False
        return True

    def done(self, q: object) -> frozenset[str]:
        d = self._done_memo.get(q)
        if d is None:
            d = self.monitor.done(q)  # type: ignore[arg-type]
            self._done_memo[q] = d
        return d

    def monitor_step(self, q: object, bits: int) -> object:
        """The monitor state after a step whose symbol is the spec atoms in ``bits``."""
        key = (q, bits)
        nq = self._step_memo.get(key)
        if nq is None:
            stepped = list(self.monitor.step(q, self.p.bits_atoms(bits)))  # type: ignore[arg-type]
            for c, parent in self._links:
                if stepped[parent] == DONE:
                    stepped[c] = DONE
            nq = tuple(stepped)
            if nq == q:
                nq = q  # the same object: the heuristic recognises its own state by identity
            self._step_memo[key] = nq
        return nq

    def symmetric(self, q: object) -> tuple[tuple[int, ...], ...]:
        """Per class of interchangeable objects, its members whose leaf has not fired in ``q``
        (at least two): their places may be permuted freely (``Problem.symmetry``)."""
        hit = self._sym_memo.get(q)
        if hit is None:
            done = self.done(q)
            groups = []
            for members in self._classes:
                live = tuple(o for o, leaf in members if leaf is None or leaf not in done)
                if len(live) > 1:
                    groups.append(live)
            hit = tuple(groups)
            self._sym_memo[q] = hit
        return hit

    def canonical(self, node: Node) -> tuple[Node, Perm]:
        """The representative of ``node`` among its relabellings by interchangeable objects:
        the unfired members of each class take their places in ascending order."""
        groups = self.symmetric(node[2])
        if not groups:
            return node, None
        locs = node[0]
        perm: list[int] | None = None
        new_locs: list[int] | None = None
        for members in groups:
            prev = -1
            for o in members:
                if locs[o] < prev:
                    break
                prev = locs[o]
            else:
                continue  # already in order
            if perm is None:
                perm = list(range(len(locs)))
                new_locs = list(locs)
            assert new_locs is not None
            order = sorted(members, key=locs.__getitem__)
            for o, src in zip(members, order, strict=True):
                new_locs[o] = locs[src]
                perm[o] = src
        if perm is None or new_locs is None:
            return node, None
        return (tuple(new_locs), node[1], node[2]), tuple(perm)

    def dead(self, q: object) -> frozenset[int]:
        """Instances that would make an atom every accepting continuation from ``q`` needs
        impossible: no successor through them can reach F, so they are never generated."""
        d = self._dead_memo.get(q)
        if d is None:
            graph = self.heuristic.graph
            d = frozenset().union(
                *(graph.dead_instances(a) for a in self.heuristic.required_atoms(q))  # type: ignore[arg-type]
            )
            self._dead_memo[q] = d
        return d

    def options(
        self, node: Node, tags: Sequence[Tag] = ()
    ) -> tuple[list[list[Instance]], frozenset[int]]:
        """Per object worth touching, the instances whose state preconditions hold and that are
        not left-shiftable into the step that reached ``node`` (see ``Tag``); and the indices of
        those among them that would shift into every such step but for their duration (a step
        made of these only is never generated: see ``steps``)."""
        locs, hands, q = node
        p = self.p
        dead = self.dead(q)
        shiftable = p.shiftable
        holder_of = p.code_holder
        free_mask = self._free_mask
        busy = 0
        for code in locs:
            r = holder_of.get(code)
            if r is not None:
                busy |= 1 << r
        # an instance shifts into every step that reached the node when it shares no robot and
        # no object with any of them, and fits the shortest
        acting = moved = 0
        back = -1 if tags else 0  # the places every way in took an object from
        for e, m, _, b in tags:
            acting |= e
            moved |= m
            back &= b
        shortest = min((d for _, _, d, _ in tags), default=0)
        undo_bit = self._undo_bit
        relevant = p.relevant(self.done(q))
        out: list[list[Instance]] = []
        late: set[int] = set()
        prune = p.prune_irrelevant
        for o, code in enumerate(locs):
            if prune and o not in relevant and code not in holder_of:
                continue
            cands: list[Instance] = []
            for inst in p.by_obj_pre[o][code]:
                if inst.index in dead or busy & free_mask[inst.index]:
                    continue
                if back & undo_bit[inst.index]:
                    continue  # it would take its object straight back (see ``Tag``)
                if (
                    tags
                    and shiftable[inst.index]
                    and not inst.executors & acting
                    and not moved >> inst.obj & 1
                ):
                    if hands is None:
                        fits = inst.lower <= shortest
                    else:
                        fits = _at_most(p.duration(inst, hands), shortest)
                    if fits:
                        continue  # left-shiftable: some optimal plan ran it one step earlier
                    late.add(inst.index)
                cands.append(inst)
            if cands:
                out.append(cands)
        return out, frozenset(late)

    def steps(
        self, node: Node, tags: Sequence[Tag] = ()
    ) -> Iterator[tuple[tuple[Instance, ...], int, Node, Tag, Perm]]:
        """All successors: every set U of applicable instances with disjoint robots, with its
        duration, the node it leads to (canonical, see ``canonical``), its tag (in the child's
        labels) and the relabelling.

        Steps that some instances shifted into the step before would make no longer are left
        out too. Let L be the chosen instances that would shift into that step but for their
        duration (``options``), R the others. Moving L into the step before turns durations
        d₁ (before), max(d(L), d(R)) into max(d₁, d(L)), d(R): no longer in total when R is
        empty (the two steps merge, max(d₁, d(L)) < d₁ + d(L)), or when d(R) ≤ d₁ and
        d(R) ≤ d(L) (fixed durations: then max(d₁, d(L)) + d(R) ≤ d₁ + d(L)). Every such move
        runs an instance earlier, so an optimal plan in which no move applies exists, and the
        search keeps it (docs/planner.md, "Left-shift rule")."""
        locs, hands, q = node
        opts, late = self.options(node, tags)
        # the shortest step that reached the node (``late`` holds for every way in)
        before = min((d for _, _, d, _ in tags), default=0) if hands is None else -1
        sym = self._sym_objects
        # fixed durations and no state atoms: the step is applied inline (the hot path)
        inline = hands is None and not self.p.state_atom_objects
        # the monitor's next state per step symbol, from this node's state: one lookup per
        # successor by the symbol alone
        after = self._after.get(q)
        if after is None:
            after = self._after[q] = {}
        monitor_step = self.monitor_step
        back_bits = self._back_bit
        # every step set once, depth-first: a set is yielded before the sets that add
        # instances of later objects to it, the last object's first (the order in which the
        # sets come decides ties in the open list, so it is kept). The candidates are flat, per
        # object in ascending order and each object's instances in reverse, so that a set's
        # extensions are pushed in one pass over the candidates from its first free object on;
        # each with where the next object's candidates begin. A stack entry per set (not per
        # set and object) saves most of the tuples the search would build
        flat: list[tuple[int, int, int, int, bool, Instance, int]] = []
        for cands in opts:
            nxt = len(flat) + len(cands)
            for inst in reversed(cands):
                flat.append(
                    (
                        inst.executors,
                        inst.lower,
                        1 << inst.obj,
                        inst.event_bits,
                        inst.index in late,
                        inst,
                        nxt,
                    )
                )
        total = len(flat)
        # the next candidate, the robots acting, the objects moved, the events, the duration,
        # and the longest chosen instance among the late ones and among the others (-1: none)
        stack: list[tuple[int, int, int, int, int, int, int, tuple[Instance, ...]]] = [
            (0, 0, 0, 0, 0, -1, -1, ())
        ]
        while stack:
            k, used, moved, events, cost, late_d, rest_d, chosen = stack.pop()
            for j in range(k, total):
                ex, d, bit, ev, is_late, inst, nxt = flat[j]
                if ex & used:
                    continue
                if is_late:
                    nl, nr = (d if d > late_d else late_d), rest_d
                else:
                    nl, nr = late_d, (d if d > rest_d else rest_d)
                stack.append(
                    (
                        nxt,
                        used | ex,
                        moved | bit,
                        events | ev,
                        d if d > cost else cost,
                        nl,
                        nr,
                        (*chosen, inst),
                    )
                )
            if late_d >= 0 and (rest_d < 0 or (rest_d <= before and rest_d <= late_d)):
                continue
            back = 0  # the places its instances take objects from (undone steps: ``Tag``)
            if inline:
                new_locs = list(locs)
                for inst in chosen:
                    new_locs[inst.obj] = inst.post
                    back |= back_bits[inst.index]
                nq = after.get(events)
                if nq is None:
                    nq = after[events] = monitor_step(q, events)
                child: Node = (tuple(new_locs), None, nq)  # type: ignore[assignment]
            else:
                applied = self.apply(node, chosen)
                if applied is None:  # a chosen instance has no motion from these hands
                    continue
                cost, child = applied
                for inst in chosen:
                    back |= back_bits[inst.index]
            if not chosen and child[2] == q:
                continue
            # the node is canonical and a step that moves no twin keeps it so (a leaf firing
            # only drops a twin from its class, and what remains stays in order)
            if moved & sym:
                child, perm = self.canonical(child)
                if perm is not None:
                    moved = _relabel(moved, perm)
                    if back:
                        back = _relabel_places(back, perm, self._n_locs)
                yield chosen, cost, child, (used, moved, cost, back), perm
            else:
                yield chosen, cost, child, (used, moved, cost, back), None

    def apply(self, node: Node, U: Sequence[Instance]) -> tuple[int, Node] | None:
        """The step ``U`` from ``node`` (preconditions assumed): its duration in ticks and the
        node after it; ``None`` when an instance of it cannot be done from the node's hands
        (the cost model found no motion)."""
        locs, hands, q = node
        p = self.p
        new_locs = list(locs)
        events = 0
        cost = 0
        if hands is None:  # fixed durations: the hot path
            for inst in U:
                new_locs[inst.obj] = inst.post
                events |= inst.event_bits
                if inst.lower > cost:
                    cost = inst.lower
            for o in p.state_atom_objects:
                events |= p.state_bits[o][new_locs[o]]
            return cost, (tuple(new_locs), None, self.monitor_step(q, events))  # type: ignore[return-value]
        new_hands = list(hands)
        chained = p.chained is not None
        for inst in U:
            new_locs[inst.obj] = inst.post
            events |= inst.event_bits
            d = p.duration(inst, hands)
            if d is None:
                return None
            if d > cost:
                cost = d
            for r, pt in p.ends(inst, hands) if chained else inst.hands:
                new_hands[r] = pt
        state_bits = p.state_bits
        for o in p.state_atom_objects:
            events |= state_bits[o][new_locs[o]]
        nq = self.monitor_step(q, events)
        child = (tuple(new_locs), tuple(new_hands), nq)
        return cost, child  # type: ignore[return-value]


_P = ParamSpec("_P")
_R = TypeVar("_R")


def _without_cycle_collector(run: Callable[_P, _R]) -> Callable[_P, _R]:
    """``run`` with Python's cyclic garbage collector off (and back on after, if it was on).
    A search allocates millions of tuples and lists that live as long as it does (the open
    list, a record per node): every 700 allocations the collector scans the young ones, and
    the old generation's full scans grow with the search. It finds next to nothing to free
    there (23 objects in line 10 x 10 seed 4's first 30k expansions), and took about a fifth
    of the search's CPU (docs/planner.md, "The cyclic garbage collector"). Reference counting
    frees everything else as before; the results do not change."""

    @functools.wraps(run)
    def wrapped(*args: _P.args, **kwargs: _P.kwargs) -> _R:
        was_on = gc.isenabled()
        gc.disable()
        try:
            return run(*args, **kwargs)
        finally:
            if was_on:
                gc.enable()

    return wrapped


@_without_cycle_collector
def search(
    problem: Problem,
    *,
    algorithm: str = "astar",
    timeout: float | None = 60.0,
    max_expansions: int | None = None,
    on_progress: Callable[[int, float], None] | None = None,
    pairs_after: int = PAIRS_AFTER,
    upper: int | None = None,
    state: _Search | None = None,
    live: Live | None = None,
    clock: Clock = WALL,
) -> PlanResult:
    """Minimum-makespan path from the problem's start node to the accepting set F.

    Args:
        problem: the compiled problem.
        algorithm: ``"astar"`` (admissible heuristic) or ``"dijkstra"`` (no heuristic).
        timeout: seconds of search before giving up with ``timeout`` status; ``None``: no limit.
            The clock is read at every expansion and every ``CHECK_EVERY`` successors, so the
            search overruns it by at most one heuristic evaluation.
        max_expansions: node budget; exceeding it also yields ``timeout``.
        on_progress: called every 1024 expansions with (expanded, best lower bound in seconds).
        pairs_after: expansions after which A* adds the pairwise bound (0: from the start).
        upper: only plans cheaper than this many ticks are wanted (anytime mode: the incumbent's
            makespan); when none exists the result is ``infeasible`` with ``lower_bound`` equal
            to it, which proves the incumbent optimal.
        state: a search object to reuse (its heuristic tables and memos).
        live: read at every expansion: another thread's smaller ``upper``, or its order to
            stop. Nodes whose f reaches ``upper`` are dropped, which changes no expansion
            below it: the plan found, when it is cheaper than every ``upper`` given, is the
            one found without them.
        clock: where ``timeout`` and the seconds reported are read (``clock.WALL``; tests: a
            ``clock.WorkClock``, which advances at each reading, docs/planner.md "The clock").
    """
    if algorithm not in ALGORITHMS:
        raise ValueError(
            f"unknown algorithm {algorithm!r}; expected one of {', '.join(ALGORITHMS)}"
        )
    now_ = clock.now  # (for ``WALL``, ``time.perf_counter`` itself)
    t0 = now_()
    deadline = math.inf if timeout is None else t0 + timeout
    s = _Search(problem) if state is None else state
    h: Callable[[Node], float]
    cheap: Callable[[Node, Hot], float]
    heur: Heuristic | None = None
    if algorithm == "astar":
        heur = s.heuristic
        h = heur
        # lazy evaluation: a fresh node waits on the open list under its cheap bound; the full
        # one (robot load, pairs) is computed when the node comes to the top, and the node goes
        # back under it if it is larger. Many generated nodes never reach the top. The cheap
        # bound includes the load of the robot that needs the most at the parent.
        cheap = heur.cheap
    else:
        h = _zero
        cheap = _zero2
    start, start_perm = s.canonical(problem.start())
    if problem.monitor.accepted(start[2]):
        return PlanResult(
            PlanStatus.SOLVED,
            (),
            0.0,
            SearchStats(0, 1, now_() - t0, algorithm),
            lower_bound=0.0,
        )
    if pairs_after <= 0 and heur is not None:
        heur.enable_pairs()
    h0 = h(start)
    if math.isinf(h0):
        return _infeasible(problem, s, algorithm, t0, 0, 1, clock=clock)

    counter = itertools.count()
    # per node reached: [g, tags of its equally cheap ways in (see ``Tag``), how many of them
    # it had when it was last expanded (-1: not expanded since its g was set), the way in
    # (parent, step, duration, relabelling; None at the start)]: one dict lookup per child
    recs: dict[Node, list[Any]] = {start: [0, [], -1, None]}
    # costs are integer ticks, so ties and the order of expansion are the same in every run
    heap: list[tuple[float, int, int, Node]] = [(h0, 0, next(counter), start)]
    expanded = generated = 0
    bound = h0  # the least f on the open list never exceeds the optimum: a proven lower bound

    def stop(elapsed: float) -> PlanResult:
        stats = SearchStats(expanded, generated, elapsed, algorithm)
        lb = to_seconds(bound)
        return PlanResult(
            PlanStatus.TIMEOUT,
            stats=stats,
            reason=f"search stopped after {elapsed:.1f} s and {expanded} expansions "
            f"(best lower bound on the makespan: {lb:.3f} s)",
            lower_bound=lb,
        )

    while heap:
        f, neg_g, _, node = heapq.heappop(heap)
        g = -neg_g
        rec = recs[node]
        # stale entry: a cheaper path to this node was found after it was pushed (the heuristic
        # need not be consistent, so a node may be expanded again with a smaller g)
        if g > rec[0]:
            continue
        node_tags = rec[1]
        if rec[2] == len(node_tags):
            continue  # already expanded with this g and these tags
        if upper is not None and f >= upper:
            continue  # (pushed before a smaller ``upper`` came: ``live``)
        if f > bound:
            bound = f  # every key on the open list is a lower bound on its node's f
        if heur is not None:
            full = g + h(node)
            if full > f:
                if not (math.isinf(full) or (upper is not None and full >= upper)):
                    heapq.heappush(heap, (full, neg_g, next(counter), node))
                continue
        rec[2] = len(node_tags)
        if problem.monitor.accepted(node[2]):
            steps = _reconstruct(s, recs, node, start_perm)
            stats = SearchStats(expanded, generated, now_() - t0, algorithm)
            makespan = to_seconds(g)
            return PlanResult(PlanStatus.SOLVED, steps, makespan, stats, lower_bound=makespan)
        expanded += 1
        if expanded == pairs_after and heur is not None:
            # a hard instance: the pairwise bound now pays for its tables
            heur.enable_pairs()
        now = now_()
        if now > deadline or (max_expansions is not None and expanded > max_expansions):
            return stop(now - t0)
        if live is not None:
            if live.stopped:
                return stop(now - t0)
            if live.upper is not None and (upper is None or live.upper < upper):
                upper = live.upper
        if on_progress is not None and expanded % 1024 == 0:
            on_progress(expanded, to_seconds(bound))
        n_children = 0
        hot = NO_HOT if heur is None else heur.hot(node)
        # the start node has no tag: nothing can be shifted into a step before it
        for U, cost, child, tag, perm in s.steps(node, node_tags):
            n_children += 1
            if n_children % CHECK_EVERY == 0 and now_() > deadline:
                return stop(now_() - t0)
            ng = g + cost
            if upper is not None and ng >= upper:
                continue
            crec = recs.get(child)
            if crec is not None and ng >= crec[0]:
                if ng > crec[0]:
                    continue
                # an equally cheap way in: its tag may allow what the others forbid
                child_tags = crec[1]
                if tag in child_tags:
                    continue
                child_tags.append(tag)
                if crec[2] < 0:
                    continue  # not expanded yet: it will see this tag when it is
                hc = cheap(child, hot)
            else:
                hc = cheap(child, hot)
                if math.isinf(hc) or (upper is not None and ng + hc >= upper):
                    continue
                if crec is None:
                    recs[child] = [ng, [tag], -1, (node, U, cost, perm)]
                else:
                    crec[:] = (ng, [tag], -1, (node, U, cost, perm))
                generated += 1
            heapq.heappush(heap, (ng + hc, -ng, next(counter), child))
    if upper is not None:
        stats = SearchStats(expanded, generated, now_() - t0, algorithm)
        lb = to_seconds(upper)
        return PlanResult(
            PlanStatus.INFEASIBLE,
            stats=stats,
            reason=f"no plan shorter than {lb:.3f} s",
            lower_bound=lb,
        )
    return _infeasible(problem, s, algorithm, t0, expanded, generated, clock=clock)


def _zero(_: Node) -> float:
    return 0.0


def _zero2(_: Node, __: Hot) -> float:
    return 0.0


def _infeasible(
    problem: Problem,
    s: _Search,
    algorithm: str,
    t0: float,
    expanded: int,
    generated: int,
    *,
    clock: Clock = WALL,
) -> PlanResult:
    stats = SearchStats(expanded, generated, clock.now() - t0, algorithm)
    return PlanResult(PlanStatus.INFEASIBLE, stats=stats, reason=explain_infeasible(problem))


def _at_most(d: int | None, bound: int) -> bool:
    """A duration fits ``bound`` (an infeasible instance, ``None``, fits nothing)."""
    return d is not None and d <= bound


def _relabel(mask: int, perm: tuple[int, ...]) -> int:
    """An object bit mask in the labels after ``perm``."""
    out = 0
    for o, src in enumerate(perm):
        if mask >> src & 1:
            out |= 1 << o
    return out


def _relabel_places(mask: int, perm: tuple[int, ...], n_locs: int) -> int:
    """A bit mask over (object, place) pairs (bit ``object * n_locs + place``) in the labels
    after ``perm``."""
    out = 0
    row = (1 << n_locs) - 1
    for o, src in enumerate(perm):
        bits = mask >> (src * n_locs) & row
        if bits:
            out |= bits << (o * n_locs)
    return out


def _reconstruct(
    s: _Search,
    recs: dict[Node, list[Any]],
    node: Node,
    start_perm: Perm = None,
) -> tuple[PlanStep, ...]:
    chain: list[tuple[Node, tuple[Instance, ...], int, Perm]] = []
    while (way := recs[node][3]) is not None:
        chain.append(way)
        node = way[0]
    chain.reverse()
    problem = s.p
    if start_perm is None and all(perm is None for *_, perm in chain):
        return plan_steps(problem, [(prev, U, cost) for prev, U, cost, _ in chain])
    # the search stored every node relabelled (interchangeable objects sorted): replay the
    # steps on the real objects, carrying which real object each stored label stands for (the
    # monitor states differ too once a relabelled object's leaf fires)
    real = list(range(len(problem.objects))) if start_perm is None else list(start_perm)
    symmetry = problem.symmetry
    out: list[tuple[Node, tuple[Instance, ...], int]] = []
    node = problem.start()
    for _, U, cost, perm in chain:
        real_U = tuple(symmetry.counterpart(i, real[i.obj]) for i in U)
        applied = s.apply(node, real_U)
        assert applied is not None and applied[0] == cost  # a relabelling changes no duration
        child = applied[1]
        out.append((node, real_U, cost))
        node = child
        if perm is not None:
            real = [real[src] for src in perm]
    assert problem.monitor.accepted(node[2])
    return plan_steps(problem, out)


def plan_steps(
    problem: Problem, chain: Sequence[tuple[Node, tuple[Instance, ...], int]]
) -> tuple[PlanStep, ...]:
    """Plan steps with bindings from (node before, step, duration in ticks) triples."""
    steps: list[PlanStep] = []
    t = 0
    for _, U, cost in chain:
        actions = tuple(sorted(inst.action for inst in U))
        steps.append(PlanStep(to_seconds(t), to_seconds(cost), actions))
        t += cost
    done_before = [problem.monitor.done(prev[2]) for prev, _, _ in chain]
    return derive_bindings(problem, steps, done_before)


def plan_problem(problem: Problem, **kwargs: object) -> PlanResult:
    return search(problem, **kwargs)  # type: ignore[arg-type]


def all_steps(problem: Problem, node: Node) -> Sequence[tuple[tuple[Instance, ...], int, Node]]:
    """Every successor of ``node`` (for tests and debugging)."""
    return [(U, cost, child) for U, cost, child, _, _ in _Search(problem).steps(node)]
