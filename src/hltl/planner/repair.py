"""Plans in fewer steps: routes squeezed into one step fewer, then their clashes repaired."""

from __future__ import annotations

import random
from collections.abc import Sequence

from hltl.planner.problem import Instance, Problem

# (step, instance) per instance of a route, in step order
Path = list[tuple[int, Instance]]
# a goal's route here: its path, its (step, robots used) cells, the step its atom happens in
Routed = tuple[Path, list[tuple[int, int]], int]
# an instance from a place: its post, how many robots it uses (with the holder), the fewest
# instances from its post to the goal's atom (0 when it fires), whether it fires, the instance,
# and the robots it uses as two indices (the second one past the last robot when it uses one;
# the first -1 and the second their mask when it uses more than two)
Arc = tuple[int, int, int, bool, Instance, int, int]

# the cost of one clash against one robot-step (clashes first, robot-steps to break ties)
CLASH = 1 << 16
# goals taken out per repair move: the clashing one and up to this many more
REPAIR_MORE = (1, 1, 2, 2, 3)
# the fewest instances to a goal's atom from a place where it cannot happen
UNREACHED = 1 << 30
# repair moves without fewer clashes before the clashing cells weigh more
STUCK = 20
# repair moves at one level after which it starts again from the plan it squeezed (0: never),
# twice as many after each such restart at the same level
RESTART = 6000


class Repair:
    """Conflict repair of one cell's goals inside a horizon of steps.

    ``objs[gi]`` is goal ``gi``'s object, ``fires[gi]`` the instances that make its atom
    happen, ``alive[gi][place]`` whether it still can from there; ``start[o]`` is where object
    ``o`` is, ``gone`` the robots nothing may use (they hold an object for good)."""

    def __init__(
        self,
        problem: Problem,
        start: Sequence[int],
        objs: Sequence[int],
        fires: Sequence[frozenset[int]],
        alive: Sequence[Sequence[bool]],
        gone: int,
        seed: int = 5,
    ) -> None:
        self.p = problem
        self.start = list(start)
        self.objs = list(objs)
        self.fires = fires
        self.gone = gone
        self.rng = random.Random(seed)
        self.n = len(fires)
        # per goal and place: the fewest instances from there to one that fires (its atom)
        self.left = [self._fewest(gi, alive[gi]) for gi in range(self.n)]
        self.arcs = [self._arcs(gi) for gi in range(self.n)]
        self.routes: dict[int, Routed] = {}
        self.T = 0
        self.count: list[list[int]] = []
        self.occ: list[int] = []
        self.weight: list[list[int]] = []  # per step and robot, what a clash there costs
        # per step and robot, what one more use costs in clashes (CLASH x its weight when
        # the robot is used, else 0), and a 0 past the last robot (``Arc``)
        self.rcost: list[list[int]] = []
        self.multi: list[int] = []  # per step, the robots used more than once
        self.clashes = 0  # cells used twice, counted once per extra use
        self.weighted = 0  # the same, each counted at its weight
        self.stuck = 0  # moves since the clashes last fell
        self.least = 0  # the fewest clashes since the weights were last raised
        self.moves = 0  # repair moves since the last squeeze
        self.base: tuple[dict[int, Path], int] = ({}, 0)  # what the last squeeze started from
        self.restarts = 0  # restarts from it

    def _fewest(self, gi: int, alive: Sequence[bool]) -> list[int]:
        """Fewest instances from each place to the goal's atom (ignoring other routes)."""
        p = self.p
        dist = [UNREACHED] * len(p.locs)
        fires = self.fires[gi]
        by_pre = p.by_obj_pre[self.objs[gi]]
        # Bellman-Ford over places (few places, few instances each)
        for loc in range(len(p.locs)):
            if any(i.index in fires and not i.executors & self.gone for i in by_pre[loc]):
                dist[loc] = 1
        changed = True
        while changed:
            changed = False
            for loc in range(len(p.locs)):
                if not alive[loc]:
                    continue
                for i in by_pre[loc]:
                    if i.executors & self.gone or i.index in fires:
                        continue
                    d = dist[i.post] + 1
                    if d < dist[loc]:
                        dist[loc] = d
                        changed = True
        return dist

    def _arcs(self, gi: int) -> list[tuple[int, int, list[list[Arc]]]]:
        """Per place: its holder's bit (-1: a place nothing may use), the holder's index (past
        the last robot when none), and the goal's instances from there (``Arc``), those of
        robots out of play left out, by the steps left after them: entry ``k`` has those
        with at most ``k`` instances after them, the last entry all of them."""
        p = self.p
        none = len(p.robots)
        left = self.left[gi]
        fires = self.fires[gi]
        out: list[tuple[int, int, list[list[Arc]]]] = []
        for loc in range(len(p.locs)):
            h = p.code_holder.get(loc)
            hb = 0 if h is None else 1 << h
            if hb & self.gone:
                out.append((-1, none, [[]]))
                continue
            arcs: list[Arc] = []
            for inst in p.by_obj_pre[self.objs[gi]][loc]:
                used = inst.executors | hb
                if used & self.gone:
                    continue
                fire = inst.index in fires
                rs = _bits(used)
                r1, r2 = (-1, used) if len(rs) > 2 else [*rs, none, none][:2]
                after = 0 if fire else left[inst.post]
                if after >= UNREACHED:  # (its atom cannot happen from there)
                    continue
                arcs.append((inst.post, len(rs), after, fire, inst, r1, r2))
            most = max((a[2] for a in arcs), default=0)
            by_left = [[a for a in arcs if a[2] <= k] for k in range(most + 1)]
            out.append((hb, none if h is None else h, by_left))
        return out

    # --- the usage table -------------------------------------------------------------------

    def _reset(self, T: int) -> None:
        self.T = T
        self.count = [[0] * len(self.p.robots) for _ in range(T)]
        self.occ = [0] * T
        self.weight = [[1] * len(self.p.robots) for _ in range(T)]
        self.rcost = [[0] * (len(self.p.robots) + 1) for _ in range(T)]
        self.multi = [0] * T
        self.clashes = 0
        self.weighted = 0
        for rt in self.routes.values():
            self._add(rt)

    def _add(self, rt: Routed) -> None:
        for t, used in rt[1]:
            row = self.count[t]
            self.occ[t] |= used
            while used:
                low = used & -used
                r = low.bit_length() - 1
                if row[r]:
                    self.clashes += 1
                    self.weighted += self.weight[t][r]
                    self.multi[t] |= low
                else:
                    self.rcost[t][r] = CLASH * self.weight[t][r]
                row[r] += 1
                used ^= low

    def _remove(self, rt: Routed) -> None:
        for t, used in rt[1]:
            row = self.count[t]
            while used:
                low = used & -used
                r = low.bit_length() - 1
                row[r] -= 1
                if row[r]:
                    self.clashes -= 1
                    self.weighted -= self.weight[t][r]
                    if row[r] == 1:
                        self.multi[t] &= ~low
                else:
                    self.occ[t] &= ~low
                    self.rcost[t][r] = 0
                used ^= low

    # --- routing against the table ---------------------------------------------------------

    def route(self, gi: int) -> Routed | None:
        """The goal's route inside the horizon with the fewest clashes with the routes in the
        table (then the fewest robot-steps, then the earliest atom); None: none at all."""
        T = self.T
        left = self.left[gi]
        arcs = self.arcs[gi]
        rcost = self.rcost
        start = self.start[self._obj(gi)]
        if left[start] > T:
            return None
        big = 1 << 62
        n_locs = len(arcs)
        # per step, per place: where from, and by which instance (None: waited)
        back: list[list[tuple[int, Instance | None] | None]] = [[]] * (T + 1)
        # the places reached, in the order first reached (ties go to the first), and their costs
        # (lists indexed by place: cheaper than dictionaries in this, the repair's inner loop)
        order = [start]
        costs = [big] * n_locs
        costs[start] = 0
        done: tuple[int, int, int, Instance] | None = None  # cost, step, place, instance
        bound = big  # done's cost
        for t in range(T):
            rc = rcost[t]
            slack = T - t - 1  # steps left after this one
            nxt = [big] * n_locs
            reached: list[int] = []
            back_next: list[tuple[int, Instance | None] | None] = [None] * n_locs
            back[t + 1] = back_next
            for loc in order:
                cost = costs[loc]
                if cost >= bound:
                    continue
                hb, hr, by_left = arcs[loc]
                if hb < 0:
                    continue
                out = by_left[slack] if slack < len(by_left) else by_left[-1]
                for post, n, after, fire, inst, r1, r2 in out:
                    if r1 >= 0:
                        c = cost + n + rc[r1] + rc[r2]
                    else:  # (more than two robots)
                        c = cost + n + sum(rc[r] for r in _bits(r2))
                    if c + after >= bound:  # (each instance left uses a robot)
                        continue
                    if fire:
                        if c < bound:
                            done = (c, t, loc, inst)
                            bound = c
                        continue
                    was = nxt[post]
                    if c < was:
                        if was == big:
                            reached.append(post)
                        nxt[post] = c
                        back_next[post] = (loc, inst)
                if left[loc] <= slack:
                    c = cost + 1 + rc[hr] if hb else cost
                    was = nxt[loc]
                    if c < was:
                        if was == big:
                            reached.append(loc)
                        nxt[loc] = c
                        back_next[loc] = (loc, None)
            order = reached
            costs = nxt
        if done is None:
            return None
        _, t_end, loc, last = done
        path: Path = [(t_end, last)]
        cells: list[tuple[int, int]] = [(t_end, last.executors | arcs[loc][0])]
        cur, ct = loc, t_end
        while ct > 0:
            came = back[ct][cur]
            assert came is not None  # (every place reached has where it came from)
            prev, act = came
            ct -= 1
            hb = arcs[prev][0]
            if act is not None:
                path.append((ct, act))
                cells.append((ct, act.executors | hb))
            elif hb:
                cells.append((ct, hb))
            cur = prev
        path.reverse()
        cells.reverse()
        return path, cells, t_end

    def _obj(self, gi: int) -> int:
        return self.objs[gi]

    # --- the search ------------------------------------------------------------------------

    def squeeze(self, routes: dict[int, Path], T: int) -> bool:
        """Start a search for a plan of ``T`` steps from ``routes`` (per goal its path, steps
        counted from 0): the goals whose atom happens at step ``T`` or later are routed again
        inside the horizon, clashes allowed. False: some goal has no route at all."""
        if routes is not self.base[0] or self.base[1] != T:  # (not a restart)
            self.base = (routes, T)
            self.restarts = 0
        self.moves = 0
        self.routes = {}
        for gi, path in routes.items():
            if path[-1][0] < T:
                self.routes[gi] = (path, self._cells(gi, path), path[-1][0])
        self._reset(T)
        self.least = 1 << 30
        self.stuck = 0
        late = [gi for gi in range(self.n) if gi not in self.routes]
        self.rng.shuffle(late)
        for gi in late:
            rt = self.route(gi)
            if rt is None:
                return False
            self.routes[gi] = rt
            self._add(rt)
        return True

    def _cells(self, gi: int, path: Path) -> list[tuple[int, int]]:
        """The (step, robots) cells a path uses: its instances' executors, and the holder in
        every step its object starts in a hand."""
        holder = self.p.code_holder
        loc = self.start[self._obj(gi)]
        cells: list[tuple[int, int]] = []
        acts = dict(path)
        for t in range(path[-1][0] + 1):
            h = holder.get(loc)
            used = 0 if h is None else 1 << h
            inst = acts.get(t)
            if inst is not None:
                used |= inst.executors
                loc = inst.post
            if used:
                cells.append((t, used))
        return cells

    def step(self) -> None:
        """One repair move: a goal in a clash and a few that share its robots routed again,
        kept when the clashes do not grow."""
        rng = self.rng
        clashing = self._clashing()
        if not clashing:
            return
        self.moves += 1
        if RESTART and self.moves > RESTART << self.restarts:
            self.restarts += 1
            self.squeeze(*self.base)
            return
        g0 = rng.choice(clashing)
        robots = 0
        for _, used in self.routes[g0][1]:
            robots |= used
        near = [
            gi
            for gi, rt in self.routes.items()
            if gi != g0 and any(used & robots for _, used in rt[1])
        ]
        k = min(len(near), rng.choice(REPAIR_MORE))
        out = [g0, *rng.sample(near, k)]
        rng.shuffle(out)
        before = self.weighted
        old = {gi: self.routes[gi] for gi in out}
        for gi in out:
            self._remove(old[gi])
            del self.routes[gi]
        new: dict[int, Routed] = {}
        for gi in out:
            rt = self.route(gi)
            if rt is None:
                break
            new[gi] = rt
            self.routes[gi] = rt
            self._add(rt)
            if self.weighted > before:  # (more routes only add clashes: given up)
                break
        if len(new) == len(out) and self.weighted <= before:
            self._progress()
            return
        for gi, rt in new.items():
            self._remove(rt)
            del self.routes[gi]
        for gi in out:
            self.routes[gi] = old[gi]
            self._add(old[gi])
        self._progress()

    def _progress(self) -> None:
        """Breakout (Morris 1993): after ``STUCK`` moves without fewer clashes, each cell
        used twice costs one more from then on, so the moves leave the clashes that stay."""
        if self.clashes < self.least:
            self.least = self.clashes
            self.stuck = 0
            return
        self.stuck += 1
        if self.stuck < STUCK:
            return
        self.stuck = 0
        self.least = self.clashes
        for t, row in enumerate(self.count):
            for r, n in enumerate(row):
                if n > 1:
                    self.weight[t][r] += 1
                    self.rcost[t][r] += CLASH
                    self.weighted += n - 1

    def _clashing(self) -> list[int]:
        multi = self.multi
        return [gi for gi, rt in self.routes.items() if any(used & multi[t] for t, used in rt[1])]

    def steps(self) -> list[list[Instance]]:
        """The routes as a plan's steps (empty steps dropped)."""
        by_step: dict[int, list[Instance]] = {}
        for path, _, _ in self.routes.values():
            for t, inst in path:
                by_step.setdefault(t, []).append(inst)
        return [by_step[t] for t in sorted(by_step)]

    def paths(self) -> dict[int, Path]:
        """Per goal its path, with the empty steps of the plan taken out."""
        return ranked({gi: rt[0] for gi, rt in self.routes.items()})


def applicable(problem: Problem, atoms: Sequence[str], after: Sequence[Sequence[int]]) -> bool:
    """Whether routes alone make the cell's plans: every goal an event that leaves its object
    in no hand (``delivered``, ``placed``), no order between goals, fixed durations."""
    return (
        problem.cost.fixed
        and not problem.state_atom_objects
        and all(a in ("delivered", "placed") for a in atoms)
        and not any(after)
    )


def ranked(routes: dict[int, Path]) -> dict[int, Path]:
    """The paths with the steps no path acts in taken out (steps counted from 0)."""
    used = sorted({t for path in routes.values() for t, _ in path})
    rank = {t: k for k, t in enumerate(used)}
    return {gi: [(rank[t], i) for t, i in path] for gi, path in routes.items()}


def length(routes: dict[int, Path]) -> int:
    """How many steps the paths act in."""
    return len({t for path in routes.values() for t, _ in path})


def _bits(mask: int) -> list[int]:
    out = []
    while mask:
        low = mask & -mask
        out.append(low.bit_length() - 1)
        mask ^= low
    return out
