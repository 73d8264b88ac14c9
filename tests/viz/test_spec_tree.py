"""Spec trees and DFA diagrams: nodes, edges, sizes, guards."""

from __future__ import annotations

import random
from pathlib import Path
from typing import Any

import pytest

from hltl.spec.hierarchy import HSpec, load_spec
from hltl.spec.printer import to_string
from hltl.viz._mpl import save_figure
from hltl.viz.spec_tree import dfa_diagram, guard_text, node_dfas, spec_tree
from tests.viz.conftest import PNG, ROOT, magic

THREE_LEVEL = ROOT / "examples" / "specs" / "three_level.yaml"


def gids(fig: Any, prefix: str) -> set[str]:
    return {p.get_gid() for p in fig.axes[0].patches if (p.get_gid() or "").startswith(prefix)}


def test_tree_has_every_node_edge_formula_and_automaton_size(tmp_path: Path) -> None:
    spec = load_spec(THREE_LEVEL)
    fig = spec_tree(spec)
    assert gids(fig, "node:") == {f"node:{n}" for n in spec.names}
    assert gids(fig, "edge:") == {f"edge:{p}:{c}" for p in spec.names for c in spec.children[p]}
    text = "\n".join(t.get_text() for t in fig.axes[0].texts)
    dfas = node_dfas(spec)
    for name in spec.names:
        assert to_string(spec.formula(name)).split(" ")[0] in text
        d = dfas[name]
        assert f"DFA: {d.n_states} states, {d.n_edges} edges" in text
    # children sit below their parent
    y = {n: _box_y(fig, n) for n in spec.names}
    assert all(y[c] < y[p] for p in spec.names for c in spec.children[p])
    assert magic(save_figure(fig, tmp_path / "t.png")) == PNG


def _box_y(fig: Any, name: str) -> float:
    box = next(p for p in fig.axes[0].patches if p.get_gid() == f"node:{name}")
    return float(box.get_y())


def test_tree_without_automata(paper_spec: HSpec) -> None:
    fig = spec_tree(paper_spec, automata=False)
    assert "DFA:" not in " ".join(t.get_text() for t in fig.axes[0].texts)


def test_dfa_diagram_states_and_edges(paper_spec: HSpec) -> None:
    dfa = node_dfas(paper_spec)["p0"]
    fig = dfa_diagram(dfa, title="p0")
    assert len(gids(fig, "state:")) == dfa.n_states
    assert len(gids(fig, "edge:")) == dfa.n_edges
    labels = {t.get_text() for t in fig.axes[0].texts}
    assert "true" in labels  # the accepting sink loops on every symbol
    assert "p100 & p200" in labels  # both children fire in one step: straight to acceptance


def test_long_guards_go_to_a_table() -> None:
    spec = load_spec(ROOT / "examples" / "specs" / "office_3.yaml")
    dfa = node_dfas(spec)["p200"]
    fig = dfa_diagram(dfa)
    table = "\n".join(t.get_text() for t in fig.texts)
    assert table.count("→") == dfa.n_edges and "placed(memo, desk3)" in table


def _holds(guard: str, names: list[str], mask: int) -> bool:
    if guard == "true":
        return True
    for term in guard.replace("\n", " ").split(" | "):
        term = term.strip().removeprefix("| ")
        ok = True
        for lit in term.split(" & "):
            neg = lit.startswith("!")
            value = bool(mask >> names.index(lit.lstrip("!")) & 1)
            ok &= value != neg
        if ok:
            return True
    return False


@pytest.mark.parametrize("k", [1, 2, 3, 4])
def test_guard_text_denotes_exactly_its_symbols(k: int) -> None:
    rng = random.Random(k)
    names = [f"p{i}" for i in range(k)]
    for _ in range(60):
        masks = {m for m in range(1 << k) if rng.random() < 0.5} or {0}
        guard = guard_text(names, masks)
        assert {m for m in range(1 << k) if _holds(guard, names, m)} == masks, guard
    assert guard_text(names, range(1 << k)) == "true"
