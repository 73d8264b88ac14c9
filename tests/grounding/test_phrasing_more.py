"""Session-4 phrasings of issue 12: keyword typos, remarks, contrast, 'instead of', 'the other'
after an 'or', 'then, once …', relative clauses and 'it' in a trailing 'once A has it'."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.errors import GroundingError
from hltl.grounding.lexicon import Lexicon, common_words
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import CELL, ROOT, assert_means
from tests.grounding.helpers import tree as _tree

SQUARE = load_scene(ROOT / "examples/scenes/4-4-square.yaml")
OBJECTS = ["cup", "bottle", "chips", "apple"]  # named alike in both scenes
PEOPLE = {"A": "Alice", "B": "Bob", "C": "Carol"}


# -- typos of keywords ----------------------------------------------------------------------------


def _swaps(word: str) -> list[str]:
    return sorted(
        {word[:k] + word[k + 1] + word[k] + word[k + 2 :] for k in range(len(word) - 1)} - {word}
    )


SENTENCE = "give Bob the cup and Carol the apple"


@settings(max_examples=40, deadline=None)
@given(st.sampled_from(["give", "the", "and"]), st.data())
def test_a_typo_of_a_keyword_means_it_or_nothing(word: str, data: st.DataObject) -> None:
    """A swap of neighbours in 'give', 'the' or 'and': the same spec, or a refusal."""
    typo = data.draw(st.sampled_from(_swaps(word)))
    words = SENTENCE.split()
    at = data.draw(st.sampled_from([k for k, w in enumerate(words) if w == word]))
    words[at] = typo
    got = _tree(" ".join(words))
    assert got is None or got == parse_instruction(SENTENCE, CELL)


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("give alice teh cup", "cup>A"),
        ("gvie Bob the chips", "chips>B"),
        ("Give Bob the chips adn Carol the apple", "chips>B & apple>C"),
    ],
)
def test_keyword_typos_examples(text: str, want: str) -> None:
    assert_means(text, want)


def test_a_keyword_typo_is_never_a_common_word_or_near_two_keywords() -> None:
    lex = Lexicon.of(CELL)
    assert "fro" in common_words() and lex.misspelt_keyword("fro") is None  # a word, not "for"
    assert lex.misspelt_keyword("hnad") is None  # "hand" and "had" are both one edit away
    assert lex.misspelt_keyword("cpu") is None  # a name ("cup") is as near: not a keyword
    assert lex.misspelt_keyword("teh") == "the"
    assert lex.misspelt_keyword("aer") is None  # "are" is skipped by the grammar: no silent drop
    assert lex.misspelt_keyword("thae") is None  # "the" or "that"


def test_a_keyword_typo_inside_a_phrase_keeps_the_phrase() -> None:
    assert_means(
        "put the bottle on the shelf and after taht give alice the chips", "bottle@shelf ; chips>A"
    )


@pytest.mark.parametrize(
    "text",
    [
        "Alice tfe cup, Bob the chips, Carol the apple",  # a name inside: not a remark
        "Give Alice the cup. ahen that is done, give Bob the apple.",  # 'when'/'then' mistyped
        "Give Alice the cup. Sorry ahen that is done, give Bob the apple.",
        "Give Bob the chips, he's tfe cup",
    ],
)
def test_what_may_be_a_request_is_never_dropped_as_a_remark(text: str) -> None:
    with pytest.raises(GroundingError):
        parse_instruction(text, CELL)


# -- remarks, contrast, nobody, instead of --------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(
    st.sampled_from(OBJECTS),
    st.sampled_from(["A", "B", "C"]),
    st.sampled_from(
        [
            "Sorry to bother you, but {}",
            "I know you're busy, but {}",
            "{}, {p} is hungry",
            "{}, {p}'s been waiting ages",
        ]
    ),
)
def test_remarks_add_nothing(obj: str, who: str, wrap: str) -> None:
    plain = f"give {PEOPLE[who]} the {obj}"
    assert_means(wrap.format(plain, p=PEOPLE[who]), f"{obj}>{who}")


def test_a_remark_with_an_unclear_pronoun_is_refused() -> None:
    with pytest.raises(GroundingError, match="could mean"):
        parse_instruction("Give Bob and Carol the chips, she's hungry", CELL)


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(OBJECTS),
    st.sampled_from(["A", "B", "C"]),
    st.sampled_from(["A", "B", "C"]),
    st.sampled_from(
        [
            "give the {o} to {p}, not to {q}",
            "give the {o} to {p}, not {q}",
            "{q} gets nothing, {p} gets the {o}",
            "give {p} the {o} and {q} gets nothing",
        ]
    ),
)
def test_a_person_set_against_the_recipient_gets_nothing(
    obj: str, who: str, other: str, form: str
) -> None:
    text = form.format(o=obj, p=PEOPLE[who], q=PEOPLE[other])
    if who == other:
        with pytest.raises(GroundingError, match="get nothing and something"):
            parse_instruction(text, CELL)
    else:
        assert_means(text, f"{obj}>{who}")


def test_negations_without_a_contrast_stay_refused() -> None:
    for text in (
        "Carol gets nothing",
        "Don't give Carol anything",
        "Give Bob the chips but not to Carol",
    ):
        with pytest.raises(GroundingError):
            parse_instruction(text, CELL)


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(OBJECTS),
    st.sampled_from(OBJECTS),
    st.sampled_from(["A", "B", "C"]),
    st.sampled_from(
        [
            "give {p} the {x} instead of the {y}",
            "instead of the {y}, give {p} the {x}",
            "give {p} the {x} instead of giving them the {y}",
        ]
    ),
)
def test_instead_of_without_a_running_task(x: str, y: str, who: str, form: str) -> None:
    text = form.format(p=PEOPLE[who], x=x, y=y)
    if x == y:
        assert _tree(text) is None
    else:
        assert_means(text, f"{x}>{who}")


# -- 'the other' after an 'or' --------------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@given(
    st.permutations(OBJECTS),
    st.permutations(["A", "B"]),
    st.sampled_from(
        [
            "Give Person {p} the {x} or the {y} and Person {q} the other",
            "Give Person {p} either the {x} or the {y}, and Person {q} the other one",
        ]
    ),
)
def test_the_other_after_an_or_of_two(objs: list[str], people: list[str], form: str) -> None:
    x, y = objs[:2]
    p, q = people
    text = form.format(p=p, q=q, x=x, y=y)
    assert_means(text, f"({x}>{p} & {y}>{q}) | ({y}>{p} & {x}>{q})", SQUARE)


def test_the_other_after_a_list_or_clauses_is_refused() -> None:
    for text in (
        "Give Person A the cup and the bottle and Person B the other",
        "Give Person A the cup or Person B the bottle and Person A the other",
    ):
        with pytest.raises(GroundingError, match="needs a choice"):
            parse_instruction(text, SQUARE)


# -- 'then, once …' and 'once A has it' -----------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(st.permutations(OBJECTS), st.permutations(["A", "B"]))
def test_once_the_person_has_it_refers_to_what_they_get(objs: list[str], people: list[str]) -> None:
    x, y = objs[:2]
    p, q = people
    assert_means(
        f"Give Person {p} the {x}, and Person {q} the {y} once Person {p} has it",
        f"{x}>{p} ; {y}>{q}",
        SQUARE,
    )
    assert_means(
        f"Give Person {p} the {x} and then, once Person {p} has it, give Person {q} the {y}",
        f"{x}>{p} ; {y}>{q}",
        SQUARE,
    )


def test_then_once_another_condition_waits_for_both() -> None:
    assert_means(
        "Give Bob the chips and then, once Carol has the cup, give Alice the apple",
        "(chips>B & cup>C) ; apple>A",
    )
    assert_means(
        "Please give Bob the chips and then, once he has them, give Carol the apple",
        "chips>B ; apple>C",
    )
    with pytest.raises(GroundingError, match="unclear where"):
        parse_instruction("Give Bob the chips, then once he has them give Carol the apple", CELL)


# -- relative clauses -----------------------------------------------------------------------------


@pytest.mark.parametrize(
    ("text", "want"),
    [
        ("Give Carol a mug that isn't red", "mug_blue>C"),
        ("Give Carol the mug that is blue", "mug_blue>C"),
        ("Give Carol a mug which is not blue", "mug_red>C"),
        ("give Bob the mugs that aren't red", "mug_blue>B"),
    ],
)
def test_a_relative_clause_picks_the_objects(text: str, want: str) -> None:
    assert_means(text, want)


@pytest.mark.parametrize(
    "text", ["Give Carol the mug that's green", "Give Carol the cup that isn't red"]
)
def test_a_relative_clause_naming_none_is_refused(text: str) -> None:
    with pytest.raises(GroundingError, match="no '"):
        parse_instruction(text, CELL)


# -- 'for each of them' ---------------------------------------------------------------------------

MUG_EACH = "(mug_red>{p} & mug_blue>{q}) | (mug_blue>{p} & mug_red>{q})"


@settings(max_examples=30, deadline=None)
@given(
    st.permutations(["A", "B", "C"]),
    st.sampled_from(
        [
            "Give {p} and {q} a mug for each of them",
            "{p} and {q} are thirsty, get a mug for each of them",
            "{p} and {q} would like a mug for each of them",
            "{p} and {q} are here. Give a mug to each of them",
        ]
    ),
)
def test_a_mug_for_each_of_them(people: list[str], form: str) -> None:
    p, q = people[:2]
    assert_means(form.format(p=PEOPLE[p], q=PEOPLE[q]), MUG_EACH.format(p=p, q=q))


def test_for_each_of_them_needs_enough_objects_and_people() -> None:
    for text in (
        "Alice, Bob and Carol are thirsty, get a mug for each of them",  # three people, two mugs
        "Give Alice and Carol the apple for each of them",  # one apple
        "Give one mug to each of them",  # nobody named
    ):
        with pytest.raises(GroundingError):
            parse_instruction(text, CELL)


# -- sequences inside either … or ------------------------------------------------------------------


@settings(max_examples=30, deadline=None)
@given(st.permutations(OBJECTS), st.permutations(["A", "B", "C"]))
def test_either_of_sequences(objs: list[str], people: list[str]) -> None:
    x, y, z = objs[:3]
    p, q, r = (PEOPLE[w] for w in people)
    text = f"Either give {p} the {x} and then {q} the {y}, or give {r} the {z}"
    assert_means(text, f"({x}>{people[0]} ; {y}>{people[1]}) | {z}>{people[2]}")


def test_steps_after_the_or_of_an_either_are_refused() -> None:
    for text in (
        "Either give Carol the apple, or give Alice the cup and then Bob the chips",
        "Either give Alice the cup then Bob the chips or give Carol the apple then Bob the cup",
    ):
        with pytest.raises(GroundingError, match="could belong"):
            parse_instruction(text, CELL)
    assert_means(
        "Either give Alice the cup or give Bob the chips. Then give Carol the apple.",
        "(cup>A | chips>B) ; apple>C",
    )


# -- relative descriptions by position ------------------------------------------------------------

ON_SURFACES = load_scene(ROOT / "tests/grounding/fixtures/on_surfaces.yaml")


def _nearest(ids: list[str], where: tuple[float, ...], scene: Scene) -> tuple[str, float, float]:
    pos = {o.id: o.position for o in scene.objects}
    d = sorted((((pos[i][0] - where[0]) ** 2 + (pos[i][1] - where[1]) ** 2) ** 0.5, i) for i in ids)
    return d[0][1], d[0][0], d[1][0]


@pytest.mark.parametrize(
    "anchor", ["Alice", "Bob", "Carol", "the shelf", "the table", "the apple", "the bottle"]
)
@pytest.mark.parametrize(
    "form",
    [
        "Give Bob the mug nearest to {a}",
        "Give Bob the mug next to {a}",
        "Give Bob a mug that's closest to {a}",
    ],
)
def test_the_mug_nearest_to_something_is_the_nearest_or_refused(anchor: str, form: str) -> None:
    """Checked against distances computed here: the clearly nearest mug, else a refusal."""
    where = {
        "Alice": CELL.humans[0].position,
        "Bob": CELL.humans[1].position,
        "Carol": CELL.humans[2].position,
        "the shelf": CELL.surfaces[0].center,
        "the table": CELL.surfaces[1].center,
        "the apple": next(o.position for o in CELL.objects if o.id == "apple"),
        "the bottle": next(o.position for o in CELL.objects if o.id == "bottle"),
    }[anchor]
    best, d1, d2 = _nearest(["mug_red", "mug_blue"], where, CELL)
    text = form.format(a=anchor)
    if d1 < 0.75 * d2:
        assert_means(text, f"{best}>B")
    else:
        with pytest.raises(GroundingError, match="about as near"):
            parse_instruction(text, CELL)


def test_places_examples() -> None:
    assert_means("Give Alice the mug closest to her", "mug_blue>A")
    assert_means("Put the mug by the shelf on the table", "mug_blue@table")
    assert_means("Give Bob the mug next to the red mug", "mug_blue>B")  # not itself
    assert_means("Give Bob the cup on the shelf", "cup_a>B", ON_SURFACES)
    assert_means("Give Alice the cup on the table and the apple", "cup_b>A & apple>A", ON_SURFACES)
    for text, scene in (
        ("Give Bob the cup on the shelf", CELL),  # the cup starts elsewhere
        ("Hand Bob the apple on the shelf", ON_SURFACES),
        ("Give Bob the cups on the table and the shelf", ON_SURFACES),
        ("Give Bob the mug near the robots", CELL),
        ("Give Bob the cup nearest to Carol", ON_SURFACES),  # as near to both cups
        ("Put the blue mug next to the red mug", CELL),  # placing by an object: no surface
    ):
        with pytest.raises(GroundingError):
            parse_instruction(text, scene)
