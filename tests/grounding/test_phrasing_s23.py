"""Session-23 phrasings of issue 12: blind21's three wrong readings fixed as families ('rest' as a
verb is not 'the rest'; a correction's 'the other one' after an object the only one of its kind,
with one other person left; a vowel put after a scene name makes another name) and blind21's
refusals by kind (docs/grounding.md, "Session 23")."""

from __future__ import annotations

from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    ROOT,
    SCENES,
    WORKSHOP,
    assert_reads,
    assert_refused,
    plain_request,
)

L24 = load_scene(ROOT / "examples/scenes/2-4-line.yaml")  # bottle, chips; Person A, Person B
F41 = load_scene(ROOT / "examples/scenes/4-1.yaml")  # bottle, chips, cup, apple; A, B

# -- (a) 'rest' said as a verb or with 'a' is not 'the rest' --------------------------------------


@settings(max_examples=30, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(
        [
            "{r}, and after that you can rest.",
            "{r} and then you can rest.",
            "{r}, and then you can have a rest",
            "{r}, then you can have a break.",
            "{r} and afterwards you can have a breather.",
        ]
    ),
)
def test_a_rest_for_the_robot_after_the_request_closes_it(scene: Scene, k: int, frame: str) -> None:
    # blind21: "First the apple to Person A, then the bottle to Person B, and after that you can
    # rest." read the rest of the objects into a third step
    request, want = plain_request(scene, k)
    assert_reads(frame.format(r=request), want, scene)


def test_rest_without_the_is_never_the_rest_of_the_objects() -> None:
    assert_reads(
        "First the apple to Person A, then the bottle to Person B, and after that you can rest.",
        "apple>A ; bottle>B",
        F41,
    )
    for text in (
        "The apple to Person A, then rest.",
        "The apple to Person A, then have a rest.",
        "Give the apple to Person A and rest the others on the table.",
    ):
        assert_refused(text, F41)
    # 'the rest' still reads
    assert_reads(
        "The apple to Person A, and the rest to Person B.",
        "apple>A & bottle>B & chips>B & cup>B",
        F41,
    )
    assert_reads(
        "The apple to Person A, and Person B gets the rest of them.",
        "apple>A & bottle>B & chips>B & cup>B",
        F41,
    )


# -- (b) a correction's 'the other one' after an object the only one of its kind -----------------


@settings(max_examples=30, deadline=None)
@given(
    st.sampled_from(["bottle", "chips"]),
    st.sampled_from(["Person A", "Person B"]),
    st.sampled_from(
        [
            "Give {p} the {o}, or no, hang on, the other one, you know.",
            "Give {p} the {o}, no, the other one.",
            "The {o} to {p}, no wait, the other one.",
            "Hand {p} the {o}, sorry, the other one I mean.",
            "{p} gets the {o}, actually, the other one.",
        ]
    ),
)
def test_the_other_one_correcting_a_lone_object_with_one_other_person_is_refused(
    obj: str, person: str, frame: str
) -> None:
    # blind21: "Give Person A the bottle, or no, hang on, the other one, you know." read chips>A
    # (the other person is as near)
    assert_refused(frame.format(o=obj, p=person), L24, match="other")


def test_the_other_one_of_a_kind_or_added_still_reads() -> None:
    lab = next(s for s in SCENES if {"cup_green", "cup_white"} <= {o.id for o in s.objects})
    assert_reads("Omar gets the green cup, no wait, the other one I mean", "cup_white>B", lab)
    assert_reads("Give Person A the bottle and Person B the other one.", "bottle>A & chips>B", L24)


# -- (c) a vowel put after a scene name makes another name -----------------------------------------


@settings(max_examples=30, deadline=None)
@given(st.sampled_from("aeio"), st.sampled_from(["Give {n} the drill.", "The torch to {n}, ta."]))
def test_a_vowel_after_a_name_is_another_person(vowel: str, frame: str) -> None:
    # blind21: "Give Jessa the drill, she's back on site." read drill>B ('Jessa' taken for a typo
    # of Jess): Jessa, Jesse, Jessi are names of their own
    assert_refused(frame.format(n="Jess" + vowel), WORKSHOP)


def test_slips_of_a_name_are_still_read() -> None:
    for typed in ("Jesss", "Jsess", "Jesa"):
        assert_reads(f"Give {typed} the drill.", "drill>B", WORKSHOP)


# -- 'give it him': British order, 'it' then the person -------------------------------------------


@settings(max_examples=30, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(
        [
            "The {o}, {p} wants it. Give it {p}, would you.",
            "{p} wants the {o}, could you hand it {p}?",
            "{p}'s asking for the {o}, pass it {p}.",
        ]
    ),
)
def test_it_before_the_person_is_what_the_person_gets(scene: Scene, k: int, frame: str) -> None:
    # blind21: "Grab that bottle and give it Person A, …", "Sam's after the red pen. Could you
    # give it him?"; blind19/20: "give it him", "Give it her, would you."
    request, want = plain_request(scene, k)
    said, thing = request.removeprefix("give ").split(" the ", 1)
    assert_reads(frame.format(o=thing, p=said), want, scene)


def test_it_before_a_person_is_refused_without_an_object_or_with_two_people() -> None:
    assert_refused("Give it Person A.", F41)  # 'it' refers to nothing
    assert_refused("The apple, give it him.", F41)  # 'him': Person A or Person B
    assert_reads("Grab that bottle and give it Person A, there's a good robot.", "bottle>A", F41)
