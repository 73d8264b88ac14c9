"""Derive the role-aware binding η_t of every step of a plan (docs/model.md, "Bindings")."""

from __future__ import annotations

from collections.abc import Sequence

from hltl.planner.problem import Problem
from hltl.planner.result import Binding, PlanStep


def derive_bindings(
    problem: Problem, steps: Sequence[PlanStep], done_before: Sequence[frozenset[str]]
) -> tuple[PlanStep, ...]:
    """Annotate each step with η_t: every acting robot is bound to the leaf its object serves.

    Binding is free between steps, so η never changes a plan's cost; it is reconstructed here
    rather than searched. The leaf of an action is the first leaf, in the spec's order, that is
    not yet done and mentions the object (the root when none does: the robot is clearing its
    hand). Roles follow the object's hand-to-hand chain from pick to delivery or placement:
    ``solo`` when one robot handles it alone, else ``giver``, ``relay`` … ``receiver``.
    """
    leaves = list(problem.spec.leaves)
    leaf_objects = {
        name: {problem.objects[i] for i in problem.formula_objects.get(name, frozenset())}
        for name in leaves
    }
    open_chain: dict[str, list[str]] = {}
    # per action (step, position in step): its chain and each executor's index in it
    slots: dict[tuple[int, int], tuple[list[str], tuple[int, ...]]] = {}
    for t, step in enumerate(steps):
        for k, a in enumerate(step.actions):
            chain = open_chain.get(a.object)
            if a.skill == "pick" or chain is None:
                chain = [a.robots[0]]
                open_chain[a.object] = chain
            if a.skill == "handover_r2r":
                chain.append(a.robots[1])
                slots[(t, k)] = (chain, (len(chain) - 2, len(chain) - 1))
            else:
                slots[(t, k)] = (chain, (len(chain) - 1,))
            if a.skill in ("place", "handover_r2h"):
                del open_chain[a.object]

    out: list[PlanStep] = []
    for t, step in enumerate(steps):
        done = done_before[t]
        bindings: list[Binding] = []
        for k, a in enumerate(step.actions):
            leaf = next(
                (n for n in leaves if n not in done and a.object in leaf_objects[n]),
                problem.spec.root,
            )
            chain, idxs = slots[(t, k)]
            for robot, i in zip(a.robots, idxs, strict=True):
                bindings.append(Binding(robot, leaf, _role(i, len(chain))))
        out.append(PlanStep(step.start, step.duration, step.actions, tuple(bindings)))
    return tuple(out)


def _role(index: int, length: int) -> str:
    if length == 1:
        return "solo"
    if index == 0:
        return "giver"
    if index == length - 1:
        return "receiver"
    return "relay"
