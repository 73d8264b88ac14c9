"""Session-24 phrasings of issue 12: blind22's wrong reading fixed as a family (an object left out
and then said to be kept for something is never added) and blind22's refusals by kind
(docs/grounding.md, "Session 24")."""

from __future__ import annotations

import pytest
from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    ROOT,
    SCENES,
    WARD,
    WORKSHOP,
    assert_reads,
    assert_refused,
    assert_same_or_refused,
    plain_request,
)

F41 = load_scene(ROOT / "examples/scenes/4-1.yaml")  # bottle, chips, cup, apple; A, B
TWO = load_scene(ROOT / "examples/scenes/two_arms.yaml")  # bottle, chips (crisps); Alice, Bob

# scenes with exactly two objects of one kind: (scene, kind, (word, id) of each, a person's name
# and id, another person's name and id)
PAIRS: list[tuple[Scene, str, tuple[tuple[str, str], tuple[str, str]], tuple[str, str]]] = [
    (CELL, "mug", (("red", "mug_red"), ("blue", "mug_blue")), ("Bob", "B")),
    (LAB, "cup", (("green", "cup_green"), ("white", "cup_white")), ("Omar", "B")),
    (WARD, "blanket", (("blue", "blanket_blue"), ("grey", "blanket_grey")), ("Mr Lee", "B")),
    (KITCHEN, "plate", (("white", "plate_white"), ("blue", "plate_blue")), ("Lena", "B")),
    (CLASSROOM, "book", (("red", "book_red"), ("green", "book_green")), ("Noah", "B")),
    (NURSERY, "block", (("red", "block_red"), ("green", "block_green")), ("Lily", "A")),
    (WORKSHOP, "spanner", (("small", "spanner_small"), ("big", "spanner_large")), ("Jess", "B")),
]
USES = ["communion wine", "tea", "flowers", "photo", "open day", "inspection", "display"]

# -- (a) an object left out, then said to be kept for something, is never added -----------------


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(PAIRS),
    st.booleans(),
    st.sampled_from(USES),
    st.sampled_from(
        [
            "Any {kind} but the {out} one to {p}, the {out} one's for the {use}.",
            "Any {kind} except the {out} one to {p}, the {out} one is for the {use}.",
            "Give {p} a {kind}, not the {out} one, the {out} one's for the {use}.",
            "Give {p} a {kind} but not the {out} one, the {out} one's only for the {use}.",
            "{p} gets a {kind}, just not the {out} one, the {out} one's for the {use}.",
        ]
    ),
)
def test_an_object_kept_for_something_is_never_added(
    pair: tuple[Scene, str, tuple[tuple[str, str], tuple[str, str]], tuple[str, str]],
    flip: bool,
    use: str,
    frame: str,
) -> None:
    # blind22: "Any cup but the green one to Omar, the green one's for the communion wine." read
    # both cups to Omar: the purpose 'for the communion wine' was taken off alone, leaving "the
    # green one's", which read as 'the green one too'
    scene, kind, ways, (p, pid) = pair
    (out, _out_id), (_keep, keep_id) = ways[::-1] if flip else ways
    text = frame.format(kind=kind, out=out, p=p, use=use)
    assert_same_or_refused(text, f"{keep_id}>{pid}", scene)


def test_the_blind22_sentence_and_its_near_forms() -> None:
    assert_reads(
        "Any cup but the green one to Omar, the green one's for the communion wine.",
        "cup_white>B",
        LAB,
    )
    # the remark never adds the object, whichever object it names
    assert_reads(
        "Give Omar the white cup, the green one's for the communion wine.", "cup_white>B", LAB
    )
    assert_reads(
        "Any cup but the green one to Omar, the white one's for the communion wine.",
        "cup_white>B",
        LAB,
    )
    # said for a person, it asks for the object: read as before
    assert_reads(
        "Any cup but the green one to Omar, the green one's for Dana.",
        "cup_white>B & cup_green>A",
        LAB,
    )
    # a place, or something that points back, is not a purpose: refused
    assert_refused("Any cup but the green one to Omar, the green one's for the sink.", LAB)
    assert_refused("Give Omar the white cup, the green one's for the other one.", LAB)
    # a purpose at the end of a request still comes off alone
    assert_reads("Put the green cup on the tray for the communion wine.", "cup_green@tray", LAB)


# -- (b) the speaker talking about themself does not block the request ---------------------------

REMARKS = [
    "I'm the vicar",
    "I've come about the back door",
    "I'll be out of your hair in a minute",
    "I could see him shaking from the doorway",
    "my back's not what it was",
    "I misheard her",
    "I keep losing it",
    "my hands are all slippy from the clay",
]


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(REMARKS),
    st.sampled_from(
        [
            "{r}, {m}.",
            "{m}. {r}.",
            "{r}. Then {m}.",
            "Hello, {m}. Could you {r}? Thanks.",
            "{r}, and {m}.",
            "{r} while {m}.",
        ]
    ),
)
def test_a_remark_of_the_speaker_is_taken_off(
    scene: Scene, k: int, remark: str, frame: str
) -> None:
    # blind22: 27 refusals had 'I'/'me'/'my' in a remark about the speaker ("Then I'm off to warm
    # up my voice.", "…, I misheard her.", "… while I sort the rota?")
    request, want = plain_request(scene, k)
    if "while" in frame and not remark.startswith("I"):
        return  # 'while my back's …' is not how people talk
    assert_same_or_refused(frame.format(r=request, m=remark), want, scene)


def test_the_blind22_speaker_remarks_read() -> None:
    assert_reads(
        "Bottle to Bob. Crisps to Alice. Then I'm off to warm up my voice.",
        "bottle>B & chips>A",
        TWO,
    )
    assert_reads(
        "Would you mind taking the blue mug over to Carol while I sort the rota?", "mug_blue>C"
    )
    assert_reads(
        "Crisps on the shelf, no, scratch that, the crisps to Alice, I misheard her.",
        "chips>A",
        TWO,
    )
    assert_reads(
        "Good morning, I'm the vicar, here to bless the new wing. If it's no trouble at all, "
        "could the sponge go into the sink? Thank you so much, very kind.",
        "sponge@sink",
        LAB,
    )
    assert_reads(
        "Oh, sorry, I've got clay up to my elbows. Could you give Bob the crisps?", "chips>B", TWO
    )


@pytest.mark.parametrize(
    "text",
    [
        # the speaker as a recipient, or wanting something: 'I'/'me' is no one in the scene
        "Give me the crisps, I'm starving.",
        "Give Bob the crisps, I need the bottle.",
        "Give Bob the crisps, I'd like it too.",
        "Give Bob the crisps, then I'll have it.",
        "The bottle for me, I'm thirsty.",
        "Give Bob the crisps and I'll keep the bottle.",
        # a remark that changes, doubts, chooses or puts off the request is not taken off (before
        # session 24 the session-15 remark rule took "I changed my mind" off)
        "Give Bob the crisps, I'm not sure which.",
        "Give Bob the crisps, or Alice, I forget who asked.",
        "Give Bob the crisps when I say so.",
        "Give Bob the crisps, I changed my mind.",
        "Give Bob the crisps, I've changed my mind, ignore that.",
        # a remark naming something in the scene may ask for it
        "Give Bob the crisps, I'm saving the bottle.",
    ],
)
def test_a_remark_that_asks_or_changes_is_still_refused(text: str) -> None:
    assert_refused(text, TWO)


# -- (c) greetings, thanks and particles of other languages; a real word is no typo -------------


@settings(max_examples=60, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(
        [
            "Sawasdee krap. {r}, krap. Khop khun krap.",
            "Habari, my friend. {r}. Asante sana.",
            "Dobryi den. {r}. Diakuiu, thank you very much.",
            "{r}. Amen to that.",
            "{r}, asante.",
            "{r}, pole pole, no hurry.",
            "Salamat po. {r}.",
            "Ah, good afternoon. {r}.",
            "{r} please krap.",
        ]
    ),
)
def test_courtesies_of_other_languages_are_taken_off(scene: Scene, k: int, frame: str) -> None:
    # blind22: "krap", "asante", "Amen to that", "Dobryi den", "Diakuiu" were read as names or
    # clauses and refused
    request, want = plain_request(scene, k)
    assert_same_or_refused(frame.format(r=request[0].upper() + request[1:]), want, scene)


def test_the_blind22_courtesies_read() -> None:
    assert_reads(
        "Sawasdee krap. Excuse me, sorry, please you bring cup to Person B, krap. Khop khun "
        "krap, very kind of you.",
        "cup>B",
        F41,
    )
    assert_reads(
        "Bowl in the sink. Spoon on the tray. The green cup on the tray too. Amen to that.",
        "bowl@sink & spoon@tray & cup_green@tray",
        LAB,
    )
    # a courtesy word that names something in the scene, or stands where a name is asked for,
    # is not taken off
    assert_refused("Give Person A the, asante.", F41)
    assert_refused("Give asante the cup.", F41)


def test_a_real_word_with_another_first_letter_is_no_typo_of_a_keyword() -> None:
    # blind22: "before I back the lorry up" read 'lorry' as 'sorry' (one edit), a correction
    assert_reads(
        "Could you put the medium box on the belt before I back the lorry up?",
        "box_medium@conveyor",
        DEPOT,
    )
    # slips that keep the first letter, or swap the first two, are still read
    assert_reads("gvie Bob the crisps", "chips>B", TWO)
    assert_reads("give Bob hte crisps", "chips>B", TWO)


# -- (d) the speaker's doubt is never taken off (12c's fuzz, seed 24) ----------------------------


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(SCENES),
    st.integers(0, 20),
    st.sampled_from(
        [
            "I'm not sure, morning! {r}.",
            "I'm not sure, thanks! Now {r}.",
            "I'm not sure. {r}, please.",
            "{r}. Ugh, I don't know. Good robot.",
            "{r}, no idea really. Thanks!",
            "Hello, I can't remember. {r}.",
        ]
    ),
)
def test_a_request_said_with_doubt_is_refused(scene: Scene, k: int, frame: str) -> None:
    # 12c's fuzz (seed 24): "I'm not sure, morning! Would you mind passing Bob the crisps?" read
    # chips>B, and "The big box to Tom. No, Mia. No, Tom. Ugh, I don't know. Good robot." read the
    # last correction: a rewrite had taken the speaker's doubt off with the opener or closer
    request, _want = plain_request(scene, k)
    assert_refused(frame.format(r=request), scene)


def test_the_fuzz_doubts_are_refused() -> None:
    assert_refused("I'm not sure, morning! Would you mind passing Bob the crisps?")
    assert_refused(
        "The big box to Tom. No, Mia. No, Tom. Ugh, I don't know. That's all from me.", DEPOT
    )
    # a hedge that is no doubt about the request still reads
    assert_reads("Give Bob the crisps, I'm sure of it.", "chips>B", TWO)


def test_a_second_cue_of_one_correction_takes_back_nothing_before_it() -> None:
    # the fuzz over blind22 (seed 24): "I want the bottle too. Crisps on the shelf, no, scratch
    # that, the crisps to Alice, I misheard her." read chips>A: the correction restated after
    # 'no' kept 'scratch that' at its head, which then took back the sentence before (the
    # speaker's own want, which must be refused)
    for text in (
        "I want the bottle too. Crisps on the shelf, no, scratch that, the crisps to Alice, I "
        "misheard her.",
        "I want the bottle too. Crisps on the shelf, no, scratch that, the crisps to Alice.",
        "I need the bottle. Crisps on the shelf, sorry, forget that, the crisps to Bob.",
    ):
        assert_refused(text, TWO)
    assert_reads(
        "Crisps on the shelf, no, scratch that, the crisps to Alice, I misheard her.",
        "chips>A",
        TWO,
    )
    assert_reads(
        "Bottle to Bob. Crisps on the shelf, no, scratch that, the crisps to Alice.",
        "bottle>B & chips>A",
        TWO,
    )
