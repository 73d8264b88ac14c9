"""Session-17 phrasings of issue 12: blind15's two wrong readings (a person's name with a later
letter changed into another first name) as a family over the scenes, with the slips that are still
corrected, checked against an oracle built from the scene and the shipped first-name list."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.grounding.lexicon import common_words, first_names
from hltl.world.scene import Scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    SCENES,
    WORKSHOP,
    assert_reads,
    assert_refused,
    name_of,
    plain_request,
)

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
