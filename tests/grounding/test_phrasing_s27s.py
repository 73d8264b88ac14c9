"""Session-27 phrasings of issue 12 (engineer 12s): courtesy words of other languages, the verb
said last, a description and the list it is, why a placement's surface was chosen, 'if you can
manage' — each rule with the near forms it must read and the near forms it must refuse
(docs/grounding.md, "Session 27 (engineer 12s)")."""

from __future__ import annotations

import dataclasses

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import Human, Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    DEPOT,
    KITCHEN,
    NURSERY,
    OFFICE,
    ROOT,
    SCENES,
    assert_reads,
    assert_refused,
    plain_request,
)

FOUR = load_scene(ROOT / "examples/scenes/4-2.yaml")  # bottle, chips, cup, apple; Person A, B
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # bottle, chips; Alice, Bob
FIG1 = load_scene(ROOT / "examples/scenes/fig1.yaml")  # bottle, chips; Alice, Bob; shelf

# -- courtesy words of other languages (normalise.py _COURTESY24, _PLEASE25) -------------------

# greetings and thanks said as a stretch of their own, one per language added in session 27
GREETINGS = (
    "Gamarjoba",
    "Gamarjobat",
    "Labas",
    "Laba diena",
    "Tena yistilign",
    "Selam",
    "Ayubowan",
    "Labdien",
    "Tere",
    "Barev dzez",
    "Zdravo",
    "Dzień dobry",
    "Privet",
    "Hej",
    "Annyeonghaseyo",
    "Mingalaba",
    "Nomoskar",
    "Sat sri akal",
    "Sannu",
    "Ndewo",
    "Aloha",
    "Marhaba",
    "Bom dia",
)
THANKS = (
    "Madloba",
    "Didi madloba",
    "Ačiū labai",
    "Aciu",
    "Ameseginalehu",
    "Betam amesegnalehu",
    "Sthuthi",
    "Bohoma sthuthi",
    "Paldies",
    "Aitäh",
    "Shnorhakalutyun",
    "Sag ol",
    "Hvala lijepa",
    "Dziękuję",
    "Blagodaryu",
    "Tack så mycket",
    "Takk",
    "Dank je wel",
    "Kamsahamnida",
    "Dhanyabad",
    "Na gode",
    "Daalu",
    "Ngiyabonga",
    "Enkosi",
    "Mahalo",
    "Toda raba",
    "Tesekkur ederim",
    "Muchas gracias",
)
PLEASE = (
    "Prašau",
    "Prasom",
    "Gtkhovt",
    "Ebakih",
    "Karunakarala",
    "Lūdzu",
    "Palun",
    "Proszę",
    "Molim",
    "Alstublieft",
    "Lütfen",
    "Pozhaluysta",
    "Parakalo",
    "Tafadhali",
    "Kripya",
    "Per favore",
)


@settings(max_examples=60, deadline=None)
@given(
    scene=st.sampled_from(SCENES),
    k=st.integers(0, 20),
    hello=st.sampled_from(GREETINGS),
    thanks=st.sampled_from(THANKS),
    please=st.sampled_from(PLEASE),
    address=st.sampled_from(("", ", genatsvale", ", my friend")),
)
def test_courtesy_of_other_languages_changes_nothing(
    scene: Scene, k: int, hello: str, thanks: str, please: str, address: str
) -> None:
    text, want = plain_request(scene, k)
    assert_reads(f"{hello}! {please}, {text}. {thanks}{address}.", want, scene)
    assert_reads(f"{text}, {thanks.lower()}", want, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Gamarjoba! Please, the crisps give to Bob, yes? Madloba.", "chips>B", TWO),
        ("Labas rytas! Prašau, give Person B the apple. Ačiū.", "apple>B", FOUR),
        ("Selam. Please, the cup to Person A. Ameseginalehu.", "cup>A", FOUR),
        ("Ayubowan! Karunakarala give Carol the red mug. Bohoma sthuthi.", "mug_red>C", CELL),
        ("Paldies, paldies, the salt to Marco.", "salt>A", KITCHEN),
    ],
)
def test_courtesy_of_other_languages_in_several_scenes(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    "text",
    [
        # where a name or an object is expected, a courtesy word is no name: refused
        "Give Madloba the cup.",
        "Give Carol the gamarjoba.",
        "Hand the apple to Ayubowan.",
        # said alone, it asks nothing
        "Gamarjoba! Madloba.",
        "Labas. Ačiū labai.",
    ],
)
def test_a_courtesy_word_where_a_name_is_expected_is_refused(text: str) -> None:
    assert_refused(text, CELL)


def _with_person(name: str) -> Scene:
    """The cell with a fourth person called ``name``."""
    return dataclasses.replace(
        CELL, humans=(*CELL.humans, Human(id="D", name=name, position=(0.0, -1.0, 0.0)))
    )


@pytest.mark.parametrize(
    ("name", "text", "want"),
    [
        # a person the scene calls by a word that is a courtesy elsewhere is that person
        ("Tere", "Tere, the cup is for you. Give Tere the cup.", "cup>D"),
        ("Palun", "Give Palun the apple, thanks.", "apple>D"),
        ("Molim", "Bring Molim the chips, please.", "chips>D"),
    ],
)
def test_a_courtesy_word_that_is_a_name_in_the_scene_stays_a_name(
    name: str, text: str, want: str
) -> None:
    assert_reads(text, want, _with_person(name))


def test_a_letter_with_a_mark_is_no_single_letter_name() -> None:
    # 'Ačiū' is read by the lexer as 'A', 'iū': the scene's Person A would be named
    assert_reads("Give Person B the chips. Ačiū labai.", "chips>B", FOUR)
    assert_reads("Ačiū, give Person A the chips.", "chips>A", FOUR)


# -- the verb said last; 'give to him the X' (normalise.py _verb_last27) -------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Person B the chips give.", "chips>B", FOUR),
        ("Please, Person A the cup and the apple give.", "cup>A & apple>A", FOUR),
        ("Mrs Khan the magazine give, please.", "magazine>C", None),
        ("The crisps on the shelf put.", "chips@shelf", FIG1),
        ("Alice is thirsty, you give to her the bottle.", "bottle>A", TWO),
        ("Bob is hungry, give to him the chips.", "chips>B", TWO),
    ],
)
def test_the_verb_said_last_reads_in_english_order(
    text: str, want: str, scene: Scene | None
) -> None:
    from tests.grounding.helpers import WARD

    assert_reads(text, want, scene if scene is not None else WARD)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # the verb agrees with a subject: 'Person B gives' is Person B doing it
        ("Person B the chips gives.", FOUR),
        # the object first, then the person: which is which is not said by the order
        ("The chips Person B give.", FOUR),
        # a word that is no person before the objects
        ("Somebody the chips give.", FOUR),
        # a person put somewhere, a surface given something
        ("Person A on the shelf put.", FOUR),
        ("The shelf the crisps give.", FIG1),
        # 'to him' with no one he can be
        ("Give to him the cup.", FOUR),
    ],
)
def test_the_verb_said_last_near_forms_are_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- a description and the list it is (normalise.py _described_list27) -------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("The two drinks, bottle and cup, go to Person B.", "bottle>B & cup>B", FOUR),
        ("Both snacks, the apple and the chips, to Person A.", "apple>A & chips>A", FOUR),
        (
            "The three things you can reach, the cup, the apple and the chips, to Person B.",
            "cup>B & apple>B & chips>B",
            FOUR,
        ),
        ("Hand over both items, chips and bottle alike, to Person B.", "chips>B & bottle>B", FOUR),
        ("The two mugs, the red mug and the blue mug, to Carol.", "mug_red>C & mug_blue>C", CELL),
        (
            "Anything edible goes to Person B, so that's the apple and the chips.",
            "apple>B & chips>B",
            FOUR,
        ),
        (
            "Everything sweet goes on the shelf, that is the bottle and the crisps.",
            "bottle@shelf & chips@shelf",
            FIG1,
        ),
        (
            "The two items you can see, the stapler and the notebook, both to Sam.",
            "stapler>B & notebook>B",
            OFFICE,
        ),
    ],
)
def test_a_description_then_its_list_reads_as_the_list(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # the count said is not the list's
        ("The three drinks, bottle and cup, go to Person B.", FOUR),
        ("Both snacks, the apple, the chips and the cup, to Person A.", FOUR),
        # the list is a choice or an exclusion, not a list
        ("The two drinks, the cup or the bottle, to Person B.", FOUR),
        ("The two drinks, not the cup and the bottle, to Person B.", FOUR),
        # the description names objects of the scene other than the list's
        ("The two mugs, the red mug and the apple, to Carol.", CELL),
        # a property the scene can check, which a listed object does not have
        ("Everything blue goes to Alice, so that's the red mug and the blue mug.", CELL),
        ("The two red things, the red mug and the apple, to Carol.", CELL),
        # 'anything <word>' with no list said: what is edible is not the grounder's to decide
        ("Anything edible goes to Person B.", FOUR),
        ("Anything edible goes to Person B, the apple and the chips.", FOUR),
        # a list naming a person
        ("Everything edible goes to Alice, so that's the apple and Bob.", CELL),
    ],
)
def test_a_description_the_list_does_not_match_is_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)


# -- why a surface, said after it; 'if you can manage' ----------------------------------------


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        (
            "Would you mind popping the crisps up on the shelf, out of the dog's reach?",
            "chips@shelf",
            FIG1,
        ),
        (
            "Bottle on the shelf out of reach, then give Bob the crisps.",
            "bottle@shelf ; chips>B",
            FIG1,
        ),
        ("Put the tape on the belt, out of the way.", "tape@conveyor", DEPOT),
        ("The teddy on the high chair, out of harm's way.", "teddy@highchair", NURSERY),
        ("Give Carol the cup, if you can manage.", "cup>C", CELL),
        ("Cup to Bob. Same with the apple, if you can manage it.", "cup>B & apple>B", CELL),
        ("Give Carol the cup, if you're able.", "cup>C", CELL),
    ],
)
def test_why_a_surface_and_whether_you_can_change_nothing(
    text: str, want: str, scene: Scene
) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        # no surface said: 'out of reach' would be the only place
        ("Put the crisps out of reach.", FIG1),
        ("The bottle, out of the way, please.", FIG1),
        # 'manage' with an object of its own is no courtesy
        ("Give Carol the cup if you can manage the apple.", CELL),
        ("Give Carol the cup, if you can manage the apple too.", CELL),
    ],
)
def test_why_and_whether_near_forms_are_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)
