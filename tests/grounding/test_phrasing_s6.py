"""Session-6 phrasings of issue 12: blind4's two wrong readings (a plural naming one object, a
clause added with ', and also' after a sequence), descriptions measured in the scene's own
layout, and the general causes of blind4's refusals."""

from __future__ import annotations

import dataclasses

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import parse_expectation, show_tree
from hltl.errors import GroundingError
from hltl.grounding.offline import parse_instruction, spec_of
from hltl.spec.equivalence import counterexample
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import CELL, ROOT, assert_means
from tests.grounding.helpers import tree as _tree

F42 = load_scene(ROOT / "examples/scenes/4-2.yaml")
SQUARE = load_scene(ROOT / "examples/scenes/4-4-square.yaml")
LINE44 = load_scene(ROOT / "examples/scenes/4-4-line.yaml")
ONE = load_scene(ROOT / "examples/scenes/1-1.yaml")


def _refused(text: str, scene: Scene = CELL, match: str | None = None) -> None:
    with pytest.raises(GroundingError, match=match):
        parse_instruction(text, scene)


# -- a plural must not silently become one object ------------------------------------------------


def _plural(word: str) -> str:
    return word + ("es" if word.endswith(("s", "x", "ch", "sh")) else "s")


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(["cup", "bottle", "apple"]),
    st.sampled_from(
        [
            "give Alice the {}",
            "put the {} on the shelf",
            "Bob wants the {}",
            "hand the {} to Carol",
            "give Bob the chips and the {}",
        ]
    ),
)
def test_a_plural_of_one_object_is_refused(word: str, frame: str) -> None:
    """'the cups' with one cup in the scene asks for more than there is: refused, never cup."""
    _refused(frame.format(_plural(word)), match="only one")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("give Alice the mugs", "mug_red>A & mug_blue>A"),  # two mugs: every mug
        ("give Alice the chips", "chips>A"),  # the name itself ends in s
        ("give Bob the crisps", "chips>B"),  # an alias
        ("give Carol all the mugs and the cup", "mug_red>C & mug_blue>C & cup>C"),
        ("Give Person A everything", "bottle>A"),
    ],
)
def test_plural_names_that_fit_the_scene_still_ground(text: str, want: str) -> None:
    assert_means(text, want, ONE if "Person A" in text else CELL)


def test_the_refusal_of_a_plural_says_what_the_scene_has() -> None:
    _refused("Give Alice the cups", match=r"'cups'.*only one \(cup\)")
    _refused("Give Person A the bottles", ONE, match="only one")


# -- ', and also …' after the steps of a sequence -------------------------------------------------

STEPS = [("Person A the bottle", "bottle>A"), ("Person B the chips", "chips>B")]
ADDED = [
    ("Person A the cup and the apple", "cup>A & apple>A"),
    ("give Person B the cup", "cup>B"),
    ("Person B the apple", "apple>B"),
]


@settings(max_examples=30, deadline=None)
@given(
    st.sampled_from(
        ["First give {0}, then {1}", "Give {0}, then give {1}", "Give {0} and then {1}"]
    ),
    st.sampled_from([", and also {}", ", also {}"]),
    st.sampled_from(ADDED),
)
def test_a_clause_added_with_also_is_not_a_later_step(
    steps: str, joint: str, added: tuple[str, str]
) -> None:
    """It stands beside the whole sequence: '(X ; Y) & Z', never 'X ; (Y & Z)'."""
    (s1, w1), (s2, w2) = STEPS
    text = steps.format(s1, s2) + joint.format(added[0])
    got = _tree(text, F42)
    if got is None:
        return  # a refusal is allowed; a different reading is not
    want = parse_expectation(f"({w1} ; {w2}) & ({added[1]})")
    assert counterexample(spec_of(got), spec_of(want)) is None, f"{text!r} -> {show_tree(got)}"


def test_the_blind4_sentence_reads_as_intended() -> None:
    assert_means(
        "First give Person A the bottle, then Person B the chips, and also Person A the cup and "
        "the apple",
        "(bottle>A ; chips>B) & cup>A & apple>A",
        F42,
    )


@pytest.mark.parametrize(
    "text",
    [
        # objects alone: B's in that step, or a new task?
        "First give Person A the bottle, then give Person B the chips, and also the cup",
        # an addition before a later step: part of which?
        "Give Person A the bottle, then Person B the chips, and also Person A the cup, then "
        "Person B the apple",
    ],
)
def test_an_unclear_addition_is_refused(text: str) -> None:
    _refused(text, F42, match="its own sentence")


def test_also_inside_one_step_is_still_that_step() -> None:
    assert_means("Give Alice the cup and also the apple", "cup>A & apple>A")
    assert_means(
        "Give Alice the cup, then give Bob the chips and the apple", "cup>A ; (chips>B & apple>B)"
    )


# -- descriptions are measured in the scene's own layout ------------------------------------------


def test_the_nearest_object_is_measured_in_the_scene_given() -> None:
    """4-4-square and 4-4-line share every name; the lexicon of one must not measure the other."""
    parse_instruction("Give Person A the cup", SQUARE)  # build and cache the square's lexicon
    assert_means("Give Person A the object closest to Person A", "cup>A", LINE44)
    assert_means("Give Person B the thing nearest to Person B", "bottle>B", LINE44)


@settings(max_examples=25, deadline=None)
@given(st.floats(-3.0, 3.0), st.floats(-3.0, 3.0))
def test_moving_a_person_moves_what_is_nearest(x: float, y: float) -> None:
    """Same names, different positions: 'the mug nearest to Alice' follows where Alice is."""
    shifted = dataclasses.replace(
        CELL,
        humans=tuple(
            dataclasses.replace(h, position=(x, y, 0.0)) if h.id == "A" else h for h in CELL.humans
        ),
    )
    mugs = {o.id: o.position for o in CELL.objects if o.category == "mug"}
    dist = sorted((((p[0] - x) ** 2 + (p[1] - y) ** 2) ** 0.5, i) for i, p in mugs.items())
    got = _tree("give Alice the mug nearest to her", shifted)
    if dist[0][0] < 0.75 * dist[1][0]:
        assert got is not None and show_tree(got) == f"{dist[0][1]}>A"
    else:
        assert got is None
