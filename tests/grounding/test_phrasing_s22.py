"""Session-22 phrasings of issue 12: the two fuzz families read wrong in session 21 (a correction
cut off before a closer; a cue after a sentence asking for the speaker taking that sentence back),
the opener rule holding 'excuse me', and blind20's refusals by kind (docs/grounding.md, "Session
22")."""

from __future__ import annotations

from collections.abc import Callable

from hypothesis import given, settings
from hypothesis import strategies as st

from hltl.world.scene import Scene
from tests.grounding.helpers import (
    OFFICE,
    SCENES,
    WARD,
    assert_reads,
    assert_refused,
    name_of,
    plain_request,
    unique_objects,
)


def _requests_in(frames: list[str]) -> Callable[..., None]:
    """Hypothesis over a scene, which of its plain requests (plain_request) and a frame."""
    return given(st.sampled_from(SCENES), st.integers(0, 20), st.sampled_from(frames))


# -- the fuzz families of session 21 -------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@_requests_in(
    [
        "{r}, sorry, the, if that's alright with you.",
        "{r}, sorry, the, before I go",
        "{r}, no wait, the, cheers",
        "{r}, oh, the, whenever you're ready",
        "{r}, the, thanks a million",
        "{r}, sorry, the, good robot",
        "{r}, scratch that, the, if it's no bother",
    ]
)
def test_a_correction_cut_off_before_a_closer_is_refused(scene: Scene, k: int, frame: str) -> None:
    # fuzz seed 22: "The cup to Alice, sorry, the, if that's alright with you." read cup>A (the
    # closer taken off left "…, sorry, the", then the lone 'the' was taken off as address)
    request, _ = plain_request(scene, k)
    assert_refused(frame.format(r=request), scene)


@settings(max_examples=20, deadline=None)
@_requests_in(["{r}, if that's alright with you.", "{r}, before I go", "{r}, the best"])
def test_the_same_closers_after_a_whole_request_are_read(scene: Scene, k: int, frame: str) -> None:
    request, want = plain_request(scene, k)
    assert_reads(frame.format(r=request), want, scene)


@settings(max_examples=40, deadline=None)
@_requests_in(
    [
        "I want the {o} too. Hey, sorry, I'm running late, {r}.",
        "We need the {o}, hey, sorry, I'm running late, {r}.",
        "I'd like the {o}. No, {r}.",
        "Give me the {o}, no wait, {r}.",
        "Bring us the {o}. Sorry, {r}.",
        "I need the {o} as well. Actually, {r}.",
    ]
)
def test_no_cue_takes_back_a_sentence_asking_for_the_speaker(
    scene: Scene, k: int, frame: str
) -> None:
    # fuzz seed 22: "I want the banana too. Hey, sorry, I'm running late for my incubation, could
    # you very kindly put the bowl in the sink?" read bowl@sink ('sorry' took the sentence asking
    # for the speaker back)
    request, _ = plain_request(scene, k)
    objs = unique_objects(scene)
    other = name_of(scene, objs[(k + 1) % len(objs)])
    assert_refused(frame.format(o=other, r=request), scene)


def test_a_correction_of_a_request_for_someone_named_is_still_read() -> None:
    # the speaker's words around a request for a person named: the cue takes it back as before
    assert_reads("I'd like you to give Alice the cup. No, give Bob the apple.", "apple>B")
    assert_reads("Give Alice the cup, no wait, give Bob the apple.", "apple>B")


# -- the opener rule -----------------------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@_requests_in(
    [
        "Excuse me, sorry, {r}.",
        "Pardon me. {r}.",
        "Hi, excuse me, sorry to bother you, {r}.",
        "Sorry to bother you, {r}.",
        "Hello, yes, sorry, excuse me, {r}.",
        "Excuse me, so sorry to interrupt, {r}.",
    ]
)
def test_the_opener_rule_takes_off_a_call_for_attention(scene: Scene, k: int, frame: str) -> None:
    request, want = plain_request(scene, k)
    assert_reads(frame.format(r=request), want, scene)


@settings(max_examples=30, deadline=None)
@_requests_in(["Excuse me, sorry,", "Hey, sorry,", "Hi, excuse me,", "Sorry to bother you,"])
def test_a_call_for_attention_after_a_request_for_the_speaker_corrects_nothing(
    scene: Scene, k: int, cue: str
) -> None:
    request, _ = plain_request(scene, k)
    objs = unique_objects(scene)
    other = name_of(scene, objs[(k + 1) % len(objs)])
    text = f"Give me the {other} as well. {cue} I'm just covering today. {request}."
    assert_refused(text, scene)


# -- blind20's refusals by kind ------------------------------------------------------------------


@settings(max_examples=40, deadline=None)
@_requests_in(
    [
        "I'm the farmer, my boots are filthy so I won't come in. {r}.",
        "Afternoon, mind the mud on my jacket, I've come straight from the field. {r}.",
        "Hi there, I'm the gardener, only in to trim the hedges. {r}.",
        "Sorry, I've got a dog waiting in the car so sorry to rush you. {r}.",
        "{r}, since you're there.",
        "{r}, go on.",
    ]
)
def test_the_speakers_remarks_and_asides_ask_nothing(scene: Scene, k: int, frame: str) -> None:
    # blind20: "Hey, sorry, I'm the farmer, my boots are filthy so I won't come in. Just pass
    # Person A the bottle" ('I' taken for a recipient)
    request, want = plain_request(scene, k)
    assert_reads(frame.format(r=request), want, scene)


@settings(max_examples=40, deadline=None)
@_requests_in(
    [
        "I'm the farmer, I want one too. {r}.",
        "I'm the farmer, give me the {o} as well. {r}.",
        "I've come for the {o}. {r}.",
        "My boots are filthy so leave it. {r}.",
        "I'm the farmer, not that one. {r}.",
        "I'm the farmer, the {o} is for me. {r}.",
    ]
)
def test_a_remark_that_could_ask_for_something_is_not_taken_off(
    scene: Scene, k: int, frame: str
) -> None:
    request, _ = plain_request(scene, k)
    objs = unique_objects(scene)
    other = name_of(scene, objs[(k + 1) % len(objs)])
    assert_refused(frame.format(o=other, r=request), scene)


def test_a_purpose_after_the_object_and_want_frames() -> None:
    assert_reads("The intern needs the red pen for marking up his draft.", "pen_red>B", OFFICE)
    assert_reads(
        "Priya really wants the stapler for her collage of the solar system.", "stapler>A", OFFICE
    )
    # a purpose that points back or counts stays, and is refused
    assert_refused("Priya needs the stapler for stapling both of them.", OFFICE)
    assert_reads("What Carol's after is the crisps.", "chips>C")
    assert_reads("Bob is absolutely gasping for the bottle after that walk.", "bottle>B")
    assert_reads("Alice is shouting for the apple.", "apple>A")
    assert_reads("Alice is wanting the apple, the one she was looking at earlier.", "apple>A")
    # of two mugs, 'the one she was looking at' does not say which
    assert_refused("Alice is wanting a mug, the one she was looking at earlier.")


def test_a_name_and_a_role_of_one_person() -> None:
    assert_reads("nurse ruth is shouting for the thermometer", "thermometer>A", WARD)


@settings(max_examples=20, deadline=None)
@given(
    st.sampled_from([("red", "blue", "mug_red"), ("blue", "red", "mug_blue")]),
    st.sampled_from(
        [
            "Give Alice the {a} mug, not the {b} one.",
            "The {a} mug, not the {b}, goes to Alice.",
            "Whichever mug isn't the {b} one goes to Alice.",
            "Alice gets the mug that isn't the {b} one.",
        ]
    ),
)
def test_an_exclusion_that_says_nothing_more(pair: tuple[str, str, str], frame: str) -> None:
    a, b, want = pair
    assert_reads(frame.format(a=a, b=b), f"{want}>A")


def test_an_exclusion_of_what_is_not_there_or_is_the_same_stays_refused() -> None:
    assert_refused("Give Alice the red mug, not the green one.")
    assert_refused("Give Alice the red mug, not the red one.")
    assert_refused("Whichever cup isn't the green one goes to Alice.")


def test_an_object_left_alone_and_a_person_given_nothing() -> None:
    assert_reads("Don't touch the cup, it's fine where it is. Bob gets the apple.", "apple>B")
    assert_refused("Don't touch the cup. Give it to Bob.")
    assert_refused("Don't touch the cup. Bob gets the cup.")
    assert_reads("Never mind Alice for now, the chips go to Bob.", "chips>B")
    assert_refused("Never mind Alice for now, the chips go to her.")
    assert_reads("Alice has had her lot, so nothing for her; the chips go to Bob.", "chips>B")
    assert_refused("Alice has had her lot, so nothing for her; the chips go to her.")
    assert_reads("Not the chips, no, it's the bottle for Bob.", "bottle>B")
