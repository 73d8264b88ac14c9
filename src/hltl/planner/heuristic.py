"""Admissible heuristic: the earliest time the root monitor can fire, bottom-up over the tree."""

from __future__ import annotations

import heapq
import math
import operator
from collections.abc import Callable

from hltl.planner.pairs import PairBound
from hltl.planner.problem import Node, Problem
from hltl.planner.relaxed import RelaxedGraph
from hltl.spec.automata import DFA
from hltl.spec.monitor import DONE, MonitorState
from hltl.spec.syntax import And, Atom, Eventually, Formula, Or

INF = math.inf

# per place of an object: (robot, head, work, tail) for each robot that must act on it
_Rows = list[tuple[tuple[int, float, float, float], ...]]
_Job = tuple[float, float, float]  # (head, work, tail)
# a robot's job at each place of an object, each job's digit, the radix (``_robot_digits``)
_Digits = tuple[list[_Job | None], list[int], int]
# a pair lookup (``pairs.Lookup``) and the monitor state it was made for
_HotPair = tuple[int, int, int, list[float], MonitorState]
# (monitor state, robot, rows, places getter, digit tables, memo): ``Heuristic._robot_entry``
_RobotEntry = tuple[
    MonitorState,
    int,
    tuple[tuple[int, list[tuple[float, float, float] | None]], ...],
    Callable[[tuple[int, ...]], tuple[int, ...]],
    tuple[list[int], ...],
    dict[int, float],
]
# what ``cheap`` bounds besides the critical path: some robots' loads and a pair's bound
Hot = tuple[tuple[_RobotEntry, ...], _HotPair | None]
NO_HOT: Hot = ((), None)


class Heuristic:
    """h(x) for the unified graph; call it on a search node."""

    def __init__(self, problem: Problem, done: Callable[[object], frozenset[str]]) -> None:
        self.p = problem
        self.graph = RelaxedGraph(problem)
        self.done = done
        mon = problem.monitor
        names = {name for name, _ in problem.spec.formulas}
        index = {n: i for i, n in enumerate(mon.nodes)}
        self.root = problem.spec.root
        # per node, deepest first: name, index in q, DFA, and per proposition either
        # ("child", name) or ("atom", Atom)
        self.nodes: list[tuple[str, int, DFA, tuple[tuple[str, object], ...]]] = []
        for name in reversed(mon.nodes):
            dfa = mon.dfas[name]
            props = tuple(
                ("child", a.name) if (not a.args and a.name in names) else ("atom", a)
                for a in dfa.props
            )
            self.nodes.append((name, index[name], dfa, props))
        self._cache: dict[tuple[str, int, tuple[float, ...]], float] = {}
        self._by_name = {name: (i, dfa, props) for name, i, dfa, props in self.nodes}
        self.n_robots = len(problem.robots)
        self._required_cache: dict[MonitorState, frozenset[Atom]] = {}
        self._required_prop_cache: dict[tuple[str, int], tuple[int, ...]] = {}
        self._load_groups: dict[MonitorState, tuple[tuple[int, _Rows], ...]] = {}
        self._rows: dict[tuple[int, tuple[Atom, ...]], _Rows] = {}
        self._machine_memo: dict[tuple[tuple[float, float, float], ...], float] = {}
        self._hot: dict[object, Hot] = {}
        self._robot_entries: dict[tuple[MonitorState, int], _RobotEntry] = {}
        self._all_entries: dict[MonitorState, tuple[_RobotEntry, ...]] = {}
        self._digits: dict[tuple[int, tuple[Atom, ...], int], _Digits] = {}
        # per (object, atoms): each place's jobs by robot (``_robot_digits``)
        self._jobs: dict[tuple[int, tuple[Atom, ...]], list[dict[int, _Job]]] = {}
        self._contrib: dict[
            tuple[tuple[Atom, ...], int], tuple[tuple[int, float, float, float], ...]
        ] = {}
        self._load_tables: dict[
            Atom, tuple[int, list[tuple[int, list[float], list[float], float]]] | None
        ] = {}
        # composites that are positive and/or combinations of "F child": their truth depends only
        # on which children are done (one-shot), so max/min over children is exact and cheap
        self._mono: dict[str, _Mono] = {}
        self._flat_mono: dict[str, _Flat] = {}
        # leaves "F a" whose atom has a place table: h is one list lookup
        self._single: dict[str, tuple[int, list[float]]] = {}
        for name in problem.spec.leaves:
            f = problem.spec.formula(name)
            if isinstance(f, Eventually) and isinstance(f.operand, Atom) and f.operand.args:
                table = self.graph.atom_table(f.operand)
                if table is not None:
                    self._single[name] = table
        self._memo: dict[tuple[tuple[int, ...], MonitorState], float] = {}
        self._crit_memo: dict[tuple[tuple[int, ...], MonitorState], float] = {}
        self.pairs: PairBound | None = None
        self._pair_lookups: dict[MonitorState, list[_HotPair]] = {}
        for name in problem.spec.composites:
            tree = _monotone(problem.spec.formula(name), names)
            if tree is not None:
                self._mono[name] = tree
                self._flat_mono[name] = _flatten(tree)
        # a conjunction of "F leaf" (nested any way) over leaves "F a" with place tables (the
        # delivery cells): the critical path is the largest table value over the leaves that
        # are neither done nor under a done composite, a list kept per monitor state
        self._conj: dict[str, tuple[str, ...]] | None = self._conjunction_tree()
        self._active: dict[MonitorState, tuple[tuple[int, list[float]], ...]] = {}

    def __call__(self, node: Node) -> float:
        locs, _, q = node
        key = (locs, q)
        hit = self._memo.get(key)
        if hit is not None:
            return hit
        critical = self._crit_memo.pop(key, None)
        if critical is None:
            critical = self._critical(locs, q)
        value = self._full(locs, q, critical, key)
        self._memo[key] = value
        return value

    def cheap(self, node: Node, hot: Hot = NO_HOT) -> float:
        """The critical-path bound, and the parts of the full value that ``hot`` names (the
        loads of some robots, one pair's bound): admissible, a fraction of the cost of the
        full value, which it never exceeds. The search orders fresh nodes by it and computes
        the full value only for the nodes it pops; it passes the parent's ``hot``: the two
        robots that need the most and the largest pair there mostly are at the child too,
        so fewer children are popped only to go back under their full value."""
        locs, _, q = node
        key = (locs, q)
        hit = self._memo.get(key)
        if hit is not None:
            return hit
        hit = self._crit_memo.get(key)
        if hit is None:
            hit = self._critical(locs, q)
            robots, pair = hot
            if hit != INF:
                # the pair first: where it is infinite (two objects that must cross each other
                # both held, facing, on a line) the loads need not be computed
                if pair is not None and pair[4] is q:
                    v = pair[3][locs[pair[0]] * pair[2] + locs[pair[1]]]
                    if v > hit:
                        hit = v
                if hit != INF:
                    for entry in robots:
                        if entry[0] is not q:
                            entry = self._robot_entry(q, entry[1])
                        load = self._robot_load(locs, entry)
                        if load > hit:
                            hit = load
            self._crit_memo[key] = hit
        return hit

    def hot(self, node: Node) -> Hot:
        """The two robots whose load bounds and the pair whose bound were the largest at
        ``node`` when its full value was computed (none when it was not)."""
        return self._hot.get((node[0], node[2]), NO_HOT)

    def _full(
        self, locs: tuple[int, ...], q: MonitorState, critical: float, key: object = None
    ) -> float:
        if critical == INF or self.n_robots < 2:
            return critical
        load, robots = self._load_bound(locs, q)
        bound = max(critical, load)
        pair = None
        if self.pairs is not None:
            value, pair = self._pair_bound(locs, q)
            bound = max(bound, value)
        if key is not None:
            self._hot[key] = (
                tuple(self._robot_entry(q, r) for r in robots if r >= 0),
                pair,
            )
        return bound

    def _conjunction_tree(self) -> dict[str, tuple[str, ...]] | None:
        """Per composite its children, when every composite is a conjunction of ``F child`` and
        every leaf has a place table; else None."""
        children: dict[str, tuple[str, ...]] = {}
        for name, flat in self._flat_mono.items():
            is_and, items = flat
            if not is_and or not all(type(x) is str for x in items):
                return None
            children[name] = tuple(str(x) for x in items)
        spec = self.p.spec
        if set(children) != set(spec.composites) or not set(spec.leaves) <= set(self._single):
            return None
        return children

    def _active_leaves(self, q: MonitorState) -> tuple[tuple[int, list[float]], ...]:
        """(object, place table) of every leaf that neither it nor a composite above it is
        done in ``q`` (conjunction trees only, see ``_conjunction_tree``)."""
        assert self._conj is not None
        done = self.done(q)
        out: list[tuple[int, list[float]]] = []
        stack = [self.root]
        while stack:
            name = stack.pop()
            if name in done:
                continue
            kids = self._conj.get(name)
            if kids is None:
                out.append(self._single[name])
            else:
                stack.extend(kids)
        res = tuple(out)
        self._active[q] = res
        return res

    def _critical(self, locs: tuple[int, ...], q: MonitorState) -> float:
        if self._conj is not None:
            active = self._active.get(q)
            if active is None:
                active = self._active_leaves(q)
            best = 0.0
            for o, table in active:
                v = table[locs[o]]
                if v > best:
                    best = v
            return best
        done = self.done(q)
        h: dict[str, float] = {}
        atom_time = self.graph.atom_time
        for name, i, dfa, props in self.nodes:
            state = q[i]
            if state == DONE:
                h[name] = 0.0
                continue
            mono = self._mono.get(name)
            if mono is not None:
                h[name] = _flat_bound(self._flat_mono[name], h, done)
                continue
            single = self._single.get(name)
            if single is not None:
                # a leaf "F a" that has not fired: a has not happened yet
                h[name] = single[1][locs[single[0]]]
                continue
            costs: list[float] = []
            for kind, ref in props:
                if kind == "child":
                    assert isinstance(ref, str)
                    costs.append(INF if ref in done else h[ref])
                else:
                    assert isinstance(ref, Atom)
                    costs.append(atom_time(ref, locs))
            h[name] = self._bottleneck(name, dfa, state, tuple(costs))
            if name == self.root:
                break
        return h[self.root]

    def enable_pairs(self) -> None:
        """Also use the pairwise bound (worth its set-up cost only on hard instances)."""
        if self.pairs is None:
            self.pairs = PairBound(self.p, self.graph)
            self._memo.clear()

    def _pair_bound(self, locs: tuple[int, ...], q: MonitorState) -> tuple[float, _HotPair | None]:
        assert self.pairs is not None
        lookups = self._pair_lookups.get(q)
        if lookups is None:
            lookups = [(*lk, q) for lk in self.pairs.lookups(sorted(self.required_atoms(q)))]
            self._pair_lookups[q] = lookups
        best = 0.0
        arg = None
        for lk in lookups:  # pair_value, inlined: called for every node
            v = lk[3][locs[lk[0]] * lk[2] + locs[lk[1]]]
            if v > best:
                best, arg = v, lk
        return best, arg

    # -- robot load ------------------------------------------------------------------------------
    def _load_bound(self, locs: tuple[int, ...], q: MonitorState) -> tuple[float, tuple[int, int]]:
        """max over robots of the time it must spend on objects every accepting run needs, and
        the two robots that need the most (-1: none)."""
        entries = self._all_entries.get(q)
        if entries is None:
            groups = self._groups(q)
            robots = sorted({r for _, by_place in groups for row in by_place for r, *_ in row})
            entries = self._all_entries[q] = tuple(self._robot_entry(q, r) for r in robots)
        best = 0.0
        hot = -1
        second = -1
        memo2 = -1.0
        robot_load = self._robot_load
        for entry in entries:
            t = robot_load(locs, entry)
            if t <= 0.0:
                continue  # no job here
            if t > best:
                best, hot, second, memo2 = t, entry[1], hot, best
            elif t > memo2:
                second, memo2 = entry[1], t
        return best, (hot, second)

    def _groups(self, q: MonitorState) -> tuple[tuple[int, _Rows], ...]:
        """Per object with jobs in ``q``: its rows (``_rows_by_place``)."""
        groups = self._load_groups.get(q)
        if groups is None:
            groups = tuple(
                (o, self._rows_by_place(o, atoms_))
                for o, atoms_ in self._group_by_object(self.required_atoms(q))
            )
            self._load_groups[q] = groups
        return groups

    def _robot_entry(self, q: MonitorState, robot: int) -> _RobotEntry:
        """What ``_robot_load`` needs for ``robot`` in ``q``: per object the robot's job
        (head, work, tail) at each of its places (None: no job there), and a key that names
        the robot's job list at a node: one digit per object, the index of its job there
        among that object's distinct jobs for the robot (0: none), read off ``locs`` through
        an ``itemgetter`` and one table per object."""
        entry = self._robot_entries.get((q, robot))
        if entry is None:
            rows = []
            tables = []
            scale = 1
            for o, atoms_ in self._group_by_object(self.required_atoms(q)):
                mine, digits, radix = self._robot_digits(o, atoms_, robot)
                if radix == 1:
                    continue
                rows.append((o, mine))
                tables.append([d * scale for d in digits])
                scale *= radix
            objs = [o for o, _ in rows]
            places = operator.itemgetter(*objs) if len(objs) > 1 else _one_place(objs)
            entry = (q, robot, tuple(rows), places, tuple(tables), {})
            self._robot_entries[(q, robot)] = entry
        return entry

    def _robot_digits(self, o: int, atoms_: tuple[Atom, ...], robot: int) -> _Digits:
        """``robot``'s job at each place of object ``o`` for ``atoms_`` (None: none), each
        job's digit (0: none, else 1 + its index among the distinct jobs) and the radix."""
        key = (o, atoms_, robot)
        hit = self._digits.get(key)
        if hit is None:
            # (one dict per place, shared by every robot: a scan of each place's row per robot
            # was 0.15-0.2 s of a 32-robot cell's first heuristic call, its first plan's time)
            jobs_at = self._jobs.get((o, atoms_))
            if jobs_at is None:
                jobs_at = [
                    {r: (hd, v, tl) for r, hd, v, tl in row}
                    for row in self._rows_by_place(o, atoms_)
                ]
                self._jobs[(o, atoms_)] = jobs_at
            mine = [at.get(robot) for at in jobs_at]
            jobs = sorted({j for j in mine if j is not None})
            digit = {j: k + 1 for k, j in enumerate(jobs)}
            hit = (mine, [0 if j is None else digit[j] for j in mine], len(jobs) + 1)
            self._digits[key] = hit
        return hit

    def _robot_load(self, locs: tuple[int, ...], entry: _RobotEntry) -> float:
        """One robot's part of ``_load_bound``, memoised by its job list's key."""
        key = sum(map(_getitem, entry[4], entry[3](locs)))
        memo = entry[5]
        t = memo.get(key)
        if t is None:
            jobs = [job for o, by_place in entry[2] if (job := by_place[locs[o]]) is not None]
            if not jobs:
                t = 0.0
            else:
                jkey = tuple(jobs)
                t = self._machine_memo.get(jkey)
                if t is None:
                    t = _one_machine_bound(jobs)
                    self._machine_memo[jkey] = t
            memo[key] = t
        return t

    def _rows_by_place(self, o: int, atoms_: tuple[Atom, ...]) -> _Rows:
        key = (o, atoms_)
        hit = self._rows.get(key)
        if hit is None:
            hit = [self._contributions(o, atoms_, loc) for loc in range(len(self.p.locs))]
            self._rows[key] = hit
        return hit

    def _group_by_object(self, atoms_: frozenset[Atom]) -> tuple[tuple[int, tuple[Atom, ...]], ...]:
        by_obj: dict[int, list[Atom]] = {}
        for atom in sorted(atoms_):
            table = self._load_table(atom)
            if table is not None and table[1]:
                by_obj.setdefault(table[0], []).append(atom)
        return tuple((o, tuple(a)) for o, a in sorted(by_obj.items()))

    def _contributions(
        self, o: int, atoms_: tuple[Atom, ...], loc: int
    ) -> tuple[tuple[int, float, float, float], ...]:
        """Per robot that must act on object ``o`` (at place ``loc``) to make all of ``atoms_``
        true: (robot, head, work, tail), combined over the atoms (least head and tail, most
        work: one route may serve several atoms)."""
        key = (atoms_, loc)
        hit = self._contrib.get(key)
        if hit is not None:
            return hit
        merged: dict[int, list[float]] = {}
        for atom in atoms_:
            table = self._load_table(atom)
            assert table is not None
            for r, load, heads, tl in table[1]:
                v = load[loc]
                if v <= 0.0:
                    continue
                job = merged.get(r)
                if job is None:
                    merged[r] = [heads[loc], v, tl]
                else:
                    job[0] = min(job[0], heads[loc])
                    job[1] = max(job[1], v)
                    job[2] = min(job[2], tl)
        out = tuple((r, j[0], j[1], j[2]) for r, j in sorted(merged.items()))
        self._contrib[key] = out
        return out

    def _load_table(
        self, atom: Atom
    ) -> tuple[int, list[tuple[int, list[float], list[float], float]]] | None:
        """The atom's object and, for each robot that some route to it needs, its load per
        place, head per place and tail (computed once per atom)."""
        if atom in self._load_tables:
            return self._load_tables[atom]
        graph = self.graph
        g = graph.goal(atom)
        table: tuple[int, list[tuple[int, list[float], list[float], float]]] | None = None
        if g is not None:
            rows = []
            for r in range(self.n_robots):
                load = graph.robot_load(atom, r)
                if load is None or not any(0.0 < v < INF for v in load):
                    continue
                heads, tail = graph.head_tail(atom, r)
                rows.append((r, load, heads, tail))
            table = (g[0], rows)
        self._load_tables[atom] = table
        return table

    def required_atoms(self, q: MonitorState) -> frozenset[Atom]:
        """Predicate atoms that every accepting continuation from ``q`` must make true."""
        hit = self._required_cache.get(q)
        if hit is not None:
            return hit
        out: set[Atom] = set()
        stack = [self.root]
        while stack:
            name = stack.pop()
            i, dfa, props = self._by_name[name]
            state = q[i]
            if state == DONE:
                continue
            mono = self._mono.get(name)
            if mono is not None:
                stack.extend(_mono_required(mono, self.done(q)))
                continue
            for b in self._required_props(name, dfa, state):
                kind, ref = props[b]
                if kind == "child":
                    assert isinstance(ref, str)
                    stack.append(ref)
                else:
                    assert isinstance(ref, Atom)
                    out.add(ref)
        res = frozenset(out)
        self._required_cache[q] = res
        return res

    def _required_props(self, name: str, dfa: DFA, start: int) -> tuple[int, ...]:
        """Bits of the propositions without which the DFA cannot reach acceptance from ``start``
        (in one step or more)."""
        key = (name, start)
        hit = self._required_prop_cache.get(key)
        if hit is not None:
            return hit
        k = len(dfa.props)
        width = 1 << k
        req: list[int] = []
        for b in range(k):
            bit = 1 << b
            seen = {start}
            frontier = [start]
            ok = False
            while frontier and not ok:
                nxt = []
                for s in frontier:
                    base = s * width
                    for m in range(width):
                        if m & bit:
                            continue
                        y = dfa.table[base + m]
                        if y in dfa.accepting:
                            ok = True
                            break
                        if y not in seen:
                            seen.add(y)
                            nxt.append(y)
                    if ok:
                        break
                frontier = nxt
            if not ok:
                req.append(b)
        res = tuple(req)
        self._required_prop_cache[key] = res
        return res

    def _bottleneck(self, name: str, dfa: DFA, start: int, costs: tuple[float, ...]) -> float:
        key = (name, start, costs)
        hit = self._cache.get(key)
        if hit is not None:
            return hit
        k = len(costs)
        width = 1 << k
        mask_cost = [0.0] * width
        for m in range(1, width):
            low = (m & -m).bit_length() - 1
            mask_cost[m] = max(mask_cost[m & (m - 1)], costs[low])
        table = dfa.table
        accepting = dfa.accepting
        best = INF
        dist: dict[int, float] = {start: 0.0}
        heap = [(0.0, start)]
        while heap:
            v, s = heapq.heappop(heap)
            if v > dist.get(s, INF) or v >= best:
                continue
            base = s * width
            for m in range(width):
                c = mask_cost[m]
                if c < v:
                    c = v
                if c >= best:
                    continue
                y = table[base + m]
                if y in accepting:
                    best = c
                if c < dist.get(y, INF):
                    dist[y] = c
                    heapq.heappush(heap, (c, y))
        self._cache[key] = best
        return best


def _one_machine_bound(jobs: list[tuple[float, float, float]]) -> float:
    """A lower bound on the makespan of one robot's jobs (head, work, tail): the robot acts on
    one object per step, so for any subset of its jobs it needs the subset's work between the
    subset's least head and its least tail. Subsets tried: all jobs, the jobs with head at least
    each job's head, and the jobs with tail at least each job's tail (preemptive one-machine
    scheduling with release and delivery times)."""
    if len(jobs) == 1:
        hd, v, tl = jobs[0]
        return hd + v + tl
    best = 0.0
    # by head, latest first: the least head so far is the job's own
    jobs.sort(reverse=True)
    total = 0.0
    least_tail = INF
    for hd, v, tl in jobs:
        total += v
        if tl < least_tail:
            least_tail = tl
        t = hd + total + least_tail
        if t > best:
            best = t
    # by tail, largest first: the least tail so far is the job's own
    jobs.sort(key=_TAIL, reverse=True)
    total = 0.0
    least_head = INF
    for hd, v, tl in jobs:
        total += v
        if hd < least_head:
            least_head = hd
        t = least_head + total + tl
        if t > best:
            best = t
    return best


_TAIL = operator.itemgetter(2)
_getitem = operator.getitem


def _one_place(objs: list[int]) -> Callable[[tuple[int, ...]], tuple[int, ...]]:
    """``locs`` -> the places of ``objs`` as a tuple (``itemgetter`` returns a bare value for
    one index, and nothing for none)."""
    if not objs:
        return lambda _: ()
    o = objs[0]
    return lambda locs: (locs[o],)


# A monotone composite: ("F", child) | ("and", a, b) | ("or", a, b)
_Mono = tuple[object, ...]


def _monotone(f: Formula, names: set[str]) -> _Mono | None:
    if isinstance(f, Eventually) and isinstance(f.operand, Atom) and f.operand.name in names:
        if not f.operand.args:
            return ("F", f.operand.name)
        return None
    if isinstance(f, (And, Or)):
        a, b = _monotone(f.left, names), _monotone(f.right, names)
        if a is None or b is None:
            return None
        return ("and" if isinstance(f, And) else "or", a, b)
    return None


# The same tree with nested "and"s (and "or"s) merged: (is it an "and", children), a child being
# a formula name ("F child") or a subtree; evaluated for every search node, so kept shallow.
_Flat = tuple[bool, tuple[object, ...]]


def _flatten(t: _Mono) -> _Flat:
    op = t[0]
    items: list[object] = []

    def collect(u: _Mono) -> None:
        if u[0] == op:
            a, b = u[1], u[2]
            assert isinstance(a, tuple) and isinstance(b, tuple)
            collect(a)
            collect(b)
        elif u[0] == "F":
            items.append(u[1])
        else:
            items.append(_flatten(u))

    if op == "F":
        return (True, (t[1],))
    collect(t)
    return (op == "and", tuple(items))


def _flat_bound(t: _Flat, h: dict[str, float], done: frozenset[str]) -> float:
    """Least time the combination can hold: max over an "and", min over an "or" of the
    children's bounds (a child already done costs nothing)."""
    is_and, items = t
    best = 0.0 if is_and else INF
    for x in items:
        if type(x) is not str:
            v = _flat_bound(x, h, done)  # type: ignore[arg-type]
        elif x in done:
            v = 0.0
        else:
            v = h[x]
        if is_and:
            if v > best:
                best = v
        elif v < best:
            best = v
    return best


def _mono_required(t: _Mono, done: frozenset[str]) -> frozenset[str]:
    """Children every way of satisfying ``t`` still needs (none once ``t`` is satisfied)."""
    if t[0] == "F":
        child = t[1]
        assert isinstance(child, str)
        return frozenset() if child in done else frozenset({child})
    a, b = t[1], t[2]
    assert isinstance(a, tuple) and isinstance(b, tuple)
    ra, rb = _mono_required(a, done), _mono_required(b, done)
    if t[0] == "and":
        return ra | rb
    if _mono_satisfied(a, done) or _mono_satisfied(b, done):
        return frozenset()
    return ra & rb


def _mono_satisfied(t: _Mono, done: frozenset[str]) -> bool:
    if t[0] == "F":
        return t[1] in done
    a, b = t[1], t[2]
    assert isinstance(a, tuple) and isinstance(b, tuple)
    if t[0] == "and":
        return _mono_satisfied(a, done) and _mono_satisfied(b, done)
    return _mono_satisfied(a, done) or _mono_satisfied(b, done)
