"""Session-20 phrasings of issue 12: the two families blind18 read wrong (a list of objects as the
subject of a plural 'go' after a clause; an order word said as a sentence of its own), and the
lead's decision on time words and a closing ', maybe' (docs/grounding.md, "Session 20")."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    KITCHEN,
    OFFICE,
    SCENES,
    WARD,
    assert_reads,
    assert_refused,
    name_of,
    plain_request,
    unique_objects,
)

# scenes with three objects no other object shares a category with, and two people
LISTING = [s for s in SCENES if len(unique_objects(s)) >= 3 and len(s.humans) >= 2]


def _three(scene: Scene, k: int) -> tuple[list[str], list[str], list[str], list[str]]:
    objs = unique_objects(scene)
    picked = [objs[(k + n) % len(objs)] for n in range(3)]
    people = [scene.humans[k % len(scene.humans)].id, scene.humans[(k + 1) % len(scene.humans)].id]
    return (
        picked,
        [name_of(scene, o) for o in picked],
        people,
        [name_of(scene, p) for p in people],
    )


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(LISTING),
    st.integers(0, 7),
    st.sampled_from([" and ", ", "]),
    st.sampled_from(["", " too", " as well"]),
    st.sampled_from(["go", "goes"]),
)
def test_a_listed_subject_of_plural_go_is_the_verbs(
    scene: Scene, k: int, sep: str, tail: str, first: str
) -> None:
    # blind18: "The bottle goes to Person A and the chips go to Person B and the cup and the
    # apple go to Person A too" read the cup as Person B's
    (o1, o2, o3), (n1, n2, n3), (p1, p2), (h1, h2) = _three(scene, k)
    text = f"the {n1} {first} to {h1}{sep}the {n2} and the {n3} go to {h2}{tail}"
    assert_reads(text, f"{o1}>{p1} & {o2}>{p2} & {o3}>{p2}", scene)


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(LISTING), st.integers(0, 7), st.sampled_from(["gets", "wants", "needs"]))
def test_a_list_after_a_verb_before_plural_go_is_refused(scene: Scene, k: int, verb: str) -> None:
    # where the first clause's objects end is not said: 'B gets the X and the Y and the Z go to A'
    _, (n1, n2, n3), _, (h1, h2) = _three(scene, k)
    assert_refused(f"{h1} {verb} the {n1} and the {n2} and the {n3} go to {h2}", scene)
    assert_refused(f"give {h1} the {n1} and the {n2} and the {n3} go to {h2}", scene)


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(LISTING),
    st.integers(0, 7),
    st.sampled_from(["Once that's done", "Then", "After that", "When that's finished", "Next"]),
)
def test_an_order_word_said_as_a_sentence_orders_the_next(scene: Scene, k: int, cue: str) -> None:
    # blind18: "Chips to Person B. Once that's done. Cup to Person A." lost its order
    (o1, o2, _), (n1, n2, _), (p1, p2), (h1, h2) = _three(scene, k)
    text = f"The {n1} to {h1}. {cue}. The {n2} to {h2}."
    assert_reads(text, f"{o1}>{p1} ; {o2}>{p2}", scene)
    # first or last it orders nothing, as before
    assert_reads(f"The {n1} to {h1}. {cue}.", f"{o1}>{p1}", scene)


# -- the lead's decision (session 20) on time words and a closing ', maybe' ---------------------


@pytest.mark.parametrize("when", ["now", "today", "right away", "soon", "asap"])
@pytest.mark.parametrize("scene", [CELL, KITCHEN, OFFICE])
def test_immediacy_words_are_read(when: str, scene: Scene) -> None:
    request, want = plain_request(scene, 2)
    assert_reads(f"{request} {when}", want, scene)


@pytest.mark.parametrize(
    "when", ["tonight", "tomorrow", "after lunch", "in an hour", "in ten minutes", "this evening"]
)
@pytest.mark.parametrize("scene", [CELL, WARD])
def test_time_words_that_defer_are_refused_saying_why(when: str, scene: Scene) -> None:
    request, _ = plain_request(scene, 1)
    assert_refused(f"{request} {when}", scene, match="puts the task off: the cell acts now")


@pytest.mark.parametrize("soft", ["maybe", "perhaps"])
@pytest.mark.parametrize("scene", [CELL, KITCHEN, OFFICE, WARD])
def test_a_closing_maybe_softens_the_whole_request(soft: str, scene: Scene) -> None:
    request, want = plain_request(scene, 0)
    assert_reads(f"{request}, {soft}.", want, scene)
    assert_reads(f"If at all possible, {request}, {soft}?", want, scene)


@pytest.mark.parametrize(
    "text",
    [
        "Give Alice the cup, maybe the apple too.",  # introduces a further object
        "Give Alice the cup, maybe Bob too.",  # a further person
        "Give Alice the cup, maybe. Give Bob the chips.",  # closes one sentence of two
        "Cup for Alice. Apple for Bob. That's all, maybe",  # after words naming nothing
        "Give Alice the cup, maybe not.",
        "Give Alice the cup maybe",  # no comma: not set off as a softener
    ],
)
def test_a_maybe_that_leaves_something_open_stays_refused(text: str) -> None:
    assert_refused(text, CELL)


# -- blind18's refusals met by kind (session 20) ---------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # a person said to get nothing, named nowhere else, is no recipient
        ("Give Alice the cup, and nothing for Bob.", "cup>A"),
        ("Don't give anything to Carol; Bob gets the chips.", "chips>B"),
        # an object said not to be the one, named nowhere else
        ("Not the bottle, only the apple to Alice.", "apple>A"),
        # objects alone after the last separator, then an order word: after the task before
        ("Could Bob have the chips, and the apple after that?", "chips>B ; apple>B"),
        ("Give Carol the cup and the bottle afterwards.", "cup>C ; bottle>C"),
        # other words for a task being complete
        ("Bob gets the cup first. When that's sorted, chips over to Alice.", "cup>B ; chips>A"),
        ("Give Bob the cup, and once that's dealt with, the apple to Carol.", "cup>B ; apple>C"),
        # a count of tasks as a header, when the rest is that many tasks
        ("Two things. Cup to Alice. Apple to Bob.", "cup>A & apple>B"),
        (
            "Three jobs: the cup to Alice, the apple to Bob and the chips to Carol.",
            "cup>A & apple>B & chips>C",
        ),
        # a polite question's tag, and a request asked as whether it is possible
        ("Could the apple go across to Carol, do you think?", "apple>C"),
        ("Is it possible that Bob gets the chips, please?", "chips>B"),
        ("Is possible you give the cup to Alice?", "cup>A"),
        ("Sorry, quick one, give Bob the chips.", "chips>B"),
    ],
)
def test_blind18_kinds_are_read(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        "Give Alice the cup, and nothing for Alice.",  # the same person gets something
        "Give Alice the cup and Bob the apple, and nothing for Bob.",
        "Give each of them the chips, and nothing for Bob.",  # a group: who is meant changes
        "Not the bottle, only the apple to Alice and the bottle to Bob.",
        "Two things. Cup to Alice.",  # the count does not match what is asked
        "Two things. Cup to Alice. Apple to Bob. Chips to Carol.",
        "Alice has the apple, do you think?",  # a question about the scene, not a request
        "Is it possible that Bob gets the chips or not?",
    ],
)
def test_blind18_near_forms_stay_refused(text: str) -> None:
    assert_refused(text, CELL)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        # a correction said as the whole request again replaces the clause before its cue
        ("Chips to Alice. Correction, chips to Bob, and the apple to Alice.", "chips>B & apple>A"),
        ("Chips to Alice, sorry, I said that wrong, chips to Bob.", "chips>B"),
        ("The cup on the shelf, no, actually, give it to Carol.", "cup>C"),
        ("Give Bob the cup. Chips to Alice. No, chips to Carol.", "cup>B & chips>C"),
        ("Give Bob the apple. Hang on, give Bob the apple and the cup.", "apple>B & cup>B"),
    ],
)
def test_a_correction_said_as_the_whole_request_replaces_it(text: str, want: str) -> None:
    assert_reads(text, want, CELL)


@pytest.mark.parametrize(
    "text",
    [
        "Chips to Alice. Correction: the apple to Bob.",  # the chips are left unsaid
        "Chips to Alice. Sorry, the apple to Bob too.",  # adds, or corrects?
        "Give Alice the cup and Bob the chips, no, give Carol the cup.",  # the chips left out
    ],
)
def test_a_correction_that_leaves_something_out_stays_refused(text: str) -> None:
    assert_refused(text, CELL)
