"""Phrasings the session-44 lead rules refuse or read (docs/grounding.md, Session 44 (lead))."""

from __future__ import annotations

import dataclasses

import pytest
from hypothesis import given
from hypothesis import strategies as st

from hltl.grounding import _rewrites44l, phrasing
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    KITCHEN,
    LAB,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
    tree,
)

# -- a he / she no name is said for, in a scene of one person (phrasing._sole_person32s with
# lexicon.unnamed_sex44l): blind42's one wrong reading, "Once you've got the bottle, hand it to
# him." with Person A alone, read bottle>A; the corpus's parts say Person A is 'she' and Person B
# 'he' in the generic scenes, and a first name, a title or a word of kin says the same

ONE = load_scene(ROOT / "examples/scenes/1-2.yaml")


def _alone(name: str, *aliases: str) -> Scene:
    """The one-person scene 1-2 with its person called ``name``."""
    person = dataclasses.replace(ONE.humans[0], name=name, aliases=aliases)
    return dataclasses.replace(ONE, humans=(person,))


HIM = ("him", "he", "He")
HER = ("her", "she", "She")
SAID = {
    "Person A": "f",
    "Person B": "m",
    "Alice": "f",
    "Bob": "m",
    "Mrs Khan": "f",
    "Mr Lee": "m",
}
FORMS = [
    "Once you've got the bottle, hand it to {obj}.",
    "Give {obj} the bottle.",
    "Pick up the bottle, then hand it to {obj}.",
    "See that bottle? {Subj}'d like it.",
    "Give the bottle to {obj}, {subj}'s thirsty.",  # session 32's, with 'him' for Person A
]


def _said(form: str, sex: str) -> str:
    obj, subj = ("him", "He") if sex == "m" else ("her", "She")
    return form.format(obj=obj, Subj=subj, subj=subj.lower())


@pytest.mark.parametrize("name", sorted(SAID))
@pytest.mark.parametrize("form", FORMS)
def test_pronoun_agreeing_with_the_one_person_reads(name: str, form: str) -> None:
    assert_reads(_said(form, SAID[name]), "bottle>A", _alone(name))


@pytest.mark.parametrize("name", sorted(SAID))
@pytest.mark.parametrize("form", FORMS)
def test_pronoun_the_one_person_is_not_refused(name: str, form: str) -> None:
    other = "m" if SAID[name] == "f" else "f"
    assert_refused(_said(form, other), _alone(name), match="not resolved: no one is named for it")


def test_blind42_wrong_reading_refused_naming_the_person() -> None:
    assert_refused(
        "Once you've got the bottle, hand it to him.",
        ONE,
        match="the scene's one person, Person A, is a she; name the person",
    )


@pytest.mark.parametrize(
    "text",
    [
        "Person A is thirsty, give him the bottle.",  # named first: the named person (blind23)
        "Give Person A the bottle, he's thirsty.",
        "Person A wants the bottle, she's thirsty.",
    ],
)
def test_named_person_still_reads(text: str) -> None:
    assert_reads(text, "bottle>A", ONE)


@pytest.mark.parametrize(
    ("name", "aliases"),
    [("Dana", ()), ("Person C", ()), ("Jess", ()), ("the visitor", ()), ("Person A", ("Kofi",))],
)
def test_no_sex_said_reads_either_pronoun(name: str, aliases: tuple[str, ...]) -> None:
    # the generic label's convention holds only for a person called by it alone: the paraphrase
    # scenes call Kofi 'Person A' too
    for form in FORMS:
        assert_reads(_said(form, "m"), "bottle>A", _alone(name, *aliases))
        assert_reads(_said(form, "f"), "bottle>A", _alone(name, *aliases))


def test_a_first_name_beside_the_label_rules_out() -> None:
    assert_refused("Give him the bottle.", _alone("Person A", "Alice"), match="is a she")
    assert_reads("Give him the bottle.", "bottle>A", _alone("Person A", "Bob"))


@given(st.sampled_from(sorted(SAID)), st.sampled_from(FORMS), st.booleans())
def test_agreement_decides(name: str, form: str, agree: bool) -> None:
    sex = SAID[name] if agree else ("m" if SAID[name] == "f" else "f")
    if agree:
        assert_reads(_said(form, sex), "bottle>A", _alone(name))
    else:
        assert_refused(_said(form, sex), _alone(name))


def test_refused_without_the_check(monkeypatch: pytest.MonkeyPatch) -> None:
    monkeypatch.setattr(phrasing, "unnamed_sex44l", lambda pid, lexicon: None)
    assert_reads("Once you've got the bottle, hand it to him.", "bottle>A", ONE)
    assert_reads("Give him the bottle.", "bottle>A", _alone("Alice"))


# -- what a person holds, said beside a request (_rewrites44l.held_beside44l): 12c's probes found
# "Mrs Khan's got her jug; give Mr Lee the magazine." read jug>C & magazine>B and "Bob's got the
# cup so give Alice the apple." cup>B & apple>A; refused now naming both readings

HELD = [
    ("Mrs Khan's got her jug; give Mr Lee the magazine.", WARD, "Mrs Khan", "jug"),
    ("Mrs Khan's got her jug, give Mr Lee the magazine.", WARD, "Mrs Khan", "jug"),
    ("Mrs Khan has the jug so give Mr Lee the magazine.", WARD, "Mrs Khan", "jug"),
    ("Bob's got the cup so give Alice the apple.", CELL, "Bob", "cup"),
    ("Alice has the apple, so give Bob the cup.", CELL, "Alice", "apple"),
    ("Bob's got his cup, so hand Alice the apple.", CELL, "Bob", "cup"),
    ("Give Carol the apple and Bob has his cup.", CELL, "Bob", "cup"),
    ("Sam has his stapler, so Priya can have the notebook.", OFFICE, "Sam", "stapler"),
    ("Jess has got her hammer; pass Kofi the drill.", WORKSHOP, "Jess", "hammer"),
]


@pytest.mark.parametrize(("text", "scene", "who", "thing"), HELD)
def test_held_beside_a_request_refused(text: str, scene: Scene, who: str, thing: str) -> None:
    assert_refused(text, scene, match=f"what {who} already holds .* {who} is to get the {thing}")


@pytest.mark.parametrize(("text", "scene", "who", "thing"), HELD)
def test_held_beside_a_request_read_without(
    text: str, scene: Scene, who: str, thing: str, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(_rewrites44l, "held_beside44l", lambda text, lexicon: None)
    assert tree(text, scene) is not None  # the grammar reads it as a share


# 12c's `holds` fuzz family: a remark that the person already holds / still has / has had / has
# their own thing, beside a request, had its thing read as a later 'it' or handed over
HOLDS = [
    ("Bob has his own crisps already. Put the cup on the shelf and then give it to Bob", CELL),
    ("Bob already has the crisps, so give Bob any mug, it doesn't matter which", CELL),
    ("Lena's got the tongs already, so the lemon should go on the counter.", KITCHEN),
    ("Jess still has the tin of screws from earlier, so put the hammer on the bench.", WORKSHOP),
    ("Jess has her own power drill already. Put the hammer on the bench", WORKSHOP),
    ("Omar is already holding the spoon. Either give Omar the banana or put it on the tray", LAB),
    ("Mrs Khan already has the medication, so take Mr Lee the magazine.", WARD),
    ("Carol's still holding the red mug, give her the apple too.", CELL),
]


@pytest.mark.parametrize(("text", "scene"), HOLDS)
def test_held_already_beside_a_request_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="already holds or had: it asks for nothing")


# the fuzz's own sentences, which the grammar read wrongly
HOLDS_READ = [
    HOLDS[0],
    HOLDS[1],
    (
        "Lena's got the tongs already, so the lemon should go on the counter and the salt should "
        "go to Lena once it's there",
        KITCHEN,
    ),
    (
        "Jess still has the tin of screws from earlier, so put the hammer on the bench and give "
        "Jess the torch once it's there",
        WORKSHOP,
    ),
    HOLDS[5],
]


@pytest.mark.parametrize(("text", "scene"), HOLDS + HOLDS_READ[2:4])
def test_held_already_beside_a_request_refused_too(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="already holds or had: it asks for nothing")


@pytest.mark.parametrize(("text", "scene"), HOLDS_READ)
def test_held_already_read_without(
    text: str, scene: Scene, monkeypatch: pytest.MonkeyPatch
) -> None:
    monkeypatch.setattr(_rewrites44l, "held_beside44l", lambda text, lexicon: None)
    # session 45 (12s): refused without held_beside44l too — normalise._remarks no longer says the
    # remark's thing for an 'it' whose object the request names before it (12c's fuzz had read
    # them with the thing misplaced or handed over)
    assert tree(text, scene) is None


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        # a share (session 32): the present 'has' beside another person's part allots
        ("Give Bob the cup, Alice has the apple.", "cup>B & apple>A", CELL),
        ("Bob has the cup and Alice the apple, please.", "cup>B & apple>A", CELL),
        ("Lena has the lemon, give Marco the tongs.", "lemon>B & tongs>A", KITCHEN),
        # a time, not a state
        ("Once Alice has the cup, Bob gets the chips", "cup>A ; chips>B", CELL),
        ("Give Alice the apple after Bob has the cup.", "cup>B ; apple>A", CELL),
        # 'her' not before a scene object
        ("Carol has her hands full, so put the apple on the shelf.", "apple@shelf", CELL),
        ("Bob still wants the apple, give it to him.", "apple>B", CELL),
    ],
)
def test_shares_and_times_read_as_before(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- a bare comma between two things after 'Not' is a correction, not a list of things left out
# (_rewrites42r._NOT_LIST42R): 12c's fuzz found "Not the apple, the cup, and it's for Alice. Alice
# wouldn't say no to the crisps." read chips>A, the cup dropped


@pytest.mark.parametrize(
    ("text", "want"),
    [
        (
            "Not the apple, the cup, and it's for Alice. Alice wouldn't say no to the crisps.",
            "cup>A & chips>A",
        ),
        ("Not the apple and not the cup; Bob gets the chips.", "chips>B"),
        ("Not the apple, not the cup: Bob gets the chips.", "chips>B"),
        ("Not the apple, nor the cup: Bob gets the chips.", "chips>B"),
        ("Not the red mug, not the blue; Bob gets the cup.", "cup>B"),
    ],
)
def test_not_then_a_bare_comma(text: str, want: str) -> None:
    assert_reads(text, want, CELL)
