"""Session-15 phrasings of issue 12 (two wrong readings on main, blind13's causes and the classes
around them), each as a family checked against an oracle built from the words the family is made
of, and near forms that must stay refused."""

from __future__ import annotations

import math

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import show_tree
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    OFFICE,
    SCENES,
    assert_refused,
    name_of,
    plain_request,
    tree,
)
from tests.grounding.helpers import assert_reads as assert_means

# -- a statement said as a question (a wrong reading on main) ------------------------------------
#
# The oracle: "<person> wants the <object>?" asks whether it is so; the same words with a full
# stop request it, and with 'can'/'could'/'may'/'might' (asking leave) they request it too.

ASKING = [
    "{p} wants the {o}?",
    "{p} needs the {o}?",
    "{p} gets the {o}?",
    "{p} would like the {o}?",
    "{p} should get the {o}?",
    "{p} is getting the {o}?",
    "The {o} is for {p}?",
    "The {o}'s for {p}?",
    "The {o} goes to {p}?",
    "So {p} wants the {o}?",
    "Sorry, {p} needs the {o}?",
    "Hang on, the {o} is for {p}?",
]
LEAVE = ["{p} can have the {o}?", "{p} could have the {o}?", "{p} may have the {o}?"]


def _person_object(scene: Scene, k: int) -> tuple[str, str, str]:
    _, want = plain_request(scene, k)
    oid, pid = want.split(">")
    return name_of(scene, pid), name_of(scene, oid), want


@settings(max_examples=80, deadline=None)
@given(st.sampled_from(SCENES), st.integers(0, 6), st.sampled_from(ASKING))
def test_a_statement_with_a_question_mark_asks(scene: Scene, k: int, form: str) -> None:
    p, o, want = _person_object(scene, k)
    text = form.format(p=p, o=o)
    assert_refused(text, scene, match="question, not a request")
    said = text.removesuffix("?") + "."
    got = tree(said, scene)
    assert got is None or show_tree(got) == want, f"{said!r} -> {show_tree(got)}"


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(SCENES), st.integers(0, 6), st.sampled_from(LEAVE))
def test_asking_leave_with_a_question_mark_requests(scene: Scene, k: int, form: str) -> None:
    p, o, want = _person_object(scene, k)
    assert_means(form.format(p=p, o=o), want, scene)


@pytest.mark.parametrize(
    "text",
    [
        "Carol's thirsty, can you hand her the water bottle?",
        "Could Bob and Carol have a mug each?",
        "Give Bob the cup?",
        "Hey, could you give Alice the cup?",
    ],
)
def test_questions_that_request_still_read(text: str) -> None:
    assert tree(text) is not None, text


# -- a contrast after a description (a wrong reading on main) ------------------------------------
#
# The oracle, measured here from the scene's positions: "the <kind> closest to <person>, not the
# <one of that kind>" is read as the one the description picks, and only if the contrast leaves
# it; else refused. (The grounder refuses them all: a contrast beside a description that picks
# one is not read.)


def _kinds(scene: Scene) -> list[tuple[str, list[str]]]:
    cats: dict[str, list[str]] = {}
    for o in scene.objects:
        cats.setdefault(o.category, []).append(o.id)
    return [(c, ids) for c, ids in cats.items() if len(ids) > 1]


def _contrasts() -> list[tuple[Scene, str, str, str, str]]:
    out = []
    for scene in (CELL, OFFICE, CLASSROOM):
        for cat, ids in _kinds(scene):
            for h in scene.humans:
                for left_out in ids:
                    out.append((scene, cat, h.id, left_out, name_of(scene, left_out)))
    return out


def _nearest(scene: Scene, ids: list[str], pid: str) -> str:
    where = next(h.position for h in scene.humans if h.id == pid)
    pos = {o.id: o.position for o in scene.objects}
    return min(ids, key=lambda i: math.dist(pos[i][:2], where[:2]))


@pytest.mark.parametrize(("scene", "cat", "pid", "left_out", "said"), _contrasts())
@pytest.mark.parametrize("lead", ["closest to", "nearest to", "nearest"])
def test_a_contrast_never_overrides_a_description(
    scene: Scene, cat: str, pid: str, left_out: str, said: str, lead: str
) -> None:
    p = name_of(scene, pid)
    ids = [o.id for o in scene.objects if o.category == cat]
    for text in (
        f"Give {p} the {cat} {lead} {p}, not the {said}",
        f"Give {p} the {cat} {lead} her, not the {said}",
        f"Give {p} the {cat} {lead} {p} but not the {said}",
    ):
        got = tree(text, scene)
        pick = _nearest(scene, ids, pid)
        if got is not None:
            assert pick != left_out and show_tree(got) == f"{pick}>{pid}", (
                f"{text!r} -> {show_tree(got)}"
            )
