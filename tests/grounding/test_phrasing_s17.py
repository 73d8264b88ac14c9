"""Session-17 phrasings of issue 12: blind15's two wrong readings (a person's name with a later
letter changed into another first name) as a family over the scenes, with the slips that are still
corrected, checked against an oracle built from the scene and the shipped first-name list."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.errors import GroundingError
from hltl.grounding.lexicon import common_words, first_names
from hltl.grounding.offline import parse_instruction
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    SCENES,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
    name_of,
    plain_request,
    unique_objects,
)

F42 = load_scene(ROOT / "examples/scenes/4-2.yaml")

# -- a typo that is another first name ("Give the banana to Dina": read as Dana in blind15) -------
#
# The oracle: a person's one-word name with a vowel after the first letter changed into another
# vowel, or with a letter put in that is sounded, is another name when it is an English first name
# (data/first_names.txt), and is refused with 'did you mean …?'; the same name spelt another way
# (a letter doubled, 'i'/'y', 'c'/'k', 'c'/'s' before e/i/y, an 'h' or 'y' after a closing vowel)
# or two neighbours swapped is still that person.

NAMED = [
    "{p} wants the {o}",
    "Give the {o} to {p}",
    "Hand {p} the {o}, please",
    "The {o} is for {p}",
    "give {p} the {o}",
]
VOWELS = "aeiou"


def _one_word_names(scene: Scene) -> list[str]:
    """One-word names of 3+ letters that name only one person of ``scene``."""
    out = []
    for h in scene.humans:
        shared = {a for x in scene.humans if x.id != h.id for a in x.aliases}
        out += [
            a
            for a in h.aliases
            if " " not in a and len(a) >= 3 and a[0].isupper() and a not in shared
        ]
    return out


def _scene_words(scene: Scene) -> set[str]:
    names = [o.id for o in scene.objects] + [o.category for o in scene.objects]
    names += [a for o in scene.objects for a in o.aliases]
    names += [a for h in scene.humans for a in (h.name, *h.aliases)]
    names += [s.id for s in scene.surfaces] + [a for s in scene.surfaces for a in s.aliases]
    return {w.lower() for n in names for w in n.replace("_", " ").split()}


def _other_names(name: str) -> list[str]:
    """First names made from ``name`` by a vowel after its first letter changed into another
    vowel, or a consonant put in after its first letter that doubles no neighbour."""
    low = name.lower()
    out: set[str] = set()
    for k in range(1, len(low)):
        if low[k] in VOWELS:
            out |= {low[:k] + v + low[k + 1 :] for v in VOWELS if v != low[k]}
    for k in range(1, len(low) + 1):
        for c in "lnrdm":
            if c not in (low[k - 1], low[k : k + 1]):
                out.add(low[:k] + c + low[k:])
    return sorted(w.capitalize() for w in out if len(w) >= 4 and w in first_names())


CASES = [
    (scene, name, other)
    for scene in SCENES
    for name in _one_word_names(scene)
    for other in _other_names(name)
    if other.lower() not in _scene_words(scene) and other.lower() not in common_words()
]


def test_the_family_has_cases_in_most_scenes() -> None:
    # the oracle is not empty: Dina/Dena/Dona for Dana, Lana/Lina for Lena, Mila for Mia, …
    assert len({id(scene) for scene, _, _ in CASES}) >= 5
    assert len(CASES) >= 12


@settings(max_examples=120, deadline=None)
@given(st.integers(0, 10_000), st.integers(0, 6), st.sampled_from(NAMED))
def test_a_name_with_a_later_letter_changed_into_another_name_is_refused(
    n: int, k: int, form: str
) -> None:
    scene, name, other = CASES[n % len(CASES)]
    _, want = plain_request(scene, k)
    o = name_of(scene, want.split(">")[0])
    typed = other if form[0] != "g" else other.lower()
    assert_refused(form.format(p=typed, o=o), scene, match=f"did you mean '{name}'")


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Give the banana to Dina", LAB),  # blind15
        ("The salt is for Lana", KITCHEN),  # blind15
        ("Give Mila the tape", DEPOT),  # a sounded letter put in
        ("Omer wants the sponge", LAB),
        ("Give Emmy the cup", LAB),  # 'a' to 'y' at the end is another sound
        ("Lina wants the salt", KITCHEN),
        ("Lila wants the teddy", NURSERY),
    ],
)
def test_a_later_letter_changed_into_another_name_is_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene, match="no person called")


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give Alise the cup", "cup>A", CELL),  # 'c' and 's' before 'e' sound alike
        ("Give Zoey the globe", "globe>C", CLASSROOM),  # 'y' after a closing vowel
        ("Give Lenna the lemon", "lemon>B", KITCHEN),  # a letter doubled (a listed name too)
        ("Give Alcie the cup", "cup>A", CELL),  # two neighbours swapped (a listed name too)
        ("Give Marko the knife", "knife>A", KITCHEN),  # 'c' and 'k' sound alike
        ("Give Avah the teddy", "teddy>C", NURSERY),  # an 'h' after a closing vowel
        ("Jesss wants the torch", "torch>B", WORKSHOP),
        ("give Crol the chips", "chips>C", CELL),  # a letter left out: no listed name
    ],
)
def test_the_same_name_spelt_another_way_is_still_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


# -- refusals that say their readings (blind15's two refusals without readings) -----------------


@pytest.mark.parametrize(
    ("text", "scene", "readings"),
    [
        ("Sam gets the blue pen, no wait, the other one I mean", OFFICE, ["pen_black", "pen_red"]),
        ("Tom gets the small box, no wait, the other one", DEPOT, ["box_medium", "box_large"]),
        (
            "Ava keeps pointing at the blokc, can she have it?",
            NURSERY,
            ["block_red", "block_green"],
        ),
        (
            "Jess keeps pointing at the spanenr, can she have it?",
            WORKSHOP,
            ["spanner_small", "spanner_large"],
        ),
        (
            "Lena keeps asking about the plaet, can she have it?",
            KITCHEN,
            ["plate_white", "plate_blue"],
        ),
    ],
)
def test_a_refusal_names_what_the_other_or_a_typo_could_mean(
    text: str, scene: Scene, readings: list[str]
) -> None:
    with pytest.raises(GroundingError) as err:
        parse_instruction(text, scene)
    for r in readings:
        assert r in str(err.value)


def test_the_other_of_two_is_still_read() -> None:
    assert_reads("Omar gets the green cup, no wait, the other one I mean", "cup_white>B", LAB)


# -- 'he' and 'she' are two people ---------------------------------------------------------------


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(SCENES), st.integers(0, 12), st.sampled_from([("he", "she"), ("she", "he")]))
def test_he_and_she_with_one_person_named_are_refused(
    scene: Scene, k: int, pronouns: tuple[str, str]
) -> None:
    objs = unique_objects(scene)
    if len(objs) < 2:
        return
    _, want = plain_request(scene, k)
    pid = want.split(">")[1]
    p = name_of(scene, pid)
    a, b = objs[k % len(objs)], objs[(k + 1) % len(objs)]
    one, other = pronouns
    text = (
        f"{p} wants the {name_of(scene, a)}, {one}'s busy, and {other} wants the "
        f"{name_of(scene, b)}"
    )
    assert_refused(text, scene)


# -- blind15's kinds: each frame over the scenes reads as the plain request ----------------------

FRAMES = [
    "Excuse me, sorry to interrupt, could you give {p} the {o}? Many thanks.",
    "Could I trouble you to give {p} the {o}? Cheers.",
    "Now then, dear, be a good helper and give {p} the {o}, won't you?",
    "Be a dear and give {p} the {o}, there's a love.",
    "{p} is hoping to get the {o}",
    "{p} could do with the {o}",
    "{p} is to have the {o}",
    "See the {o}? Take it over to {p}.",
    "You can give the {o} to {p}, yes?",
    "Would you mind passing the {o} along to {p}?",
    "Any chance of the {o} going to {p}?",
    "Scene change. The {o} to {p}. Go.",
    "The {o} to {p}, and that's your lot",
]


@settings(max_examples=150, deadline=None)
@given(st.sampled_from(SCENES), st.integers(0, 12), st.sampled_from(FRAMES))
def test_a_frame_of_blind15_reads_as_the_plain_request(scene: Scene, k: int, frame: str) -> None:
    _, want = plain_request(scene, k)
    oid, pid = want.split(">")
    assert_reads(frame.format(p=name_of(scene, pid), o=name_of(scene, oid)), want, scene)


@pytest.mark.parametrize(
    ("text", "want", "scene"),
    [
        ("Give Bob the cup, and do the same for Carol but with the apple", "cup>B & apple>C", CELL),
        ("The bowl and the spoon: put them both in the sink.", "bowl@sink & spoon@sink", LAB),
        ("First the lemon to Lena. After, the salt to Marco. Finish.", "lemon>B ; salt>A", KITCHEN),
        ("Spoon: Omar. Bowl: Dana. Sponge: sink.", "spoon>B & bowl>A & sponge@sink", LAB),
        (
            "Pens first: red pen in the box. Then the stapler goes to Sam.",
            "pen_red@box ; stapler>B",
            OFFICE,
        ),
        ("Either cup is fine for Omar", "cup_green>B | cup_white>B", LAB),
        ("The knife can go to Marco or to Lena, whoever's nearer", "knife>A | knife>B", KITCHEN),
        ("One of the pens for Priya: the red or the blue", "pen_red>A | pen_blue>A", OFFICE),
        ("Put the pair of blocks on the play mat", "block_red@mat & block_green@mat", NURSERY),
        ("Hand Person A the only bottle there is", "bottle>A", CELL),
        (
            "Bob is getting a couple of things, namely the cup and the apple",
            "cup>B & apple>B",
            CELL,
        ),
        ("Leave the bowl where it is and take Emma the spoon", "spoon>C", LAB),
        ("Give Emma the spoon, no not the spoon, the banana!", "banana>C", LAB),
        ("Torch to Kofi. No no, not Kofi. Torch to Jess.", "torch>B", WORKSHOP),
        ("Apple to Carol. Actually no, cup to Carol.", "cup>C", CELL),
        ("White plate to Mr Novak, whoops, I meant the blue one", "plate_blue>C", KITCHEN),
        ("the white plate can sit on the rack", "plate_white@rack", KITCHEN),
        ("Marco can have whichever plate isn't the white one", "plate_blue>A", KITCHEN),
        ("Leave the chips alone and put only the apple on the shelf", "apple@shelf", CELL),
        ("Drop the spoon in the snik for washing", "spoon@sink", LAB),
        ("Sam wants the pair of pens, the black and the blue", "pen_black>B & pen_blue>B", OFFICE),
        ("Bob asked for his appl", "apple>B", CELL),
        ("Drill to Jess, correction, drill in the locker", "drill@locker", WORKSHOP),
        ("Would you take Mrs Khan's tablets over to her?", "pills>C", WARD),
        ("Lemon to Marco then knife to Lena, sorry, swap the people", "lemon>B ; knife>A", KITCHEN),
        ("Apple to Alice and chips to Bob, sorry, swap the people", "apple>B & chips>A", CELL),
        (
            "Mrs Ortiz is borrowing two books, the red one and the green one",
            "book_red>A & book_green>A",
            CLASSROOM,
        ),
        (
            "Okay two things, salt to Marco, lemon to Lena, and that's your lot",
            "salt>A & lemon>B",
            KITCHEN,
        ),
    ],
)
def test_a_kind_of_blind15_is_read(text: str, want: str, scene: Scene) -> None:
    assert_reads(text, want, scene)


@pytest.mark.parametrize(
    ("text", "scene"),
    [
        ("Salt to Lena. Thanks chef, and the knife to you too.", KITCHEN),
        ("I could do with the scanner", DEPOT),
        ("See the scanner? Take it over to her.", DEPOT),
        ("Do the same for Carol but with the apple", CELL),
        ("Black pen: Sam. Blue pen:", OFFICE),
        ("One of the drinks for Person A: the bottle or the chips", F42),
        ("Bob is getting a couple of things, namely the cup, the apple and the chips", CELL),
        ("Leave the bowl where it is and take Emma the bowl", LAB),
        ("Person A, but not Person A, gets the cup", F42),
        ("Bowl to Omar, whoops, I meant the blue one", LAB),
        ("Torch to Kofi. No no, not Kofi.", WORKSHOP),
        ("Did you give the lemon to Lena, yes?", KITCHEN),
        ("Any chance of the drill going to Kofi's brother?", WORKSHOP),
        ("Leave the chips alone and put only the chips on the shelf", CELL),
        ("Bowl to Omar, correction, spoon in the sink", LAB),
        ("Apple to Alice and chips to Alice, sorry, swap the people", CELL),
        ("Would you take Mr Lee's jug over to her?", WARD),
        ("Okay three things, drill to Kofi, torch to Jess, and that's your lot", WORKSHOP),
        ("Emma wants the pair of spoons", LAB),
        ("Sam wants the pair of pens", OFFICE),
        ("Omar can have whichever spoon isn't the green one", LAB),
    ],
)
def test_a_near_form_of_blind15_is_refused(text: str, scene: Scene) -> None:
    assert_refused(text, scene)
