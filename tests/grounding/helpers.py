"""Helpers shared by the grounding phrasing tests: ground, compare by language, typo edits."""

from __future__ import annotations

from collections.abc import Callable
from pathlib import Path

import pytest

from hltl.bench.grounding import parse_expectation, show_tree
from hltl.errors import GroundingError
from hltl.grounding import normalise
from hltl.grounding.lexicon import PRONOUN_SEX, name_sexes
from hltl.grounding.offline import parse_instruction, spec_of
from hltl.grounding.tree import Node
from hltl.spec.equivalence import counterexample
from hltl.world.scene import Scene, load_scene

ROOT = Path(__file__).resolve().parents[2]
CELL = load_scene(ROOT / "examples/scenes/grounding_cell.yaml")


def paraphrase_scene(name: str) -> Scene:
    """A scene of the paraphrase corpus (tests/grounding/paraphrase/scenes/<name>.yaml)."""
    return load_scene(ROOT / f"tests/grounding/paraphrase/scenes/{name}.yaml")


LAB, OFFICE, WARD, DEPOT = (paraphrase_scene(n) for n in ("lab", "office", "ward", "depot"))
KITCHEN, CLASSROOM, NURSERY, WORKSHOP = (
    paraphrase_scene(n) for n in ("kitchen", "classroom", "nursery", "workshop")
)
# the scenes the phrasing families range over
SCENES = [CELL, LAB, OFFICE, WARD, DEPOT, KITCHEN, CLASSROOM, NURSERY, WORKSHOP]


def name_of(scene: Scene, oid: str) -> str:
    """A name of object or person ``oid`` that names it alone in ``scene``."""
    for o in scene.objects:
        if o.id == oid:
            return next(
                (a for a in o.aliases if len(a.split()) == 2), o.aliases[0] if o.aliases else o.id
            )
    h = next(h for h in scene.humans if h.id == oid)
    shared = {a for x in scene.humans if x.id != oid for a in x.aliases}
    return next(a for a in (*h.aliases, h.name) if a not in shared)


def unique_objects(scene: Scene) -> list[str]:
    """The objects of ``scene`` whose category no other object shares."""
    cats = [o.category for o in scene.objects]
    return [o.id for o in scene.objects if cats.count(o.category) == 1]


def plain_request(scene: Scene, k: int) -> tuple[str, str]:
    """A plain request of ``scene`` ('give <person> the <object>') and its reading, the object
    one no other object shares a category with, the person one no other person shares a name
    with."""
    cats = [o.category for o in scene.objects]
    objs = [o for o in scene.objects if cats.count(o.category) == 1]
    o = objs[k % len(objs)]
    h = scene.humans[k % len(scene.humans)]
    shared = {a for x in scene.humans if x.id != h.id for a in x.aliases}
    name = next(a for a in (*h.aliases, h.name) if a not in shared)
    return f"give {name} the {o.aliases[0] if o.aliases else o.id}", f"{o.id}>{h.id}"


def fits(name: str, pronoun: str) -> bool:
    """Whether ``pronoun`` may be the person called ``name`` (session 34: a first name of one sex,
    src/hltl/grounding/data/first_names_sex.txt, rules a pronoun of the other sex out)."""
    sex = name_sexes().get(name.lower())
    return sex is None or PRONOUN_SEX[pronoun.lower()] == sex


def pronoun_for(name: str, female: str) -> str:
    """``female`` ('she', 'her', 'hers') said of ``name``: 'he', 'him', 'his' for a man's name."""
    if name_sexes().get(name.lower()) != "m":
        return female
    return {"she": "he", "her": "him", "hers": "his"}[female]


def assert_means(text: str, want: str, scene: Scene = CELL) -> None:
    """Assert that ``text`` grounds to a spec language-equivalent to ``want`` (corpus notation)."""
    got = parse_instruction(text, scene)
    assert counterexample(spec_of(got), spec_of(parse_expectation(want))) is None, (
        f"{text!r} -> {show_tree(got)}, want {want}"
    )


def assert_reads(text: str, want: str, scene: Scene = CELL) -> None:
    """As assert_means, with the same tree taken as equal without the language check."""
    got = parse_instruction(text, scene)
    if show_tree(got) != show_tree(parse_expectation(want)):
        assert_means(text, want, scene)


def assert_refused(text: str, scene: Scene = CELL, match: str | None = None) -> None:
    """``text`` is refused (with a message matching ``match``)."""
    with pytest.raises(GroundingError, match=match):
        parse_instruction(text, scene)


def assert_case(text: str, want: str | None, scene: Scene = CELL) -> None:
    """``text`` reads as ``want`` (corpus notation), or is refused when ``want`` is None."""
    if want is None:
        assert_refused(text, scene)
    else:
        assert_reads(text, want, scene)


Case = tuple[str, str | None, Scene]


class PhrasingCases:
    """The cases of a session's phrasing test file (the scaffolding each file had of its own):
    ``test(*cases)`` is a test of (text, reading or None for a sentence that must stay refused,
    scene) cases, bound to a ``test_…`` name in the file; ``read`` keeps every case that reads,
    for ``refused_without``."""

    def __init__(self) -> None:
        self.read: list[tuple[str, str, Scene]] = []

    def test(self, *cases: Case) -> Callable[[str, str | None, Scene], None]:
        """A test of ``cases``, each read as its reading or refused."""
        self.read.extend((t, w, s) for t, w, s in cases if w is not None)

        @pytest.mark.parametrize(("text", "want", "scene"), list(cases))
        def check(text: str, want: str | None, scene: Scene) -> None:
            assert_case(text, want, scene)

        return check

    def refused_without(self, steps: tuple[object, ...], monkeypatch: pytest.MonkeyPatch) -> None:
        """Every case that reads is refused with ``steps`` taken out of the rewrites
        (normalise._STEPS19): each rule is what reads it (the "cannot fail" rule)."""
        mine = set(steps)
        kept = tuple(s for s in normalise._STEPS19 if s not in mine)
        self.refused_with(normalise, "_STEPS19", kept, monkeypatch)

    def refused_with(
        self, module: object, name: str, off: object, monkeypatch: pytest.MonkeyPatch
    ) -> None:
        """Every case that reads is refused with ``module.name`` replaced by ``off`` (a rule
        outside the rewrites, e.g. one the grammar calls, turned off): that rule is what reads
        it."""
        monkeypatch.setattr(module, name, off)
        assert self.read
        for text, _want, scene in self.read:
            assert_refused(text, scene)


def assert_same_or_refused(text: str, want: str, scene: Scene = CELL) -> None:
    """``text`` is read as ``want`` or refused: never as something else."""
    got = tree(text, scene)
    if got is not None and show_tree(got) != show_tree(parse_expectation(want)):
        assert counterexample(spec_of(got), spec_of(parse_expectation(want))) is None, (
            f"{text!r} -> {show_tree(got)}, want {want} or a refusal"
        )


def tree(text: str, scene: Scene = CELL) -> Node | None:
    """The task tree of ``text``, or None when it is refused."""
    try:
        return parse_instruction(text, scene)
    except GroundingError:
        return None


def one_edits(word: str) -> list[str]:
    """Every word one insertion, deletion, substitution or swap of neighbours from ``word``."""
    letters = "abcdefghijklmnopqrstuvwxyz"
    out = {word[:k] + word[k + 1 :] for k in range(len(word))}
    out |= {word[:k] + c + word[k:] for k in range(len(word) + 1) for c in letters}
    out |= {word[:k] + c + word[k + 1 :] for k in range(len(word)) for c in letters}
    out |= {word[:k] + word[k + 1] + word[k] + word[k + 2 :] for k in range(len(word) - 1)}
    out.discard(word)
    return sorted(out)


Unclear = tuple[str, Scene, tuple[str, ...]]


def assert_names_readings(text: str, scene: Scene, readings: tuple[str, ...]) -> None:
    """``text`` is refused, and its refusal names every one of ``readings``."""
    with pytest.raises(GroundingError) as refused:
        parse_instruction(text, scene)
    assert all(r in str(refused.value) for r in readings), str(refused.value)


def assert_refusals_are(
    mine: tuple[object, ...], cases: list[Unclear], monkeypatch: pytest.MonkeyPatch
) -> None:
    """Without the refusals ``mine`` (offline._REFUSALS), no case's refusal names all its
    readings: those refusals are what name them."""
    from hltl.grounding import offline

    off = set(mine)
    monkeypatch.setattr(offline, "_REFUSALS", tuple(r for r in offline._REFUSALS if r not in off))
    for text, scene, readings in cases:
        try:
            parse_instruction(text, scene)
        except GroundingError as refused:
            assert not all(r in str(refused) for r in readings), text


def unclear_tests(
    cases: list[Unclear], mine: tuple[object, ...]
) -> tuple[Callable[[str, Scene, tuple[str, ...]], None], Callable[[pytest.MonkeyPatch], None]]:
    """The two tests of a session's refusals that name their readings (bound to ``test_…``
    names in its file): each case's refusal names every reading, and without the refusals
    ``mine`` none does."""

    @pytest.mark.parametrize(("text", "scene", "readings"), cases)
    def names(text: str, scene: Scene, readings: tuple[str, ...]) -> None:
        assert_names_readings(text, scene, readings)

    def these(monkeypatch: pytest.MonkeyPatch) -> None:
        assert_refusals_are(mine, cases, monkeypatch)

    return names, these
