"""Session-42 phrasings of issue 12 (engineer 12): blind40's wants, pronouns and possessives,
courtesies and question forms, each as a family (docs/grounding.md, "Session 42 (engineer 12)").
Each rule with sentences in other words and scenes it reads (which fail with the rule taken out),
lower-cased and with a one-edit typo of a scene word, and near sentences that must stay refused."""

from __future__ import annotations

import pytest

from hltl.grounding import _normalise2, _rewrites41, _rewrites42, _rewrites42s, _rewrites45r
from hltl.world.scene import load_scene
from tests.grounding.helpers import (
    CELL,
    CLASSROOM,
    DEPOT,
    KITCHEN,
    LAB,
    NURSERY,
    OFFICE,
    ROOT,
    WARD,
    WORKSHOP,
    PhrasingCases,
    assert_refused,
)

# two people named only 'Person A' and 'Person B' (no sex), and one person alone
DUO = load_scene(ROOT / "examples/scenes/2-2.yaml")
ONE = load_scene(ROOT / "examples/scenes/1-1.yaml")

# -- wants said by an idiom: the session-41 family widened (_rewrites41._want_idiom41) ------------

IDIOMS = PhrasingCases()

test_want_idioms = IDIOMS.test(
    ("Jess'd give anything for the torch.", "torch>B", WORKSHOP),
    ("Mrs Khan would jump at the blue blanket.", "blanket_blue>C", WARD),
    ("Tom has a yen for the barcode scanner.", "scanner>B", DEPOT),
    ("Lena's got a real hankering for the lemon.", "lemon>B", KITCHEN),
    ("Sam's been pining for the red pen.", "pen_red>B", OFFICE),
    ("sam's been pining for the red pen", "pen_red>B", OFFICE),
    ("Sam's been pining for the red pne.", "pen_red>B", OFFICE),
    (
        "Priya is rather keen on the stapler, and Sam fancies the notepad.",
        "stapler>A & notebook>B",
        OFFICE,
    ),
    ("Omar keeps going on about wanting the banana.", "banana>B", LAB),
    ("omar keeps going on about wanting the bananna", "banana>B", LAB),
    ("Emma put in a word for the green cup earlier.", "cup_green>C", LAB),
    # the past; negation; a person or a surface after the idiom; the person handed something else
    # after it (session 32: it may be instead)
    ("Mrs Khan would have jumped at the blue blanket.", None, WARD),
    ("Tom hasn't a yen for the barcode scanner.", None, DEPOT),
    ("Sam's been pining for Priya.", None, OFFICE),
    ("Omar keeps going on about wanting the tray.", None, LAB),
    ("Lena's got a real hankering for the lemon, give her the knife.", None, KITCHEN),
)

# the one person opening the sentence, said again after 'and' before a want (_elided_want42)
ELIDED = PhrasingCases()

test_elided_want = ELIDED.test(
    ("Noah is worn out and would kill for the glue stick.", "glue>B", CLASSROOM),
    ("Mrs Khan is cold and would love the blue blanket.", "blanket_blue>C", WARD),
    ("mrs khan is cold and would love the blue blankte", "blanket_blue>C", WARD),
    # two people before the 'and'; the past; a person after it
    ("Noah and Zoe are worn out and would kill for the glue stick.", None, CLASSROOM),
    ("Noah was worn out and would have killed for the glue stick.", None, CLASSROOM),
    ("Noah is worn out and would kill for Zoe.", None, CLASSROOM),
)


def test_elided_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # with 12s's session-42 rule of the same kind out too (both read these cases; session 43)
    ELIDED.refused_without((_rewrites42._elided_want42, _rewrites42s._state_and42s), monkeypatch)


# all morning long: how long it was asked for (session 11's words, _normalise1._WORDS)
test_all_morning_long = IDIOMS.test(
    ("Bob's been pining for those crisps all morning long.", "chips>B", CELL),
    ("Zoe has been angling for the globe all lesson long.", "globe>C", CLASSROOM),
)


def test_idioms_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 55: session 30's idiom step reads "P's been pining / crying for X" too (blind53 #38's
    # family, the same as _want_idiom41's): both taken out
    IDIOMS.refused_without((_rewrites41._want_idiom41, _normalise2._idioms30), monkeypatch)


# -- a want said in a cleft (_cleft_want42) -----------------------------------------------------

CLEFTS = PhrasingCases()

test_clefts = CLEFTS.test(
    ("It's the chips that Bob has his heart set on, the poor thing.", "chips>B", CELL),
    ("It's the stapler Sam's after.", "stapler>B", OFFICE),
    ("it's the tape tom is short of", "tape>B", DEPOT),
    ("The sippy cup's what Ava is after.", "beaker>C", NURSERY),
    ("The sippy cpu's what Ava is after.", "beaker>C", NURSERY),
    (
        "Mia wants the scanner; as for Tom, it's the tape he's short of.",
        "scanner>A & tape>B",
        DEPOT,
    ),
    (
        "Lena has her eye on the lemon, and as for Marco, it's the tongs he's hoping for.",
        "lemon>B & tongs>A",
        KITCHEN,
    ),
    # a pronoun the topic cannot be; a surface; a person for the thing; no topic for the pronoun;
    # after a request naming things, a cleft may add or correct (session 31's refusal stands)
    ("Bob wants the cup; the apple's what he's having.", None, CELL),
    ("Bob wants the cup; it's the apple he's after.", None, CELL),
    ("Mia wants the scanner; as for Tom, it's the tape she's short of.", None, DEPOT),
    ("It's the shelf that Bob is after.", None, CELL),
    ("It's Alice that Bob is after.", None, CELL),
    ("It's the apple that she is after.", None, CELL),
)


def test_clefts_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # session 45 (12r): "X's what P is after" is "X is what P is after" by its rule too
    CLEFTS.refused_without((_rewrites42._cleft_want42, _rewrites45r._whats_wanted45r), monkeypatch)


# -- a want said by what the thing would do for the person (_would_help42) ------------------------

HELPS = PhrasingCases()

test_would_help = HELPS.test(
    ("Mrs Khan is flagging, the magazine would perk her up.", "magazine>C", WARD),
    ("Noah's stuck; that ruler would be a lifesaver for him.", "ruler>B", CLASSROOM),
    ("Bob's flagging; the apple would hit the spot.", "apple>B", CELL),
    ("bob's flagging; the aple would hit the spot", "apple>B", CELL),
    ("Sam is parched, that blue pen would save his life.", "pen_blue>B", OFFICE),
    # a pronoun that fits no one named; two people; a place; the past
    ("Mrs Khan is flagging, the magazine would perk him up.", None, WARD),
    ("Mrs Khan and Ruth are flagging, the magazine would perk her up.", None, WARD),
    ("Bob's flagging; the shelf would hit the spot.", None, CELL),
    ("Bob was flagging; the apple would have hit the spot.", None, CELL),
)


def test_would_help_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    HELPS.refused_without((_rewrites42._would_help42,), monkeypatch)


# -- how much, said against everyone else (_more_than42) ------------------------------------------

MORE = PhrasingCases()

test_more_than = MORE.test(
    ("Person B needs that bottle more than anybody right now.", "bottle>B", DUO),
    ("Tom needs the packing tape more than anyone else right now.", "tape>B", DEPOT),
    ("lena wants the lemon more than anything right now", "lemon>B", KITCHEN),
    # someone named after 'more than': a comparison with them, not how much
    ("Tom needs the packing tape more than Mia right now.", None, DEPOT),
)


def test_more_than_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    MORE.refused_without((_rewrites42._more_than42,), monkeypatch)


# -- possession said to the cell is a handover (_possession42; the lead's policy) -----------------

OWNERS = PhrasingCases()

test_possession = OWNERS.test(
    ("the chips are person b's", "chips>B", DUO),
    ("The tongs are Lena's.", "tongs>B", KITCHEN),
    ("That magazine's hers, Mrs Khan's.", "magazine>C", WARD),
    ("Stapler, that's Priya's. Notepad, Sam's.", "stapler>A & notebook>B", OFFICE),
    ("Stapelr, that's Priya's.", "stapler>A", OFFICE),
    ("Whose is the globe? Zoe's.", "globe>C", CLASSROOM),
    ("Noah is down for the ruler and the globe is Zoe's.", "ruler>B & globe>C", CLASSROOM),
    # several things or owners; a negation; a thing the person has already; a surface
    ("The pens are Sam's.", None, OFFICE),
    ("The globe is Zoe's and Noah's.", None, CLASSROOM),
    ("The tongs aren't Lena's.", None, KITCHEN),
    ("The tongs are Lena's, she's got them.", None, KITCHEN),
    ("The shelf is Zoe's.", None, CLASSROOM),
)


def test_possession_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    OWNERS.refused_without((_rewrites42._possession42,), monkeypatch)


# 'X is P's' said alone: the grammar's reading, which session 33's _owner_only33s (offline.py)
# refused until the lead's policy (and sessions 30r, 38r, 39 and 39r asserted refused)
test_owner_said_alone = PhrasingCases().test(
    ("The drill is Jess's.", "drill>B", WORKSHOP),
    ("The magazine's Mrs Khan's.", "magazine>C", WARD),
    ("The sponge's Omar's.", "sponge>B", LAB),
    ("The knife is Lena's.", "knife>B", KITCHEN),
    ("the knife is lena's", "knife>B", KITCHEN),
    # several things
    ("The spanners are Jess's!", None, WORKSHOP),
)


# -- a thing left or lost, asked back for its owner (_left_behind42) -------------------------------

LEFT = PhrasingCases()

test_left_behind = LEFT.test(
    ("Person B left his bottle here; could he have it back?", "bottle>B", DUO),
    (
        "Person A left that bottle behind at the bus stop; it's hers, so she ought to get it back.",
        "bottle>A",
        ONE,
    ),
    ("sam forgot his notepda. he'll want it back", "notebook>B", OFFICE),
    # 'his' and 'she' of one person; a pronoun that fits no one; a place of the scene after it
    ("Person B left his bottle here; could she have it back?", None, DUO),
    ("Mrs Khan left her magazine here; could he have it back?", None, WARD),
    ("Sam forgot his notepad on the desk. He'll want it back.", None, OFFICE),
)


def test_left_behind_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    LEFT.refused_without((_rewrites42._left_behind42,), monkeypatch)


# -- pronouns: a confirmation, the order by people, 'so' + pronoun, 'it …, the X that is', who
# asked (_confirm42, _people_order42, _so_pronoun42, _that_is42, _rewrites41._said_tag41) ------

PRONOUNS = PhrasingCases()

test_confirm = PRONOUNS.test(
    ("Bob? Bottle. For him, yeah, that one.", "bottle>B", CELL),
    ("Give Mrs Khan the magazine. Yes, for her, that one.", "magazine>C", WARD),
    ("zoe? globe. for her, yeah, that one", "globe>C", CLASSROOM),
    # a pronoun that fits no one named; two people named before it
    ("Give Mrs Khan the magazine. Yes, for him, that one.", None, WARD),
    ("Bob? Bottle. Alice? Crisps. For him, yeah, that one.", None, CELL),
)

test_people_order = PRONOUNS.test(
    (
        "Begin with Mr Lee: he has the jug. Mrs Khan after him, with the magazine.",
        "jug>B ; magazine>C",
        WARD,
    ),
    (
        "Start with Zoe. She gets the globe. Noah after her, with the ruler.",
        "globe>C ; ruler>B",
        CLASSROOM,
    ),
    (
        "start with zoe. she gets the glboe. noah after her, with the ruler.",
        "globe>C ; ruler>B",
        CLASSROOM,
    ),
    # a pronoun that cannot be the one named; two people before 'after him'
    ("Begin with Mr Lee: she has the jug.", None, WARD),
    (
        "Mr Lee has the jug and Mrs Khan the pills. Ruth after her, with the magazine.",
        None,
        WARD,
    ),
)

test_so_pronoun = PRONOUNS.test(
    (
        "Ruth needs the thermometer and Mrs Khan is bored, so bring her the magazine.",
        "thermometer>A & magazine>C",
        WARD,
    ),
    (
        "tom wants the tape and mia is off soon so give her the scanner",
        "tape>B & scanner>A",
        DEPOT,
    ),
    # the pronoun fits no one of the clause before 'so'; two people in that clause
    ("Ruth needs the thermometer and Mr Lee is bored, so bring her the magazine.", None, WARD),
    (
        "Ruth needs the thermometer and Mrs Khan and Mr Lee are bored, so bring her the magazine.",
        None,
        WARD,
    ),
)

test_that_is = PRONOUNS.test(
    (
        "Sam mentioned he'd like it brought over, the stapler that is.",
        "stapler>B",
        OFFICE,
    ),
    ("Hand it to Jess, that is, the torch.", "torch>B", WORKSHOP),
    ("hand it to jess, that is, the trch.", "torch>B", WORKSHOP),
    # a thing already named in the clause: which one is meant?
    ("Hand the drill to Jess, the torch that is.", None, WORKSHOP),
)

test_asked_tag = PRONOUNS.test(
    (
        "Chips for Person B, he asked. Bottle for Person A, she asked too.",
        "chips>B & bottle>A",
        DUO,
    ),
    ("chips for person b, he asked. bottle for person a, she asked too", "chips>B & bottle>A", DUO),
    # a pronoun that fits no one of its sentence
    ("Chips for Person B, he asked. Bottle for Mrs Khan, he asked too.", None, WARD),
)


def test_pronouns_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    PRONOUNS.refused_without(
        (
            _rewrites42._confirm42,
            _rewrites42._people_order42,
            _rewrites42._so_pronoun42,
            _rewrites42._that_is42,
            _rewrites41._said_tag41,
            _rewrites42s._middle_state42s,
        ),
        monkeypatch,
    )


# -- courtesies opening the request (_courtesy42) ----------------------------------------------

COURTESIES = PhrasingCases()

test_courtesies = COURTESIES.test(
    (
        "Morning, and sorry about the noise from the brass band upstairs: the jug for Mr Lee.",
        "jug>B",
        WARD,
    ),
    (
        "Pardon me for butting in on your chess game, but could Sam have the stapler? Ta.",
        "stapler>B",
        OFFICE,
    ),
    (
        "pardon me for butting in on your chess game, but could sam have the staplre? ta",
        "stapler>B",
        OFFICE,
    ),
    (
        "With warm thanks from everyone on the night shift: the grey blanket to Mrs Khan.",
        "blanket_grey>C",
        WARD,
    ),
    (
        "The caretaker sends his regards; meanwhile could Jess have the torch?",
        "torch>B",
        WORKSHOP,
    ),
    (
        "Diolch, which is thanks in Welsh, my first language. Now, pass Lena the lemon.",
        "lemon>B",
        KITCHEN,
    ),
    # words of the scene inside the courtesy; a person of the scene sending regards; no request
    ("Sorry about the lemon: pass Lena the knife.", None, KITCHEN),
    ("Marco sends his regards; pass Lena the knife.", None, KITCHEN),
    ("Sorry about the noise from the band upstairs.", None, KITCHEN),
)


def test_courtesies_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    COURTESIES.refused_without((_rewrites42._courtesy42,), monkeypatch)


# -- question forms and proposals (_ask_forms42, _proposal42, _room_for42) -------------------------

QUESTIONS = PhrasingCases()

test_ask_forms = QUESTIONS.test(
    ("Could I trouble you to see that Zoe gets the globe?", "globe>C", CLASSROOM),
    ("could i trouble you to see that zoe gets the glboe?", "globe>C", CLASSROOM),
    (
        "While you're on your feet, would you be good enough to see Mr Lee gets the jug?",
        "jug>B",
        WARD,
    ),
    ("Is it too much bother to get Sam his stapler from over there?", "stapler>B", OFFICE),
    ("Could Lily trouble you for the teddy bear, do you suppose?", "teddy>A", NURSERY),
    # a time that puts it off; someone not in the scene asked for it
    ("Is there any way Tom could get the tape after lunch?", None, DEPOT),
    ("Could Mr Smith trouble you for the tape?", None, DEPOT),
)

test_proposals = QUESTIONS.test(
    (
        "How would it be if Noah had the ruler and Zoe the globe? Do that, please.",
        "ruler>B & globe>C",
        CLASSROOM,
    ),
    ("Shall the tape go to Tom, then? Yes, let's do that.", "tape>B", DEPOT),
    ("what if jess got the torhc? go ahead", "torch>B", WORKSHOP),
    # no assent: it asks the hearer's view
    ("How would it be if Noah had the ruler and Zoe the globe?", None, CLASSROOM),
)

test_room_for = QUESTIONS.test(
    (
        "Is there room in the box for the stapler, and could you put it there?",
        "stapler@box",
        OFFICE,
    ),
    (
        "Is there space on the rack for the white plate? If so, pop it on there.",
        "plate_white@rack",
        KITCHEN,
    ),
    # a person for the place; no request to put it
    ("Is there room on Lena for the white plate, and could you put it there?", None, KITCHEN),
    ("Is there space on the rack for the white plate?", None, KITCHEN),
)


def test_questions_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    QUESTIONS.refused_without(
        (_rewrites42._ask_forms42, _rewrites42._proposal42, _rewrites42._room_for42), monkeypatch
    )


# -- the rest: 'one' for the kind wanted, 'so' run on, 'lock X away' before a time (_get_one42,
# _so_run_on42, _rewrites41._lock_away41) ---------------------------------------------------------

REST = PhrasingCases()

test_rest = REST.test(
    ("Omar's after a spoon. Could you get him one?", "spoon>B", LAB),
    ("Omar needs a cup; bring him one, please.", "cup_green>B | cup_white>B", LAB),
    ("tom has dibs on the tape so the scanner goes to mia", "tape>B & scanner>A", DEPOT),
    (
        "Would you be a pal and lock the drill away in the locker before the boss comes round?",
        "drill@locker",
        WORKSHOP,
    ),
    # a pronoun for 'one' that fits no one
    ("Omar needs a cup; bring her one, please.", None, LAB),
)


def test_rest_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    REST.refused_without(
        (
            _rewrites42._get_one42,
            _rewrites42._so_run_on42,
            _rewrites41._lock_away41,
        ),
        monkeypatch,
    )


# -- the possession policy's older refusal (offline._owner_only33s) keeps several things --------


def test_owner_of_several_things_stays_refused() -> None:
    assert_refused("The spanners are Jess's!", WORKSHOP, match="could say whose the spanners")


# -- the person's own thing in a want; a placement said as what someone says (_own_thing42,
# _says_placed42) ---------------------------------------------------------------------------------

SAID = PhrasingCases()

test_own_thing = SAID.test(
    (
        "Mr Lee wants the jug and Mrs Khan is after her magazine, can you sort that",
        "jug>B & magazine>C",
        WARD,
    ),
    (
        "mr lee wants the jug and mrs khan is after her magazien, can you sort that",
        "jug>B & magazine>C",
        WARD,
    ),
    # a possessive that cannot be the one who wants: whose is it?
    ("Mr Lee wants the jug and Mrs Khan is after his magazine, can you sort that", None, WARD),
)

test_says_placed = SAID.test(
    (
        "mrs ortiz has asked for the scissors and says the globe can live on the shelf from now on",
        "scissors>A & globe@shelf",
        CLASSROOM,
    ),
    ("Priya says the stapler should stay in the box.", "stapler@box", OFFICE),
    ("Priya says the staplr should stay in the box.", "stapler@box", OFFICE),
    (
        "Noah wants the ruler, and says the globe can go on the shelf.",
        "ruler>B & globe@shelf",
        CLASSROOM,
    ),
    # a person where the surface goes; someone not in the scene says it
    ("Noah wants the ruler and says the globe can go on Zoe.", None, CLASSROOM),
    ("Mr Smith says the globe can live on the shelf.", None, CLASSROOM),
)


def test_said_refused_without(monkeypatch: pytest.MonkeyPatch) -> None:
    # with 12s's session-42 rule of the same kind out too (both read these cases; session 43)
    SAID.refused_without(
        (_rewrites42._own_thing42, _rewrites42._says_placed42, _rewrites42s._lives_on42s),
        monkeypatch,
    )
