"""Session-5 phrasings of issue 12: speaker preambles, reasons and remarks, retractions, 'both'
and 'all four' as objects, 'respectively', 'X last', 'there', 'once P has them', typos inside
names of two words, negated wants, corrections naming a person and an object."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import parse_expectation, show_tree
from hltl.errors import GroundingError
from hltl.grounding.lexicon import Lexicon, common_words, tokenize
from hltl.grounding.offline import parse_instruction, spec_of
from hltl.spec.equivalence import counterexample
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import CELL, ROOT, assert_means, one_edits, pronoun_for
from tests.grounding.helpers import tree as _tree

SQUARE = load_scene(ROOT / "examples/scenes/4-4-square.yaml")
DUO = load_scene(ROOT / "examples/scenes/2-2.yaml")
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")
OBJECTS = ["cup", "bottle", "chips", "apple"]
PEOPLE = {"A": "Alice", "B": "Bob", "C": "Carol"}


def assert_refused(text: str, scene: Scene = CELL, match: str | None = None) -> None:
    with pytest.raises(GroundingError, match=match):
        parse_instruction(text, scene)


# -- openings by the speaker and trailing remarks ------------------------------------------------

OPENINGS = [
    "I was wondering if you could {}",
    "I'd appreciate it if you could {}",
    "It would be great if you could {}",
    "Be a dear and {}",
    "Do me a favour and {}",
    "{}, if that's ok",
    "{} because he's hungry",
    "{}, she asked for it earlier",
    "{}, it's in the way",
    "{} since they are waiting",
    "Because Bob is hungry, {}",
    "Alice has been waiting a while. {}",
    "{}, can you sort that out?",
]
REQUESTS = [
    ("give Bob the chips", "chips>B"),
    ("put the cup on the shelf", "cup@shelf"),
    ("hand Carol the apple and Alice the red mug", "apple>C & mug_red>A"),
    ("give Alice the bottle, then Bob the cup", "bottle>A ; cup>B"),
]


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(OPENINGS), st.sampled_from(REQUESTS))
def test_openings_and_remarks_add_nothing(wrap: str, request: tuple[str, str]) -> None:
    text, want = request
    got = _tree(wrap.format(text))
    assert got is None or counterexample(spec_of(got), spec_of(parse_expectation(want))) is None


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("I was wondering if you could pass Alice the crisps", "chips>A"),
        ("Give Bob the chips because he's hungry", "chips>B"),
        ("Hand Carol the apple, she asked for it earlier", "apple>C"),
        ("Put the cup on the shelf, it's in the way", "cup@shelf"),
        ("Alice has been waiting a while. Give her the red mug.", "mug_red>A"),
        ("Give Bob the chips because Carol doesn't like them", "chips>B"),
        ("Give Alice the cup so she can have some tea", "cup>A"),
        ("Bob and Carol want something to drink, get a mug for each of them",
         "(mug_red>B & mug_blue>C) | (mug_blue>B & mug_red>C)"),
        ("Give Carol one of the mugs, I don't mind which", "mug_red>C | mug_blue>C"),
        ("Bob's after the chips, can you sort that out?", "chips>B"),
        ("Bob could use the cup, if that's ok", "cup>B"),
    ],
)  # fmt: skip
def test_remark_examples(text: str, want: str) -> None:
    assert_means(text, want)


@pytest.mark.parametrize(
    "text",
    [
        "Give Bob the chips because Carol wants the apple",  # a reason naming an object
        "Give Bob the chips because then give Carol the apple",
        "Give Bob the chips, Carol brownies",  # an unknown object, not a remark
        "Give Bob the chips, Carol wants them too",
        # someone else who wants or waits for it may be asking for it too
        "Give Bob the chips because Carol wants them",
        "Give Bob the cup, Alice is waiting for it",
        "Give Alice the cup and Carol the apple once she gets there",  # she: who arrives?
        "Give Bob the chips and Carol the apple because she's hungry",  # 'she': Alice or Carol
        "Because Bob is hungry",
        "Give the cup to Bob if he is hungry",
    ],
)
def test_what_may_be_a_request_is_not_dropped(text: str) -> None:
    assert _tree(text) is None


# -- corrections ---------------------------------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(
    st.permutations(OBJECTS),
    st.permutations(list(PEOPLE)),
    st.sampled_from(["Scratch that", "Forget that", "Strike that", "No"]),
)
def test_a_retraction_replaces_the_sentence_before(
    objs: list[str], people: list[str], word: str
) -> None:
    (a, b), (p, q) = objs[:2], people[:2]
    assert_means(f"Give {PEOPLE[p]} the {a}. {word}, give {PEOPLE[q]} the {b}.", f"{b}>{q}")
    assert_means(f"Give {PEOPLE[p]} the {a}, {word.lower()}, {PEOPLE[q]} wants the {b}", f"{b}>{q}")
    # 'her' is the person of the sentence taken back ('him' for a man's first name: session 34)
    her = pronoun_for(PEOPLE[p], "her")
    assert_means(f"Give {PEOPLE[p]} the {a}. {word}, give {her} the {b}.", f"{b}>{p}")


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give the bottle to Alice. Oh wait, to Bob actually.", "bottle>B"),
        ("Give Bob the chips and Carol the apple, actually no, Carol the cup", "chips>B & cup>C"),
        ("Put the cup on the counter. Scratch that, the crisps are for Bob.", "chips>B"),
        ("Bob wants the cup, no, give it to Carol", "cup>C"),
    ],
)
def test_correction_examples(text: str, want: str) -> None:
    assert_means(text, want)


@pytest.mark.parametrize(
    "text",
    [
        # which part is taken back is unclear
        "Give Bob the cup, then give Alice the apple. Scratch that, give Carol the chips.",
        # a person with two objects: which one does the new one replace?
        "Give Bob the chips and Carol the apple and the bottle, no, Carol the cup",
        "Give Alice the chips and Bob the cup. Scratch that, give her the bottle.",
        "Give Carol the apple. Give Bob the apple instead, no, give Alice the cup",
    ],
)
def test_unclear_corrections_are_refused(text: str) -> None:
    assert _tree(text) is None


# -- quantities ------------------------------------------------------------------------------------


@settings(max_examples=20, deadline=None)
@given(st.sampled_from(["A", "B"]), st.sampled_from(["all four", "all of it", "everything"]))
def test_all_four_is_every_object_of_a_scene_of_four(who: str, words: str) -> None:
    assert_means(f"Give Person {who} {words}", " & ".join(f"{o}>{who}" for o in OBJECTS), SQUARE)


def test_both_and_all_n_need_that_many() -> None:
    assert_means("Person A gets nothing, give Person B both", "bottle>B & chips>B", DUO)
    assert_means(
        "Either put the bottle on the shelf and then give Bob the chips, or give Alice both",
        "(bottle@shelf ; chips>B) | (bottle>A & chips>A)",
        TWO,
    )
    assert_means("Hand Alice one of the two mugs", "mug_red>A | mug_blue>A")
    assert_means("Give each person one item", "(bottle>A & chips>B) | (chips>A & bottle>B)", DUO)
    # six objects, none named
    assert_refused("Give Alice both", match="does not say which 2 objects")
    assert_refused("Give Person A all three", SQUARE, match="which 3 objects")
    assert_refused("Hand Alice one of the three mugs", match="not 3")
    assert_refused("Give everyone a mug", match="the scene has only 2")
    assert_refused("Give each person the apple", match="handed over only once")


@settings(max_examples=30, deadline=None)
@given(st.permutations(OBJECTS), st.permutations(list(PEOPLE)), st.integers(2, 3))
def test_respectively_pairs_the_lists(objs: list[str], people: list[str], n: int) -> None:
    names = [PEOPLE[p] for p in people[:n]]
    things = [f"the {o}" for o in objs[:n]]
    want = " & ".join(f"{o}>{p}" for o, p in zip(objs, people[:n], strict=False))

    def listed(xs: list[str]) -> str:
        return ", ".join(xs[:-1]) + " and " + xs[-1]

    assert_means(f"Give {listed(names)} {listed(things)} respectively", want)
    assert_means(f"Give {listed(things)} to {listed(names)}, respectively", want)
    assert_means(f"{listed(names)} get {listed(things)} respectively", want)
    # a list naming several objects at once cannot be paired: refused
    mugs = [*things[: n - 1], "the mugs"]
    assert _tree(f"Give {listed(names)} {listed(mugs)} respectively") is None


def test_respectively_refusals() -> None:
    assert_refused("Give Alice and Bob the cup respectively", match="respectively")
    assert_refused("Give Alice and Bob a mug and the apple respectively", match="respectively")
    assert_refused("Give Bob the cup and the apple respectively", match="respectively")


# -- order -----------------------------------------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(st.permutations(OBJECTS), st.permutations(list(PEOPLE)))
def test_x_last_comes_after_the_rest(objs: list[str], people: list[str]) -> None:
    (a, b, c), (p, q, r) = objs[:3], people
    x, y, z = (PEOPLE[w] for w in people)
    assert_means(f"Give {x} the {a} last; first give {y} the {b}", f"{b}>{q} ; {a}>{p}")
    assert_means(f"Give {y} the {b} and {x} the {a} last", f"{b}>{q} ; {a}>{p}")
    assert_means(
        f"Give {x} the {a} last, and {y} the {b} and {z} the {c}",
        f"({b}>{q} & {c}>{r}) ; {a}>{p}",
    )
    assert_means(f"Start by giving {x} the {a}, then hand {y} the {b}", f"{a}>{p} ; {b}>{q}")


def test_last_that_could_order_objects_is_refused() -> None:
    assert_refused("Give Alice the cup and the apple last", match="last")
    assert_refused("Give Bob the last mug", match="last")


@settings(max_examples=30, deadline=None)
@given(st.permutations(OBJECTS), st.permutations(["A", "B"]))
def test_once_the_person_has_them(objs: list[str], people: list[str]) -> None:
    (a, b, c), (p, q) = objs[:3], people
    assert_means(
        f"Give Person {p} the {a}, and Person {q} the {b} once Person {p} has them",
        f"{a}>{p} ; {b}>{q}",
        SQUARE,
    )
    assert_means(
        f"Give Person {p} the {a} and the {c}, and Person {q} the {b} once Person {p} has them",
        f"({a}>{p} & {c}>{p}) ; {b}>{q}",
        SQUARE,
    )
    # 'it' with two objects given: which one?
    assert (
        _tree(
            f"Give Person {p} the {a} and the {c}, and Person {q} the {b} once Person {p} has it",
            SQUARE,
        )
        is None
    )


def test_she_in_a_trailing_once_is_not_who_waits() -> None:
    assert_means("Give Alice the cup, and Bob the apple once she has it", "cup>A ; apple>B")
    assert_means("Give Bob the cup and the apple, and Carol the chips once he has them",
           "(cup>B & apple>B) ; chips>C")  # fmt: skip
    # two people it could be, besides the one who waits
    assert_refused(
        "Give Alice the cup and Carol the chips, and Bob the apple once she has it", match="'she'"
    )


def test_either_with_a_list_before_its_or() -> None:
    assert_means(
        "Either Person A gets the cup and the apple, or Person B gets all four",
        "(cup>A & apple>A) | (bottle>B & chips>B & cup>B & apple>B)",
        SQUARE,
    )


# -- places, names ---------------------------------------------------------------------------------


def test_there_is_the_surface_named_before() -> None:
    assert_means("Put the apple on the shelf and the cup there too", "apple@shelf & cup@shelf")
    assert_means("Put the apple on the shelf, then put the cup there", "apple@shelf ; cup@shelf")
    assert_refused("Give the cup to Bob and the apple there too", match="there")
    assert_refused("Put the apple on the shelf and the cup on the table and the bottle there")
    assert_refused("There's the cup, give it to Bob")


ALIASES = [("blue mug", "mug_blue"), ("red mug", "mug_red"), ("water bottle", "bottle")]


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(ALIASES), st.data())
def test_a_typo_inside_a_two_word_name_means_it_or_nothing(
    alias: tuple[str, str], data: st.DataObject
) -> None:
    words = alias[0].split()
    at = data.draw(st.sampled_from(range(len(words))))
    typo = data.draw(st.sampled_from(one_edits(words[at])))
    words[at] = typo
    got = _tree(f"give Carol the {' '.join(words)}")
    assert got is None or show_tree(got) == f"{alias[1]}>C", f"{words} -> {got}"


def test_two_word_typo_examples_and_limits() -> None:
    assert_means("Give Carol the bleu mug", "mug_blue>C")
    assert_means("give Carol the wter bottle", "bottle>C")
    assert "rad" in common_words()
    assert_refused("give Carol the rad mug", match="rad mug")  # a real word is no typo
    # three letters: beside the exact other word, by a swap of neighbours only (session 6)
    assert_means("Give Carol the rde mug", "mug_red>C")
    assert_refused("Give Carol the rdd mug")
    assert Lexicon.of(CELL).match(tokenize("bleu mug"), 0) is not None


def test_crisps_where_the_scene_says_chips() -> None:
    assert_means("Give Person B the crisps", "chips>B", SQUARE)
    assert_means("Give Person B the crisp", "chips>B", SQUARE)


# -- negation beside a request ---------------------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(st.permutations(OBJECTS), st.sampled_from(list(PEOPLE)))
def test_a_negated_want_beside_a_request(objs: list[str], p: str) -> None:
    a, b = objs[:2]
    who = PEOPLE[p]
    # (session 34: 'he' for a man's first name; 'she' would be someone else)
    assert_means(f"{who} doesn't want the {a}, {pronoun_for(who, 'she')} wants the {b}", f"{b}>{p}")
    assert_means(f"Don't give {who} the {a}, give {who} the {b}", f"{b}>{p}")
    # the same object again, 'everything' or a pronoun after it: refused, not guessed
    assert _tree(f"{who} doesn't want the {a}, give her everything") is None
    assert _tree(f"{who} doesn't want the {a}, give the {a} to {who}") is None
    assert _tree(f"{who} doesn't want the {a}, give it to {who}") is None
    assert _tree(f"{who} doesn't want the {a}") is None
