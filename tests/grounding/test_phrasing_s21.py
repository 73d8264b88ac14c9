"""Session-21 phrasings of issue 12: the four families read wrong in session 20 (blind19's order
said across sentences and its name one letter from a scene's name; the fuzz's 'not yet' and its
'Excuse me, sorry,' taken for a correction), with near forms (docs/grounding.md, "Session 21")."""

from __future__ import annotations

import re
from collections.abc import Callable

from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.bench.grounding import parse_expectation, show_tree
from hltl.grounding.lexicon import PRONOUN_SEX, Lexicon, _same_name, _touching, title_sex
from hltl.world.scene import Scene, load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    LAB,
    ROOT,
    SCENES,
    assert_reads,
    assert_refused,
    fits,
    name_of,
    paraphrase_scene,
    plain_request,
    tree,
    unique_objects,
)

# scenes with two objects no other object shares a category with, and two people
PAIRED = [s for s in SCENES if len(unique_objects(s)) >= 2 and len(s.humans) >= 2]
T21 = load_scene(ROOT / "examples/scenes/2-1.yaml")  # Person A and B; bottle and chips


def _requests_in(frames: list[str]) -> Callable[..., None]:
    """Hypothesis over a scene, which of its plain requests (plain_request) and a frame."""
    return given(st.sampled_from(SCENES), st.integers(0, 20), st.sampled_from(frames))


def _two(scene: Scene, k: int) -> tuple[tuple[str, str], tuple[str, str], tuple[str, str]]:
    objs = unique_objects(scene)
    o1, o2 = objs[k % len(objs)], objs[(k + 1) % len(objs)]
    p1, p2 = scene.humans[k % len(scene.humans)].id, scene.humans[(k + 1) % len(scene.humans)].id
    return (o1, o2), (p1, p2), (name_of(scene, o1), name_of(scene, o2))


@settings(max_examples=40, deadline=None)
@given(
    st.sampled_from(PAIRED),
    st.integers(0, 7),
    st.sampled_from(["Then", "After that,", "Next,"]),
    st.sampled_from(["Those are for {h}.", "{h} gets them.", "Give them to {h}."]),
)
def test_objects_said_alone_in_order_keep_the_order_of_the_step_giving_them(
    scene: Scene, k: int, cue: str, giving: str
) -> None:
    # blind19: "Start with the bottle. Person B gets it. Then the chips. Those are for Person A."
    # read bottle>B & chips>A (the order went with the sentence naming the chips alone)
    (o1, o2), (p1, p2), (n1, n2) = _two(scene, k)
    h1, h2 = name_of(scene, p1), name_of(scene, p2)
    said = giving.format(h=h2)
    assert_reads(f"{h1} gets the {n1}. {cue} the {n2}. {said}", f"{o1}>{p1} ; {o2}>{p2}", scene)
    assert_reads(f"The {n1}. {h1} gets it. {cue} the {n2}. {said}", f"{o1}>{p1} ; {o2}>{p2}", scene)
    # 'Before that' puts the step giving them first
    assert_reads(
        f"{h1} gets the {n1}. Before that, the {n2}. {said}", f"{o2}>{p2} ; {o1}>{p1}", scene
    )


def test_the_blind19_sentence_and_its_near_forms() -> None:
    want = "bottle>B ; chips>A"
    assert_reads(
        "Start with the bottle. Person B gets it. Then the chips. Those are for Person A.",
        want,
        T21,
    )
    assert_reads(
        "Person B gets the bottle. Then pick up the chips. Give them to Person A.", want, T21
    )
    # the order said inside a sentence and who gets them in the next: refused, not read as '&'
    assert_refused(
        "Person B gets the bottle, then the chips. Person A gets those.", T21, "put in order"
    )
    # a sentence naming other objects after the objects alone is no step with them
    assert_reads("Person B gets the bottle. Then the chips. Person A gets them.", want, T21)


@settings(max_examples=60, deadline=None)
@given(st.sampled_from(SCENES), st.integers(0, 30), st.data())
def test_a_name_with_a_letter_far_on_the_keyboard_is_another_name(
    scene: Scene, k: int, data: st.DataObject
) -> None:
    # blind19: "Give Noam the ruler" read Noam as Noah: 'm' is not beside 'h' on a keyboard,
    # so Noam is another name, from a language the English list of names lacks
    lexicon = Lexicon.of(scene)
    names = [
        a
        for h in scene.humans
        for a in h.aliases
        if a.isalpha() and len(a) >= 4 and a[0].isupper() and a.lower() not in ("student",)
    ]
    if not names:
        return
    name = names[k % len(names)].lower()
    at = data.draw(st.integers(1, len(name) - 1))
    far = [
        c for c in "abcdefghijklmnopqrstuvwxyz" if c != name[at] and c not in _touching(name[at])
    ]
    typed = name[:at] + data.draw(st.sampled_from(far)) + name[at + 1 :]
    if _same_name(typed, name):
        return  # 'Alyce': the same name spelt another way ('i'/'y' sound the same)
    refs = lexicon.misspelt(typed)
    # never read as the scene's person: another name, or a word of its own
    assert refs is None or all(r.kind != "human" for r in refs), (typed, name, refs)


def test_noam_is_refused_and_near_slips_of_a_name_are_read() -> None:
    assert_refused("Give Noam the ruler, he's drawing margins.", CLASSROOM)
    assert_refused("Give Noam the ruler.", CLASSROOM)
    # a key beside the one meant ('Npah': 'p' beside 'o'), a letter doubled, a swap: read
    for typed in ("Npah", "Noahh", "Naoh"):
        assert_reads(f"Give {typed} the ruler.", "ruler>B", CLASSROOM)


@settings(max_examples=30, deadline=None)
@_requests_in(["Not yet, {r}", "{r}, but not yet", "Not yet: {r}", "{r}. Not just yet."])
def test_not_yet_puts_the_task_off(scene: Scene, k: int, frame: str) -> None:
    # fuzz seed 21: "Not yet, attention please, this is your captain speaking: the bowl to Dana"
    # read the bowl to Dana
    request, _ = plain_request(scene, k)
    assert_refused(frame.format(r=request), scene, "puts the task off")


def test_not_yet_after_an_order_colon_is_refused() -> None:
    assert_refused(
        "Not yet, attention please, this is your captain speaking: the bowl to Dana", LAB
    )


@settings(max_examples=30, deadline=None)
@_requests_in(["Excuse me, sorry,", "Pardon me, sorry,", "Excuse me, so sorry,"])
def test_excuse_me_sorry_corrects_nothing(scene: Scene, k: int, cue: str) -> None:
    # fuzz seed 21: "Give me the glue stick as well. Excuse me, sorry, I'm just covering this
    # class today. Could you put the globe on the desk?" dropped the sentence asking for 'me'
    request, want = plain_request(scene, k)
    obj = unique_objects(scene)[(k + 1) % len(unique_objects(scene))]
    text = f"Give me the {name_of(scene, obj)} as well. {cue} I'm just covering today. {request}."
    assert_refused(text, scene)
    # alone, the apology is taken off and the request read
    assert_reads(f"{cue} I'm just covering today. {request}.", want, scene)


def test_sorry_to_bother_is_an_apology_whose_refusal_names_the_readings() -> None:
    # blind19: refused as a correction, without naming the two cups
    assert_refused(
        "Morning! Postdoc here, sorry to bother. Would you be so kind as to bring the cup "
        "across to Omar for me? Cheers.",
        LAB,
        "cup_green or cup_white",
    )
    assert_reads(
        "Morning! Postdoc here, sorry to bother. Could you bring the banana to Omar?",
        "banana>B",
        LAB,
    )
    # a real correction after 'sorry' is still one
    assert_reads("The banana to Dana, sorry, to Omar.", "banana>B", LAB)


# -- blind19's refusals by kind ------------------------------------------------------------------


def _named_other34(request: str, want: str, reason: str, scene: Scene) -> bool:
    """Whether the request names its person by a first name the reason's he / she cannot be."""
    human = next(h for h in scene.humans if h.id == want.split(">")[1])
    pronoun = reason.split("'")[0]
    return any(
        " " not in name
        and re.search(rf"\b{re.escape(name)}\b", request, re.I) is not None
        and not fits(name, pronoun)
        for name in (human.name, *human.aliases)
    )


@settings(max_examples=40, deadline=None)
@_requests_in(
    [
        "she's getting chilly after her exercises",
        "her hands are full",
        "the customers are waiting on their mains",
        "it's all sticky",
        "he's drawing margins",
        "they keep rolling about",
    ]
)
def test_a_reason_after_the_request_is_taken_off(scene: Scene, k: int, reason: str) -> None:
    request, want = plain_request(scene, k)
    said = PRONOUN_SEX.get(reason.split()[0].split("'")[0])  # 'she's …', 'her hands …'
    if said is not None and title_sex(want.split(">")[1], Lexicon.of(scene)) not in (None, said):
        # session 31 (the lead's decision, 12s): 'she' after 'Give Mr Lee …' cannot be Mr Lee,
        # so the reason is about someone the instruction does not name (Ruth or Mrs Khan): not
        # taken off, refused with the readings ("Give Mr Lee the jug, she's thirsty.")
        assert_refused(f"{request}, {reason}.", scene, match="by title")
        return
    if reason.split()[0] in ("she's", "he's") and _named_other34(request, want, reason, scene):
        # session 34 (12s): likewise a first name of the other sex ('Give Bob the cup, she's
        # getting chilly …'): someone the request does not name, refused with the readings
        assert_refused(f"{request}, {reason}.", scene, match="cannot mean")
        return
    assert_reads(f"{request}, {reason}.", want, scene)


@settings(max_examples=40, deadline=None)
@_requests_in(
    [
        "she's not having {o}",  # a negation
        "he wants {o} too",  # another want
        "she's after {o} as well",
        "it's for {p}",  # another person
        "he needs them both",
        "she gets one first",
    ]
)
def test_a_reason_that_could_change_the_request_is_not_taken_off(
    scene: Scene, k: int, reason: str
) -> None:
    request, want = plain_request(scene, k)
    other = unique_objects(scene)[(k + 1) % len(unique_objects(scene))]
    person = name_of(scene, scene.humans[(k + 1) % len(scene.humans)].id)
    said = reason.format(o=f"the {name_of(scene, other)}", p=person)
    got = tree(f"{request}, {said}.", scene)
    alone = show_tree(parse_expectation(want))
    assert got is None or show_tree(got) != alone, f"{request}, {said}. read as the request alone"


@settings(max_examples=30, deadline=None)
@_requests_in(
    [
        "I'm only the plumber, don't mind me, but would you {r}?",
        "Hello. I would like to ask you, please {r}.",
        "Can I ask you for something? Please {r}.",
        "Hey, sorry, I'm running late, could you very kindly {r}?",
        "You couldn't {r}, could you?",
        "Shall we {r}, do you think?",
    ]
)
def test_the_speakers_remarks_and_question_frames_ask_nothing_more(
    scene: Scene, k: int, frame: str
) -> None:
    request, want = plain_request(scene, k)
    assert_reads(frame.format(r=request), want, scene)


def test_requests_asked_as_whether_they_can_be_done() -> None:
    ward = paraphrase_scene("ward")
    assert_reads("Mr Lee's thirsty, could he have the water jug, do you reckon?", "jug>B", ward)
    assert_reads("Is Person A able to get the bottle from you?", "bottle>A", T21)
    assert_reads(
        "Would it be possible for Person A to have the chips, and for Person B to get the bottle?",
        "chips>A & bottle>B",
        T21,
    )
    # a statement with the tag asks nothing; a request for the speaker stays refused
    assert_refused("Mr Lee has the water jug, do you reckon?", ward)
    assert_refused("Can I ask you for something? Give me the drill.", paraphrase_scene("workshop"))
    assert_refused("You couldn't give me the bottle, could you?", T21)


def test_the_speakers_next_step_after_the_request_is_taken_off() -> None:
    workshop = paraphrase_scene("workshop")
    assert_reads(
        "I'll need the power drill put on the workbench before I start on this socket.",
        "drill@bench",
        workshop,
    )
    # before another step of the cell's it orders, as always
    assert_reads(
        "Put the drill on the workbench before you give Jess the torch.",
        "drill@bench ; torch>B",
        workshop,
    )


@settings(max_examples=30, deadline=None)
@_requests_in(
    [
        "Porter coming through, sorry! {r}.",
        "Oh, aren't you clever. {r}.",
        "Mind your backs! {r}.",
    ]
)
def test_calls_and_a_person_said_not_to_be_the_one(scene: Scene, k: int, frame: str) -> None:
    request, want = plain_request(scene, k)
    others = [h for h in scene.humans if h.id != want.split(">")[1]]
    other = name_of(scene, others[0].id)
    assert_reads(frame.format(r=request, other=other), want, scene)


def test_a_person_said_not_to_be_the_one_but_named_again_stays_refused() -> None:
    cell = CELL
    assert_refused("Alice should get the mug. Not Alice, sorry, Carol.", cell, "mug_blue")
    assert_refused("Not Alice, Carol and Bob get a mug each.", cell)
    # said before a command it could be said to the hearer (session 12: refused)
    assert_refused("Not Bob, give Alice the cup", cell)
    assert_reads("Not Bob, Alice should get the cup.", "cup>A", cell)
    assert_reads("Not Person A, Person B should get the bottle.", "bottle>B", T21)


@settings(max_examples=30, deadline=None)
@given(st.sampled_from(PAIRED), st.integers(0, 7), st.sampled_from(["", "Sorry, ", "And "]))
def test_a_closing_in_that_order_orders_the_sentences(scene: Scene, k: int, lead: str) -> None:
    (o1, o2), (p1, p2), (n1, n2) = _two(scene, k)
    h1, h2 = name_of(scene, p1), name_of(scene, p2)
    text = f"The {n1} to {h1}. The {n2} to {h2}. {lead}in that order."
    assert_reads(text, f"{o1}>{p1} ; {o2}>{p2}", scene)
    # an order said already is not said again
    assert_refused(f"The {n1} to {h1}. Before that, the {n2} to {h2}. In that order.", scene)


def test_either_will_do_for_one_person() -> None:
    assert_reads("Either cup will do for Dana.", "cup_green>A | cup_white>A", LAB)
    assert_refused("Either cup will do for Dana and Omar.", LAB)
