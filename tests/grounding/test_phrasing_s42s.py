"""Session-42 phrasings of issue 12 (engineer 12s): remarks, purposes, asides and run-ons beside a
request (blind40's kinds, said in other words, scenes and people), and two readings of main made
refusals; docs/grounding.md, "Session 42 (engineer 12s)"."""

from __future__ import annotations

import pytest

from hltl.grounding import _normalise4 as n4
from hltl.grounding import _rewrites42 as r42
from hltl.grounding import _rewrites42s as r42s
from hltl.grounding import offline
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_refused,
    tree,
)

# -- Part 0b: someone else's occasion, an order put off ------------------------------------------


@pytest.mark.parametrize(
    ("text", "scene", "named"),
    [
        ("Grandad needs the beaker after her swim.", NURSERY, ("Person A", "Person C")),
        ("grandad needs the beaker after her swim", NURSERY, ("Person A", "Person C")),
        ("Mr Lee could use the jug after her physio.", WARD, ("Person A", "Person C")),
        ("Zoe would love the globe after his game.", CLASSROOM, ("Person B",)),
    ],
)
def test_elses_occasion_refused(text: str, scene: object, named: tuple[str, ...]) -> None:
    """'after her …' of a man's want (or 'his' of a woman's): someone else's, a time: refused,
    naming whom the pronoun could be (main read the want alone)."""
    for who in named:
        assert_refused(text, scene, match=who)  # type: ignore[arg-type]


def test_elses_occasion_read_without_the_refusal(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the refusal, session 34's and 37's occasion rules read them as the want alone."""
    kept = tuple(r for r in offline._REFUSALS if r is not r42s._elses_after42s)
    monkeypatch.setattr(offline, "_REFUSALS", kept)
    assert tree("Grandad needs the beaker after her swim.", NURSERY) is not None
    assert tree("Zoe would love the globe after his game.", CLASSROOM) is not None


OWN = PhrasingCases()
test_own_occasion_read = OWN.test(
    # the pronoun the person's own: read as before
    ("Grandad needs the beaker after his swimming lesson.", "beaker>B", NURSERY),
    ("Mrs Khan could use the jug after her physio.", "jug>C", WARD),
)

ORDERED = [
    ("Zoe wants the globe, give it to her after her football practice.", CLASSROOM),
    ("Kofi needs the drill, so pass it to him after his darts match.", WORKSHOP),
]


@pytest.mark.parametrize(("text", "scene"), ORDERED)
def test_order_after_occasion_refused(text: str, scene: object) -> None:
    """A want, then an order put off by 'after her …': the time rule's refusal."""
    assert_refused(text, scene)  # type: ignore[arg-type]


def test_order_after_occasion_read_without_the_fix(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the order check of session 37's `_after_doing37` they read (main did)."""
    monkeypatch.setattr(n4, "_ORDER_LAST37", n4.re.compile(r"(?!x)x"))
    for text, scene in ORDERED:
        assert tree(text, scene) is not None, text


# -- a remark of the person's state or doing, then 'and' + their want (_state_and42s) -------------

STATE = PhrasingCases()
test_state_and = STATE.test(
    ("Lena is rushed off her feet and could use the tongs.", "tongs>B", KITCHEN),
    ("lena is rushed off her feet and could use the tongs", "tongs>B", KITCHEN),
    ("Lena is rushed off her feet and could use the tnogs.", "tongs>B", KITCHEN),
    ("Marco is sweating over the stove and would love the lemon.", "lemon>A", KITCHEN),
    ("Lena has been rushed off her feet and could use the tongs.", "tongs>B", KITCHEN),
    # a state with its cause ('after his five-a-side', session 29's _state_cause29s), then the
    # want: read since 12's session-42 _elided_want42 landed beside this rule (session 43, lead:
    # the want is said and nothing waits on the game)
    ("Kofi is starving after his five-a-side and would love the torch.", "torch>A", WORKSHOP),
    ("Jess is parched after her bike ride and would love the torch.", "torch>B", WORKSHOP),
)
test_state_and_refused = STATE.test(
    # a remark naming a thing or a person of the scene, or a negation: not only a remark
    ("Lena is fed up with the tongs and would like the knife.", None, KITCHEN),
    ("Lena is helping Marco and could use the tongs.", None, KITCHEN),
    ("Jess isn't busy and needs the small spanner.", None, WORKSHOP),
)


def test_state_and_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # with 12's session-42 rule of the same kind out too (both read these cases; session 43)
    STATE.refused_without((r42s._state_and42s, r42._elided_want42), monkeypatch)


# -- a want said by inference (_inferred42s) ------------------------------------------------------

INFERRED = PhrasingCases()
test_inferred = INFERRED.test(
    ("Jess keeps glancing at the drill, I reckon she'd like it.", "drill>B", WORKSHOP),
    ("jess keeps glancing at the drill so i reckon shed like it", "drill>B", WORKSHOP),
    ("Jess keeps glancing at the drlil, I reckon she'd like it.", "drill>B", WORKSHOP),
    ("Ava keeps reaching for the teddy so I think she wants it.", "teddy>C", NURSERY),
)
test_inferred_refused = INFERRED.test(
    # another thing wanted than the one looked at; a pronoun that is not the person
    ("Jess keeps glancing at the drill, I reckon she'd like the hammer.", None, WORKSHOP),
    ("Grandad keeps reaching for the teddy so I think she'd like it.", None, NURSERY),
)


def test_inferred_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    INFERRED.refused_without((r42s._inferred42s,), monkeypatch)


# -- a closing courtesy to the robot (_robot_rest42s) ---------------------------------------------

REST = PhrasingCases()
test_rest = REST.test(
    ("Hand Jess the torch and then you can put your feet up.", "torch>B", WORKSHOP),
    ("hand jess the torch and then you can put your feet up", "torch>B", WORKSHOP),
    ("Hand Jess the torhc and then you can put your feet up.", "torch>B", WORKSHOP),
    ("Hand Jess the torch, and then take five.", "torch>B", WORKSHOP),
    ("Put the globe on the shelf when you're going past.", "globe@shelf", CLASSROOM),
)
test_rest_refused = REST.test(
    # what comes after names the scene: a task, or a time
    ("Put the globe on the shelf when you're done with the ruler.", None, CLASSROOM),
)


def test_rest_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # with 12's session-42 rule of the same kind out too (both read these cases; session 43)
    REST.refused_without((r42s._robot_rest42s, r42._ask_forms42), monkeypatch)


# -- meanwhile, and a pastime's place (_while_doing42s, _pastime_place42s) ------------------------

WHILE = PhrasingCases()
test_while = WHILE.test(
    ("Kofi's having the torch while he fixes the van.", "torch>A", WORKSHOP),
    ("kofis having the torch while he fixes the van", "torch>A", WORKSHOP),
    ("Give Priya the notebook while she waits for the bus.", "notebook>A", OFFICE),
)
test_while_refused = WHILE.test(
    # the pronoun not the person who gets it; what they do names the scene
    ("Give Mrs Khan the magazine while he waits for the doctor.", None, WARD),
    ("Give Priya the notebook while she holds the stapler.", None, OFFICE),
)


def test_while_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    WHILE.refused_without((r42s._while_doing42s,), monkeypatch)


PLACE = PhrasingCases()
test_pastime_place = PLACE.test(
    ("Ruth asked for the thermometer after her jog round the park.", "thermometer>A", WARD),
    ("Noah needs the ruler after his swim in the sea.", "ruler>B", CLASSROOM),
)
test_pastime_place_refused = PLACE.test(
    # the place is a surface of the scene
    ("Noah needs the ruler after his nap on the shelf.", None, CLASSROOM),
)


def test_pastime_place_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PLACE.refused_without((r42s._pastime_place42s,), monkeypatch)


# -- a purpose: 'to go with', 'for … to find' (_go_with42s, _to_find42s) --------------------------

GO_WITH = PhrasingCases()
test_go_with = GO_WITH.test(
    ("Hand Jess the hammer to go with her nails.", "hammer>B", WORKSHOP),
    ("hand jess the hammer to go with her nails", "hammer>B", WORKSHOP),
    ("Mrs Khan's asked for the jgu to go with her tablets.", None, WARD),  # 'tablets': the pills
    ("Mrs Khan's asked for the jgu to go with her supper.", "jug>C", WARD),
)
test_go_with_refused = GO_WITH.test(
    # with a thing of the scene; his / her not the person
    ("Hand Jess the hammer to go with the screws.", None, WORKSHOP),
    ("Hand Mrs Khan the jug to go with his supper.", None, WARD),
)


def test_go_with_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    GO_WITH.refused_without((r42s._go_with42s,), monkeypatch)


TO_FIND = PhrasingCases()
test_to_find = TO_FIND.test(
    ("Put the gloves on the pallet for the next shift to sort.", "gloves@pallet", DEPOT),
    ("put the gloves on the pallet for the next shift to find", "gloves@pallet", DEPOT),
    ("Leave the torch on the bench for the next shift to find.", "torch@bench", WORKSHOP),
)
test_to_find_refused = TO_FIND.test(
    # the finders counted
    ("Put the torch on the bench for the next two shifts to find.", None, WORKSHOP),
)


def test_to_find_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    TO_FIND.refused_without((r42s._to_find42s,), monkeypatch)


# -- a placement said to hold from now on (_lives_on42s) ------------------------------------------

LIVES = PhrasingCases()
test_lives = LIVES.test(
    ("The hammer can live on the bench from now on.", "hammer@bench", WORKSHOP),
    ("from now on the teddy lives on the play mat", "teddy@mat", NURSERY),
    ("The stapler belongs in the box from now on.", "stapler@box", OFFICE),
    (
        "Priya has asked for the red pen and says the stapler can live in the box from now on.",
        "pen_red>A & stapler@box",
        OFFICE,
    ),
)
test_lives_refused = LIVES.test(
    # no such thing in the scene
    ("The saw can live on the bench from now on.", None, WORKSHOP),
)


def test_lives_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # with 12's session-42 rule of the same kind out too (both read these cases; session 43)
    LIVES.refused_without((r42s._lives_on42s, r42._says_placed42), monkeypatch)


# -- run-ons (_as_for42s, _for_surface42s, _once_there42s, _thinking42s) --------------------------

AS_FOR = PhrasingCases()
test_as_for = AS_FOR.test(
    ("As for the drill, Jess can have that.", "drill>B", WORKSHOP),
    ("as for the hammer let's put it on the bench while we're at it", "hammer@bench", WORKSHOP),
    (
        "Dana gets the spoon, and as for the bowl, let's put that in the sink.",
        "spoon>A & bowl@sink",
        LAB,
    ),
)
test_as_for_refused = AS_FOR.test(
    # no such thing in the scene; another thing before the pronoun
    ("As for the saw, Jess can have it.", None, WORKSHOP),
    ("As for the hammer, Jess wants the drill more than it.", None, WORKSHOP),
)


def test_as_for_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    AS_FOR.refused_without((r42s._as_for42s,), monkeypatch)


FOR_SURFACE = PhrasingCases()
test_for_surface = FOR_SURFACE.test(
    ("The hammer's for the bench, leave it there.", "hammer@bench", WORKSHOP),
    ("the hammers for the locker", "hammer@locker", WORKSHOP),
    ("Kofi wants the drill. The hammer is for the locker.", "drill>A & hammer@locker", WORKSHOP),
)
test_for_surface_refused = FOR_SURFACE.test(
    # a thing named that is not of the scene
    ("The saw's for the bench, leave it there.", None, WORKSHOP),
)


def test_for_surface_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    FOR_SURFACE.refused_without((r42s._for_surface42s,), monkeypatch)


ONCE = PhrasingCases()
test_once = ONCE.test(
    (
        "put the sponge in the sink first and once its in there omar can have the bowl",
        "sponge@sink ; bowl>B",
        LAB,
    ),
    (
        "Give Dana the spoon and once she's got it the bowl can head over to Omar.",
        "spoon>A ; bowl>B",
        LAB,
    ),
)


def test_once_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    ONCE.refused_without((r42s._once_there42s,), monkeypatch)


THINKING = PhrasingCases()
test_thinking = THINKING.test(
    (
        "So I was thinking the spoon for Dana to start with, then the bowl to Omar.",
        "spoon>A ; bowl>B",
        LAB,
    ),
    (
        "i was thinking the spoon for dana to start with then the bowl to omar",
        "spoon>A ; bowl>B",
        LAB,
    ),
)
test_thinking_refused = THINKING.test(
    # a thought of a thing not in the scene
    ("I was thinking the kettle for Dana to start with.", None, LAB),
)


def test_thinking_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    THINKING.refused_without((r42s._thinking42s,), monkeypatch)


# -- remarks of the speaker, of a child, of earlier orders, of a doer ------------------------------

SPEAKER = PhrasingCases()
test_speaker = SPEAKER.test(
    ("Put the torch on the bench would you im trying to clear the yard", "torch@bench", WORKSHOP),
    ("put the torch on the bench would you im clearing the yard", "torch@bench", WORKSHOP),
)
test_speaker_refused = SPEAKER.test(
    # the speaker's remark names a thing of the scene
    ("Pop the bib on the mat, I'm trying to find the teddy.", None, NURSERY),
)


def test_speaker_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    SPEAKER.refused_without((r42s._speaker_doing42s,), monkeypatch)


LITTLE = PhrasingCases()
test_little = LITTLE.test(
    ("Ava's after the bib, the wee one's spilt her juice.", "bib>C", NURSERY),
)


def test_little_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LITTLE.refused_without((r42s._little_one42s,), monkeypatch)


STAND = PhrasingCases()
test_stand = STAND.test(
    ("The instructions from this morning still apply: Dana gets the spoon.", "spoon>A", LAB),
    ("orders from before still stand omar is having the bowl", "bowl>B", LAB),
)


def test_stand_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    STAND.refused_without((r42s._orders_stand42s,), monkeypatch)


DOER = PhrasingCases()
test_doer = DOER.test(
    ("Jess is fitting the new shelves, pass the drill.", "drill>B", WORKSHOP),
    ("jess is fitting the new shelves so pass the drill", "drill>B", WORKSHOP),
)
test_doer_refused = DOER.test(
    # not a doing; a handover named already
    ("Jess is off home, pass the drill.", None, WORKSHOP),
)


def test_doer_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    DOER.refused_without((r42s._doer_gets42s,), monkeypatch)


MIDDLE = PhrasingCases()
test_middle_state = MIDDLE.test(
    (
        "kofi is drilling and needs the screws and jess is knackered so bring her the torch",
        "screws>A & torch>B",
        WORKSHOP,
    ),
    ("Dana wants the bowl and Emma is bored, so pass her the banana.", "bowl>A & banana>C", LAB),
    ("Dana wants the bowl and Emma is bored, so pass her the bananna.", "bowl>A & banana>C", LAB),
)
test_middle_state_refused = MIDDLE.test(
    # the pronoun cannot be the person of the state
    ("Ruth wants the jug and Mr Lee is bored, so pass her the magazine.", None, WARD),
)


def test_middle_state_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # with 12's session-42 rule of the same kind out too (both read these cases; session 43)
    MIDDLE.refused_without((r42s._middle_state42s, r42._so_pronoun42), monkeypatch)


OPENING = PhrasingCases()
test_opening_occasion = OPENING.test(
    ("ever since judo practice carol has wanted the apple", "apple>C", CELL),
    ("Ever since his judo practice Bob has wanted the apple.", "apple>B", CELL),
    ("ever since judo practice carol has wanted the appel", "apple>C", CELL),
)
test_opening_occasion_refused = OPENING.test(
    # an order after it (put off); his / her not the person; an event word
    ("after judo practice give carol the apple", None, CELL),
    ("ever since his judo practice carol has wanted the apple", None, CELL),
    ("ever since the wedding carol has wanted the apple", None, CELL),
)


def test_opening_occasion_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OPENING.refused_without((r42s._opening_occasion42s,), monkeypatch)


# -- 'so' without a comma after an opening state (session 32's _opening_state32s) -----------------

SO = PhrasingCases()
test_so = SO.test(
    ("kofis had a long shift at the bike shop so give him the torch", "torch>A", WORKSHOP),
    ("Kofi had a long shift at the bike shop so give him the torch.", "torch>A", WORKSHOP),
    ("Kofi had a long shift at the bike shop so give him the trch.", "torch>A", WORKSHOP),
)


def test_so_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    """Without the ' so' (no comma) stop of session 32's rule they are refused."""
    plain = n4._OPENING_STATE32S.pattern.replace(
        r"|\s+(?=so\s+(?:could|can|would|will|please|give|hand|pass|bring|take|get|let|pop|put)\b)",
        "",
    )
    assert plain != n4._OPENING_STATE32S.pattern
    SO.refused_with(n4, "_OPENING_STATE32S", n4.re.compile(plain, n4._F), monkeypatch)
